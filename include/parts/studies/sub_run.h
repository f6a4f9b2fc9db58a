/**
 * A run inside a study (a coarse run of an error estimate, a pilot): run
 * with its console output in a log file, its displacement kept at T and
 * at the steps of a coarser time grid, interpolated onto another run's
 * mesh; and where a study itself prints and writes (sub_run.cc).
 */
#ifndef contact_sub_run_h
#define contact_sub_run_h

#include <core/contact_problem.h>

#include <ostream>
#include <string>
#include <vector>

namespace Contact
{
  /** A run's summary, and its displacement at T and at the times of a
   *  coarser time grid, interpolated onto another run's mesh. */
  struct RunAtTimes
  {
    RunSummary              summary;
    VectorType              displacement;
    std::vector<VectorType> history;
  };

  template <int dim>
  class ReferenceInterpolation;

  /** Runs `problem`, keeping its displacement at every `stride`-th step
   *  (none for 0) and at T, interpolated by `onto` (its own for null). With
   *  a `log_file` the run's console output goes there instead (a sub-run of
   *  an estimate or a target, which the console shows in one line). */
  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride,
                      const std::string                 &log_file = "");

  /** A quantity at T of a run, found by its name: its V-norm or one of
   *  its final quantities. A quantity that a run does not have (e.g. one
   *  of the free nodes on Gamma_3 where a coarse mesh has none) is NaN
   *  there. */
  double quantity_of(const RunSummary &summary, const std::string &name);

  /** The line that stands for a sub-run on the console: its unknowns and
   *  steps, and where its log is. */
  std::string sub_run_line(const RunSummary  &summary,
                           const std::string &log_file);

  /** The console of a study: the first process's standard output (the
   *  stream of the others is never opened, so it drops what it is given). */
  std::ostream &study_console();

  /** Writes `text` to `file` on the first process. */
  void write_study_file(const std::string &file, const std::string &text);
} // namespace Contact

#endif
