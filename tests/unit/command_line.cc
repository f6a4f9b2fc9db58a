/* The command line of `contact` where no scene runs: --help prints the
   usage; --print-parameters with a scene prints the scene's values, not
   the defaults; a directory or a file that cannot be read as the scene is
   an error naming it, not a run of the default scene; an output directory
   with a line break is refused. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <run.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  // Runs the command line; prints its error, or the lines of its output
  // that contain `wanted` (all of it if empty).
  void run(const std::vector<std::string> &arguments,
           const std::string              &wanted = "")
  {
    std::vector<const char *> argv{"contact"};
    std::cout << "contact";
    for (const std::string &argument : arguments)
      {
        argv.push_back(argument.c_str());
        std::cout << ' ' << argument;
      }
    std::cout << std::endl;

    std::ostringstream captured;
    std::streambuf    *console = std::cout.rdbuf(captured.rdbuf());
    try
      {
        Contact::run_from_command_line(argv.size(), argv.data());
        std::cout.rdbuf(console);
        std::istringstream lines(captured.str());
        for (std::string line; std::getline(lines, line);)
          if (line.find(wanted) != std::string::npos)
            std::cout << "  " << line << std::endl;
      }
    catch (const dealii::ExceptionBase &error)
      {
        std::cout.rdbuf(console);
        std::ostringstream message;
        error.print_info(message);
        std::cout << "  error: " << message.str() << std::endl;
      }
  }
} // namespace

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  run({"--help"});

  std::ofstream("scene.prm") << "subsection Time\n"
                             << "  set End time = 0.5\n"
                             << "end\n";
  run({"--print-parameters", "scene.prm"}, "set End time");
  run({"--print-parameters"}, "set End time");

  // A line break in the output directory (possible with --set only).
  run({"--set", "Output/Output directory=first\nsecond", "scene.prm"});

  run({"."});
  run({"/proc/self/mem"});
  run({"no_such_scene.prm"});
}
