/**
 * Checkpoint<dim>: checkpoint and restart of a run of ContactProblem<dim>
 * (checkpoint.cc describes the file): everything a time step reads from
 * the past, one binary file per process, and on --resume the same read
 * back, with the checks that the file belongs to this problem.
 *
 * The problem owns it; it holds references to the parts of the problem
 * that a checkpoint stores and restores.
 */
#ifndef contact_checkpoint_h
#define contact_checkpoint_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <core/parameters.h>
#include <core/discrete_space.h>
#include <core/mesh_plan.h>
#include <core/step_state.h>
#include <core/friction_solver.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  template <int dim>
  class Postprocessor;


  template <int dim>
  class Checkpoint
  {
  public:
    /** The parts of the run: the friction solver is replaced with each
     *  mesh, so the owner's pointer is held. */
    Checkpoint(
      const Parameters                                       &run_parameters,
      const DiscreteSpace<dim>                               &discrete_space,
      MeshAdaptation                                         &mesh_adaptation,
      StepState                                              &step_state,
      const std::unique_ptr<FrictionSolver<dim>>             &solver,
      const std::vector<std::unique_ptr<Postprocessor<dim>>> &observers,
      const ConditionalOStream                               &console,
      TimerOutput                                            &timer);

    /** On --resume, before anything is computed or written: the
     *  checkpoint of this number of processes exists, and the mesh plan
     *  stored with it becomes the run's. */
    void restore_mesh_plan();

    /** Whether a checkpoint is due after the current step. */
    bool due() const;

    void save();

    /** On --resume, once the problem is set up on the checkpoint's mesh:
     *  the state of the run at the checkpoint's step. */
    void load();

  private:
    /** Refuses a checkpoint of another discrete problem than this run's
     *  (its shape, or an entry of the .prm that defines it). */
    void require_same_problem(
      const std::string                        &stored_shape,
      const std::map<std::string, std::string> &stored_entries) const;

    const Parameters                                       &parameters;
    const DiscreteSpace<dim>                               &space;
    MeshAdaptation                                         &adaptation;
    StepState                                              &state;
    const std::unique_ptr<FrictionSolver<dim>>             &friction_solver;
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &postprocessors;
    const ConditionalOStream                               &pcout;
    TimerOutput                                            &computing_timer;
    // This process's file.
    const std::string name;
    // The wall time since the last checkpoint ('Checkpoint minutes').
    Timer wall_timer;
  };
} // namespace Contact

#endif
