/**
 * 'Convergence study/Levels' > 0 (convergence_study.cc).
 */
#ifndef contact_convergence_study_h
#define contact_convergence_study_h

#include <core/parameters.h>
#include <parts/studies/study.h>

namespace Contact
{
  /** Runs the scene Levels + 1 times, halving h, k or both from one level
   *  to the next (each level in its own subdirectory level-l, on the
   *  scene's own mesh refined), and prints and writes the table of errors
   *  and rates (convergence.txt). Its result is empty: no one run stands
   *  for the study. */
  template <int dim>
  class ConvergenceStudy : public Study<dim>
  {
  public:
    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override;
  };
} // namespace Contact

#endif
