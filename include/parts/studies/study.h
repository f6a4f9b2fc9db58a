/**
 * What runs a scene: a study. Every mode of the program is one (a single
 * run, a run with its error estimate, a mesh adapted by pilots, a run to a
 * target error, a convergence study), and parts/studies/compose_study.cc
 * composes them: a study that wraps another (the pilots run the scene on the
 * mesh they adapted, a target runs the run it chose) is given it at
 * construction, and what every run of a study is equipped with (the mesh
 * adaptation during the run, adapt_during_run.h) is given to it likewise.
 * No study calls another study's code.
 */
#ifndef contact_study_h
#define contact_study_h

#include <core/parameters.h>
#include <core/contact_problem.h>
#include <core/mesh_plan.h>
#include <parts/studies/richardson.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace Contact
{
  /** One row of an estimate's table: a quantity's value (for the V-norm
   *  ||eps(u_h(T))||), the differences of consecutive runs h vs 2h, 2h vs
   *  4h (and 4h vs 8h; for the V-norm the norms of the differences), the
   *  estimate, with the separation its space and time parts, and with a
   *  manufactured solution the exact error. */
  struct EstimateRow
  {
    std::string         name;
    double              value;
    std::vector<double> differences;
    RichardsonEstimate  estimate;
    /** With the separation: the parts of the error that halving only h
     *  and only k remove (signed for a quantity), each with the order its
     *  own runs show, and whether the estimate is their sum. */
    double space_part  = nan;
    double time_part   = nan;
    double space_order = nan;
    double time_order  = nan;
    bool   from_parts  = false;
    double exact_error = nan;
    /** For worst_V_error: the time of the largest estimate. */
    double time = nan;
  };

  /** What a study gives back: the summary of the run in the scene's own
   *  directory and, where the study estimates its error, the estimate's
   *  table (empty otherwise; a convergence study's summary is empty too:
   *  no one run stands for it). */
  struct RunResult
  {
    RunSummary               summary;
    std::vector<EstimateRow> rows;
  };

  /** What equips a run that a study builds, before it runs, given the
   *  run's own parameters: adapt_during_run() for a scene that adapts its
   *  mesh during the run. */
  template <int dim>
  using Equipment =
    std::function<void(ContactProblem<dim> &, const Parameters &)>;

  /** What a study runs the scene with, besides its parameters. */
  template <int dim>
  struct StudyInput
  {
    /** The cycles that changed the scene's mesh (pilots); empty: the
     *  scene's own mesh. */
    MeshPlan plan;
    /** The orders in h and k that earlier runs (a target's pilots)
     *  measured of the scene's quantities; a study without an error
     *  estimate has no use for them. */
    KnownOrders orders;
    /** Called on the run in the scene's own output directory (not on the
     *  runs in its subdirectories) before it runs: what the study that
     *  wraps this one adds to it (the files of the pilots). */
    Equipment<dim> equip_scene_run;
  };

  /** A study of a scene: what app/ runs. */
  template <int dim>
  class Study
  {
  public:
    virtual ~Study() = default;

    /** Runs `scene` as the study does, on the scene's mesh changed by
     *  `input.plan`. */
    virtual RunResult run(const Parameters      &scene,
                          const StudyInput<dim> &input) = 0;
  };

  /** The scene run once (study.cc), each run equipped by `equipment`. */
  template <int dim>
  class SingleRun : public Study<dim>
  {
  public:
    explicit SingleRun(const Equipment<dim> &equipment);

    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override;

  private:
    const Equipment<dim> equip;
  };
} // namespace Contact

#endif
