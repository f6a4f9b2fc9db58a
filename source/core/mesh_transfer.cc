/* ---------------------------------------------------------------------
 * The move of a run to a mesh adapted during it (ContactProblem::
 * adapt_mesh_during_run()): the cells are chosen by the function that
 * equipped the run, recorded in the plan, and the state at
 * t_n is carried over to the new mesh, where the run goes on.
 * --------------------------------------------------------------------- */

#include <deal.II/distributed/solution_transfer.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>

#include <iomanip>
#include <vector>

namespace Contact
{
  // @sect4{ContactProblem::transfer_to_adapted_mesh}

  // u_n and w_n are interpolated to the new mesh by p4est's transfer (a
  // refined cell's children take the parent's field, exactly; a coarsened
  // parent takes its children's values at its nodes) and made to satisfy
  // the constraints of the new V_h: its hanging nodes, and where Gamma_3 is
  // curved the normal component of the new nodes there. Everything else is
  // built again from them, as at the start of a run: the matrices (assembled
  // before the transfer's interpolation, which they do not read), K and
  // its factor (one factorisation per mesh), Gamma_3's nodes and the
  // friction solver, whose slip velocities are those of the transferred
  // w_n (its friction forces, only the first guess of the next step's
  // active sets, start from zero), and M w_n and B u_n for the next step's
  // right-hand side.
  //
  // The transfer changes the kinetic and elastic energy: a coarsening
  // loses what the children resolved, a constraint removes a component.
  // The change (after minus before) is kept as a term of the energy
  // balance, so that the identity of the whole run still closes and the
  // transfer's error is in the books, not in the numerical dissipation.
  template <int dim>
  void ContactProblem<dim>::transfer_to_adapted_mesh()
  {
    TimerOutput::Scope t(computing_timer, "Mesh adaptation");
    for (const auto &postprocessor : postprocessors)
      postprocessor->mesh_event(MeshEvent::before_change);
    adaptation.choose_cells();
    adaptation.plan.add_cycle_from_flags(*space.triangulation);
    // Coarsening flags that p4est drops (not every child of a cell
    // flagged) may leave nothing to change: then the mesh stays.
    space.triangulation->prepare_coarsening_and_refinement();
    bool changes = false;
    for (const auto &cell : space.triangulation->active_cell_iterators())
      if (cell->is_locally_owned() &&
          (cell->refine_flag_set() || cell->coarsen_flag_set()))
        changes = true;
    if (Utilities::MPI::max(changes ? 1 : 0, space.mpi_communicator) == 0)
      {
        adaptation.plan.refined.pop_back();
        adaptation.plan.coarsened.pop_back();
        return;
      }
    // The factor of K refers to K, which the new mesh's set-up
    // reinitialises (MUMPS frees its factor through the matrix's map), and
    // the friction solver to the factor: both go first.
    friction_solver.reset();
    matrices.factorization.reset();
    const EnergyBalance before        = state.energy;
    const double        energy_before = before.kinetic + before.elastic;
    const types::global_dof_index unknowns_before = space.dof_handler.n_dofs();
    {
      const VectorType old_displacement = space.ghosted(state.displacement);
      const VectorType old_velocity     = space.ghosted(state.velocity);
      parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
        space.dof_handler);
      transfer.prepare_for_coarsening_and_refinement(
        std::vector<const VectorType *>{&old_displacement, &old_velocity});
      space.triangulation->execute_coarsening_and_refinement();

      setup_system();
      std::vector<VectorType *> new_fields{&state.displacement,
                                           &state.velocity};
      transfer.interpolate(new_fields);
    }
    space.constraints.distribute(state.displacement);
    space.constraints.distribute(state.velocity);

    matrices.update_state_products(state, space.constraints);
    after_mesh_transfer(state.energy, before);
    const double energy_after = state.energy.kinetic + state.energy.elastic;
    state.energy.mesh_transfer += energy_after - energy_before;

    // Said before the friction solver's set-up reports on the new mesh.
    pcout << "Mesh adaptation after step " << state.step_number
          << " (t = " << number_text(state.time)
          << "): " << space.triangulation->n_global_active_cells() << " cells, "
          << unknowns_before << " -> " << space.dof_handler.n_dofs()
          << " unknowns, " << friction_solver->boundary().nodes.size()
          << " free nodes on Gamma_3; kinetic + elastic energy "
          << std::setprecision(6) << energy_before << " before the transfer, "
          << energy_after << " after" << std::endl;

    matrices.factorize(state.time_step,
                       parameters.solver,
                       space,
                       computing_timer);
    friction_solver->reinit(matrices.system, *matrices.factorization);
    friction_solver->set_initial_velocity(state.velocity);
    for (const auto &postprocessor : postprocessors)
      postprocessor->mesh_event(MeshEvent::after_change);
  }


#define INSTANTIATE(dim) \
  template void ContactProblem<dim>::transfer_to_adapted_mesh();

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
