/**
 * 'Accuracy/Target error': pilot runs measure how the error of the scene
 * falls with h and with k and what a run costs; the cheapest run
 * predicted to reach the target then runs with its error estimate
 * (target_error.cc).
 */
#ifndef contact_target_error_h
#define contact_target_error_h

#include <base/parameters.h>

namespace Contact
{
  /** Runs the pilots, chooses degree, h and k, and runs the choice with its
   *  error estimate; prints and writes target.txt. */
  template <int dim>
  void run_to_target(const Parameters &parameters);
} // namespace Contact

#endif
