/**
 * 'Convergence study/Levels' > 0: the scene runs Levels + 1 times, halving
 * h, k or both from one level to the next, and the errors are printed with
 * their rates (convergence_study.cc).
 */
#ifndef contact_convergence_study_h
#define contact_convergence_study_h

#include <base/parameters.h>

namespace Contact
{
  /** Runs the levels of the study of `scene` (each in its own
   *  subdirectory level-l), and prints and writes the table of errors and
   *  rates (convergence.txt). */
  template <int dim>
  void run_convergence_study(const Parameters &scene);
} // namespace Contact

#endif
