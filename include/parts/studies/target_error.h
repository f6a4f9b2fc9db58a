/**
 * 'Accuracy/Target error' (target_error.cc).
 */
#ifndef contact_target_error_h
#define contact_target_error_h

#include <core/parameters.h>
#include <parts/studies/study.h>

#include <memory>

namespace Contact
{
  /** Runs the pilots (target_error_pilots.h, each equipped by `equipment`)
   *  that measure how the error of the scene falls with h and with k and
   *  what a run costs, chooses the degree, h and k of the cheapest run
   *  predicted to reach the target, and runs it by `run_with_estimate`,
   *  with the orders that the pilots measured; prints and writes
   *  target.txt. Its result is the chosen run's. */
  template <int dim>
  class TargetError : public Study<dim>
  {
  public:
    TargetError(std::unique_ptr<Study<dim>> run_with_estimate,
                const Equipment<dim>       &equipment);

    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override;

  private:
    const std::unique_ptr<Study<dim>> chosen_run;
    const Equipment<dim>              equip;
  };
} // namespace Contact

#endif
