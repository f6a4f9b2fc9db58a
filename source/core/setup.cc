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
#include <core/geometry.h>

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

  // The geometry of the .prm builds the mesh (source/core/box.cc,
  // source/parts/<geometry>/). Hypercubes go to p4est's distributed
  // triangulation, which refines its own part. p4est does not take simplices:
  // on several processes the whole simplex mesh is built on every process,
  // partitioned by METIS, and each process keeps its part in a fully
  // distributed triangulation.
  template <int dim>
  void ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(computing_timer, "Grid");
    auto              *fully_distributed =
      dynamic_cast<parallel::fullydistributed::Triangulation<dim> *>(
        space.triangulation.get());
    if (fully_distributed == nullptr)
      {
        geometry->create_mesh(*space.triangulation);
        adaptation.plan.replay(*space.triangulation);
        return;
      }
    AssertThrow(adaptation.plan.n_cycles() == 0,
                ExcInternalError("A mesh adaptation on simplices."));
    Triangulation<dim> whole;
    geometry->create_mesh(whole);
    GridTools::partition_triangulation(
      Utilities::MPI::n_mpi_processes(space.mpi_communicator), whole);
    fully_distributed->create_triangulation(
      TriangulationDescription::Utilities::
        create_description_from_triangulation(whole, space.mpi_communicator));
  }


  // @sect4{ContactProblem::setup_system}

  // V_h with its constraints, the matrices and the vectors of the state,
  // the nodes of Gamma_3 and the friction solver on them, and M, A_h and
  // B_h: on the Geometry's mesh, and again on each mesh adapted during the
  // run.
  template <int dim>
  void ContactProblem<dim>::setup_system()
  {
    {
      TimerOutput::Scope t(computing_timer, "Setup");
      space.setup(parameters.boundary);
      matrices.reinit(space);
      for (VectorType *vector : {&state.displacement,
                                 &state.velocity,
                                 &state.old_displacement,
                                 &state.old_velocity,
                                 &state.load,
                                 &state.step_rhs,
                                 &state.system_times_velocity})
        vector->reinit(space.locally_owned_dofs, space.mpi_communicator);

      friction_solver = create_friction_solver(
        make_contact_nodes(space, parameters.boundary.contact_ids),
        {parameters,
         space.constraints,
         space.locally_owned_dofs,
         space.mpi_communicator,
         pcout,
         computing_timer});
      loads->setup(friction_solver->boundary());
    }
    {
      TimerOutput::Scope t(computing_timer, "Assembly");
      matrices.assemble(space, parameters.material);
    }
    after_assembly(matrices);
  }


  // @sect4{ContactProblem::create_loads}

  // The loads of the .prm, or of an exact solution (a virtual
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


#define INSTANTIATE(dim)                                                    \
  template void                        ContactProblem<dim>::make_grid();    \
  template void                        ContactProblem<dim>::setup_system(); \
  template std::unique_ptr<Loads<dim>> ContactProblem<dim>::create_loads(   \
    const Parameters &, const DiscreteSpace<dim> &, TimerOutput &) const;   \
  template std::unique_ptr<FrictionSolver<dim>>                             \
  ContactProblem<dim>::create_friction_solver(                              \
    std::vector<ContactNode<dim>>, const FrictionSolverEnvironment &) const;

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
