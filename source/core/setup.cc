/* Mesh, finite element space, constraints of V_h and the nodes of Gamma_3. */

#include <deal.II/base/exceptions.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
#include <core/contact_nodes.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace Contact
{
  // @sect4{ContactProblem::make_grid}

  // The geometry of the .prm builds the mesh (source/geometry/).
  // Hypercubes go to p4est's distributed triangulation, which refines its
  // own part. p4est does not take simplices: on several processes the
  // whole simplex mesh is built on every process, partitioned by METIS, and
  // each process keeps its part in a fully distributed triangulation.
  template <int dim>
  void ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope                         t(computing_timer, "Grid");
    const std::unique_ptr<const Geometry<dim>> geometry =
      create_geometry<dim>(parameters, mpi_communicator);
    auto *fully_distributed =
      dynamic_cast<parallel::fullydistributed::Triangulation<dim> *>(
        space.triangulation.get());
    if (fully_distributed == nullptr)
      {
        geometry->create_mesh(*space.triangulation);
        mesh_plan.replay(*space.triangulation);
        return;
      }
    AssertThrow(mesh_plan.n_cycles() == 0,
                ExcInternalError("A mesh adaptation on simplices."));
    Triangulation<dim> whole;
    geometry->create_mesh(whole);
    GridTools::partition_triangulation(
      Utilities::MPI::n_mpi_processes(mpi_communicator), whole);
    fully_distributed->create_triangulation(
      TriangulationDescription::Utilities::
        create_description_from_triangulation(whole, mpi_communicator));
  }


  // @sect4{ContactProblem::setup_system}

  // V_h with its constraints, the sparsity of the matrices, the vectors of
  // the state, the nodes of Gamma_3 and the friction solver on them: on the
  // Geometry's mesh, and again on each mesh adapted during the run.
  template <int dim>
  void ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    space.setup(parameters.boundary);
    const IndexSet &owned    = space.locally_owned_dofs;
    const IndexSet &relevant = space.locally_relevant_dofs;

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(space.dof_handler,
                                    dsp,
                                    space.constraints,
                                    false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned,
                                               mpi_communicator,
                                               relevant);
    for (MatrixType *matrix : {&matrices.mass,
                               &matrices.viscosity,
                               &matrices.elasticity,
                               &matrices.system})
      matrix->reinit(owned, owned, dsp, mpi_communicator);
    for (VectorType &vector : matrices.momentum_density)
      vector.reinit(owned, mpi_communicator);
    matrices.angular_momentum_density.reinit(owned, mpi_communicator);
    for (VectorType *vector : {&state.displacement,
                               &state.velocity,
                               &state.old_displacement,
                               &state.old_velocity,
                               &state.load,
                               &state.step_rhs,
                               &state.system_times_velocity})
      vector->reinit(owned, mpi_communicator);

    friction_solver = create_friction_solver(
      make_contact_nodes(space, parameters.boundary.contact_ids),
      {parameters,
       space.constraints,
       space.locally_owned_dofs,
       mpi_communicator,
       pcout,
       computing_timer});
    loads->setup(friction_solver->boundary());
  }


  // @sect4{ContactProblem::create_loads}

  // The loads of the .prm, or of the manufactured solution (a virtual
  // function: a problem derived from this one may make loads derived from
  // Loads).
  template <int dim>
  std::unique_ptr<Loads<dim>>
  ContactProblem<dim>::create_loads(const Parameters         &run_parameters,
                                    const DiscreteSpace<dim> &discrete_space,
                                    TimerOutput              &timer) const
  {
    return std::make_unique<Loads<dim>>(run_parameters, discrete_space, timer);
  }


  // @sect4{ContactProblem::create_friction_solver}

  // The friction solver on the nodes of Gamma_3 of the current mesh, every
  // node sticking and without force (a virtual function: a problem derived
  // from this one may change the nodes or make a solver derived from
  // FrictionSolver).
  template <int dim>
  std::unique_ptr<FrictionSolver<dim>>
  ContactProblem<dim>::create_friction_solver(
    std::vector<ContactNode<dim>>    nodes,
    const FrictionSolverEnvironment &environment) const
  {
    return std::make_unique<FrictionSolver<dim>>(environment, std::move(nodes));
  }


  // @sect4{ContactProblem::report_mesh}

  // The size of the problem, and a warning where the mapping costs the
  // tractions an order.
  template <int dim>
  void ContactProblem<dim>::report_mesh() const
  {
    pcout << "Mesh: " << space.triangulation->n_global_active_cells()
          << " cells, "
          << (parameters.geometry.cell_shape ==
                  GeometryParameters::CellShape::simplex ?
                'P' :
                'Q')
          << space.fe.degree << ", " << space.dof_handler.n_dofs()
          << " unknowns, " << friction_solver->boundary().nodes.size()
          << " free nodes on Gamma_3" << std::endl;
    // Measured on the bushing (doc/verification.md, "A curved Gamma_3"):
    // Q2 nodes on the chords of a circle make the slip onset converge at
    // first order in h only, Q2 on the curved cells at second order.
    const auto &geometry = parameters.geometry;
    if (create_geometry(parameters)->has_curved_boundary() &&
        geometry.mapping_degree < space.fe.degree)
      pcout << "Warning: '" << Entry::mapping_degree
            << "' = " << geometry.mapping_degree << " is below '"
            << Entry::finite_element_degree << "' = " << space.fe.degree
            << ": the element's nodes on the circles lie on their chords, "
               "which costs the tractions on Gamma_3 an order of accuracy "
               "(doc/verification.md); set both equal."
            << std::endl;
  }


#define INSTANTIATE(dim)                                                     \
  template void                        ContactProblem<dim>::make_grid();     \
  template void                        ContactProblem<dim>::setup_system();  \
  template std::unique_ptr<Loads<dim>> ContactProblem<dim>::create_loads(    \
    const Parameters &, const DiscreteSpace<dim> &, TimerOutput &) const;    \
  template std::unique_ptr<FrictionSolver<dim>>                              \
  ContactProblem<dim>::create_friction_solver(                               \
    std::vector<ContactNode<dim>>, const FrictionSolverEnvironment &) const; \
  template void ContactProblem<dim>::report_mesh() const;

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
