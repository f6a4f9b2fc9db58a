/**
 * 'Accuracy/Estimate error': a run that also says how accurate it is
 * (error_estimate.cc; the report: error_estimate_report.cc).
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
  /** Runs the scene as given, then with h and k doubled, quadrupled and
   *  (where the mesh allows) multiplied by 8, and prints and writes the
   *  errors at T that Richardson extrapolation (richardson.h) estimates
   *  from their differences (error_estimate.txt), each run equipped by
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
