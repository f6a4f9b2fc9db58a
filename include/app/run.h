/**
 * The command line of the program: `contact [--set Section/Entry=value]...
 * scene.prm`. The dimension is read from the .prm first ('Dimension'),
 * then the whole file is parsed and checked and ContactProblem<2> or <3>
 * runs.
 */
#ifndef contact_run_h
#define contact_run_h

#include <base/parameters.h>

#include <string>
#include <vector>

namespace Contact
{
  /** Runs the program; user errors are thrown as dealii::ExceptionBase. */
  void run_from_command_line(const int argc, const char *const *argv);

  /** Sets 'Section/Entry' = value in prm, as --set does (with the same
   *  message for an entry that is not declared or a value that does not
   *  fit). */
  void apply_override(ParameterHandler  &prm,
                      const std::string &path,
                      const std::string &value);

  /** The parameters of `parameter_file` with overrides 'Section/Entry=value'
   *  applied, read and checked as by the command line. */
  Parameters read_parameters(const std::string              &parameter_file,
                             const std::vector<std::string> &overrides);
} // namespace Contact

#endif
