/**
 * 'Accuracy/Estimate error': a run that also says how accurate it is. The
 * scene runs as given, then with h and k doubled, quadrupled and (where the
 * mesh allows) multiplied by 8; from the differences of consecutive runs
 * each quantity's error at T is estimated by Richardson extrapolation
 * (richardson.h) with the order the runs show, where they show one order
 * consistently (error_estimate.cc; the report: error_estimate_report.cc).
 */
#ifndef contact_error_estimate_h
#define contact_error_estimate_h

#include <core/parameters.h>
#include <parts/studies/study.h>
#include <parts/studies/sub_run.h>

#include <string>
#include <vector>

namespace Contact
{
  /** The coarse runs take ceil(N / 2^l) steps; a ratio of their time step
   *  to the run's that differs from 2^l by more than this (relative) gets a
   *  warning. */
  constexpr double max_step_ratio_deviation = 0.05;

  /** Runs the scene and its coarse versions, and prints and writes the
   *  estimated errors (error_estimate.txt), each run equipped by
   *  `equipment`. A quantity with known orders in h and k
   *  (StudyInput::orders) is extrapolated with both. On a mesh adapted by
   *  pilots (StudyInput::plan: the cycles that changed the scene's mesh)
   *  the coarse runs are on that mesh coarsened by one and two levels
   *  (MeshPlan::coarser()). */
  template <int dim>
  class ErrorEstimate : public Study<dim>
  {
  public:
    explicit ErrorEstimate(const Equipment<dim> &equipment);

    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override;

  private:
    const Equipment<dim> equip;
  };

  /** The runs of an estimate: the given one and those with 2h, 4h (and
   *  8h) in the sequence; with the separation, those with 2h and 4h at k
   *  (space) and with 2k and 4k at h (time). */
  struct EstimateRuns
  {
    std::vector<RunAtTimes> sequence;
    std::vector<RunAtTimes> space;
    std::vector<RunAtTimes> time;
  };

  /** The text of an estimate: what it compares and how, the table of
   *  `rows`, and the notes and warnings on them (error_estimate_report.cc). */
  std::string estimate_report(const Parameters               &parameters,
                              const EstimateRuns             &runs,
                              const std::vector<EstimateRow> &rows,
                              const KnownOrders              &orders);
} // namespace Contact

#endif
