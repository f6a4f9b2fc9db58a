/**
 * RunStorage<dim>: what stores a run of ContactProblem<dim> while it
 * goes, so that a run stopped at any moment can be continued from the
 * last one stored ('Output/Resume', --resume). The core does not store
 * runs itself: a part of the kind RunStorageParts (base/parts.h) does, and
 * the problem calls it at fixed points of its run:
 *   restore_mesh_plan()  on a resumed run, before anything is computed
 *                        or written: the stored run's mesh plan becomes
 *                        the run's, so that the mesh is built as it was,
 *   load()               on a resumed run, once the problem is set up on
 *                        that mesh: the stored state (the step state, the
 *                        friction solver's, each postprocessor's, whether
 *                        an adaptation of the mesh is due),
 *   due() and save()     after each step (and after the mesh's adaptation
 *                        of that step): the run stored when it is due.
 * A program without such a part refuses a resumed run.
 */
#ifndef contact_run_storage_h
#define contact_run_storage_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <base/parts.h>
#include <core/discrete_space.h>
#include <core/friction_solver.h>
#include <core/mesh_plan.h>
#include <core/parameters.h>
#include <core/step_state.h>

#include <memory>
#include <vector>

namespace Contact
{
  using namespace dealii;

  template <int dim>
  class Postprocessor;


  /** What a run's storage stores and restores: references to the parts
   *  of the problem, which outlives it. The friction solver is replaced
   *  with each mesh, so its owner's pointer is held. */
  template <int dim>
  struct RunStorageView
  {
    const Parameters                                       &parameters;
    const DiscreteSpace<dim>                               &space;
    MeshAdaptation                                         &adaptation;
    StepState                                              &state;
    const std::unique_ptr<FrictionSolver<dim>>             &friction_solver;
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &postprocessors;
    const ConditionalOStream                               &pcout;
    TimerOutput                                            &computing_timer;
  };


  template <int dim>
  class RunStorage
  {
  public:
    virtual ~RunStorage() = default;

    virtual void restore_mesh_plan() = 0;
    virtual void load()              = 0;
    /** Whether the run is to be stored after the current step. */
    virtual bool due() const = 0;
    virtual void save()      = 0;
  };


  /** The kind of the storages of runs (base/parts.h), registered for
   *  every compiled dimension; a run has the first of them, if any. */
  template <int dim>
  using RunStorageParts =
    PartRegistry<RunStorage<dim>, const RunStorageView<dim> &>;
} // namespace Contact

#endif
