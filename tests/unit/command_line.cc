/* The command line of `contact` where no scene runs: --help prints the
   usage; --version the version, commit and deal.II version; --print-parameters
   with a scene prints the scene's values, not the defaults; a directory or a
   file that cannot be read as the scene is an error naming it, not a run of the
   default scene; an output directory with a line break is refused;
   doc/parameters.prm, the documented list of every entry, is what
   --print-parameters prints (regenerate it with `cmake --build build --target
   parameters_doc`). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>

#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  // Runs the command line without printing it; returns its output.
  std::string output_of(const std::vector<std::string> &arguments)
  {
    std::vector<const char *> argv{"contact"};
    for (const std::string &argument : arguments)
      argv.push_back(argument.c_str());
    std::ostringstream captured;
    std::streambuf    *console = std::cout.rdbuf(captured.rdbuf());
    Contact::run_from_command_line(argv.size(), argv.data());
    std::cout.rdbuf(console);
    return captured.str();
  }

  // Whether the committed doc/parameters.prm is the current list of
  // entries, and where it first differs if not.
  void compare_documented_parameters()
  {
    std::ifstream      file(CONTACT_DOC_DIR "/parameters.prm");
    std::ostringstream documented;
    documented << file.rdbuf();
    std::istringstream current(output_of({"--print-parameters"})),
      committed(documented.str());
    std::string  a, b;
    unsigned int line = 0;
    bool         same = true;
    while (same)
      {
        const bool more_a = static_cast<bool>(std::getline(current, a));
        const bool more_b = static_cast<bool>(std::getline(committed, b));
        ++line;
        if (!more_a && !more_b)
          break;
        same = (more_a == more_b && a == b);
      }
    std::cout << "doc/parameters.prm is what --print-parameters prints: "
              << (same ? "yes" :
                         "no, from line " + std::to_string(line) + " on ('" +
                           a + "' against '" + b +
                           "'): cmake --build build --target "
                           "parameters_doc")
              << std::endl;
  }

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
  // The version, the commit where the build knew it, deal.II's version
  // (which change from build to build, so only their form is printed).
  const std::string version = output_of({"--version"});
  std::cout << "contact --version\n  names the version, the commit and "
            << "deal.II's version: "
            << (std::regex_match(version,
                                 std::regex(
                                   "contact [0-9]+\\.[0-9]+\\.[0-9]+ "
                                   "\\(commit ([0-9a-f]+\\+?|unknown), "
                                   "deal\\.II [0-9.]+\\)\n")) ?
                  "yes" :
                  "no: " + version)
            << std::endl;

  std::ofstream("scene.prm") << "subsection Time\n"
                             << "  set End time = 0.5\n"
                             << "end\n";
  run({"--print-parameters", "scene.prm"}, "set End time");
  run({"--print-parameters"}, "set End time");
  // --set applies to the listing too, and an undeclared entry is refused.
  run({"--print-parameters", "--set", "Time/End time=2"}, "set End time");
  run({"--print-parameters", "--set", "Time/Nothing=2"});
  compare_documented_parameters();

  // An empty entry path, or an empty name in it (crashed inside
  // ParameterHandler, or gave its internal-error text).
  run({"--set", "=3", "scene.prm"});
  run({"--set", "/Dimension=2", "scene.prm"});

  // A line break in the output directory (possible with --set only).
  run({"--set", "Output/Output directory=first\nsecond", "scene.prm"});

  // More report times than can be meant, and one that is not a number
  // (deal.II's list pattern took a time quadratic in their number).
  {
    std::ofstream many("many_report_times.prm");
    many << "subsection Output\n  set Report times = 1";
    for (unsigned int i = 0; i < 10000; ++i)
      many << ", 1";
    many << "\nend\n";
  }
  run({"many_report_times.prm"});
  run({"--set", "Output/Report times=0.3, abc", "scene.prm"});

  run({"."});
  run({"/proc/self/mem"});
  run({"no_such_scene.prm"});
}
