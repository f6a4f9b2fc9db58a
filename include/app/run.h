/**
 * The command line of the program: `contact [--set Section/Entry=value]...
 * scene.prm`. The scene is read and checked (prm_reader.h) and runs in its
 * dimension, by the part that runs scenes (core/scene_runner.h: the study
 * it asks for, parts/studies/compose_study.h), or as one run in a build
 * without that part.
 */
#ifndef contact_run_h
#define contact_run_h

#include <core/parameters.h>

#include <string>
#include <vector>

namespace Contact
{
  /** Runs the program; user errors are thrown as dealii::ExceptionBase. */
  void run_from_command_line(const int argc, const char *const *argv);

  /** The parameters of `parameter_file` with overrides 'Section/Entry=value'
   *  applied, read and checked as by the command line. */
  Parameters read_parameters(const std::string              &parameter_file,
                             const std::vector<std::string> &overrides);
} // namespace Contact

#endif
