/* The command line: reading it, and running the study the scene asks for
 * in its dimension (include/app/run.h). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <app/prm_reader.h>
#include <app/run.h>
#include <base/dimensions.h>
#include <base/version.h>
#include <core/contact_problem.h>
#include <core/scene_runner.h>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  namespace
  {
    const char *usage =
      "Usage: contact [--set 'Section/Entry=value']... [--resume] "
      "scene.prm\n"
      "       contact --print-parameters [scene.prm]\n"
      "       contact --help\n"
      "       contact --version\n"
      "  --resume continues from the checkpoint in the output directory\n"
      "  --set overrides an entry of the .prm file, e.g.\n"
      "  --set 'Friction/Friction bound S=2.5'\n"
      "  --print-parameters prints every entry with its value (the default, or "
      "scene.prm's), range and documentation";

    struct CommandLine
    {
      bool                                             print_parameters = false;
      bool                                             help             = false;
      bool                                             version          = false;
      std::string                                      parameter_file;
      std::vector<std::pair<std::string, std::string>> overrides;
    };

    CommandLine read_command_line(const int argc, const char *const *argv)
    {
      CommandLine command_line;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--print-parameters")
            command_line.print_parameters = true;
          else if (argument == "--help" || argument == "-h")
            command_line.help = true;
          else if (argument == "--version")
            command_line.version = true;
          else if (argument == "--resume")
            command_line.overrides.emplace_back(Entry::resume, "true");
          else if (argument == "--set" && i + 1 < argc)
            {
              const std::string assignment = argv[++i];
              const auto        equal      = assignment.find('=');
              const std::string path =
                equal == std::string::npos ?
                  "" :
                  Utilities::trim(assignment.substr(0, equal));
              // An empty path, or an empty section or entry name in it
              // ('=3', '/Dimension=2', 'Time//End time=1'), is no entry.
              AssertThrow(!path.empty() && path.front() != '/' &&
                            path.back() != '/' &&
                            path.find("//") == std::string::npos,
                          ExcMessage("'--set " + assignment +
                                     "' is not of the form "
                                     "'Section/Entry=value' (or 'Entry=value' "
                                     "for an entry outside the subsections, "
                                     "such as 'Dimension=3').\n" +
                                     usage));
              command_line.overrides.emplace_back(
                path, Utilities::trim(assignment.substr(equal + 1)));
            }
          else
            {
              AssertThrow(command_line.parameter_file.empty() &&
                            argument.rfind("-", 0) != 0,
                          ExcMessage("Unexpected argument '" + argument +
                                     "'.\n" + usage));
              command_line.parameter_file = argument;
            }
        }
      AssertThrow(command_line.help || command_line.version ||
                    command_line.print_parameters ||
                    !command_line.parameter_file.empty(),
                  ExcMessage(std::string("No parameter file given.\n") +
                             usage));
      return command_line;
    }

    // The scene, run by the part that runs scenes (core/scene_runner.h),
    // or, in a build without one, as one run.
    void run_scene(const Parameters &parameters)
    {
      if (!SceneRunners::parts().empty())
        {
          SceneRunners::parts().front().create()->run(parameters);
          return;
        }
#define INSTANTIATE(dim)           \
  if (parameters.dimension == dim) \
    ContactProblem<dim>(parameters).run();
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    }
  } // namespace


  void run_from_command_line(const int argc, const char *const *argv)
  {
    const CommandLine command_line = read_command_line(argc, argv);
    if (command_line.help)
      {
        std::cout << usage << std::endl;
        return;
      }
    if (command_line.version)
      {
        std::cout << version_text() << std::endl;
        return;
      }
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    if (command_line.print_parameters)
      {
        read_scene(prm, command_line.parameter_file, command_line.overrides);
        prm.print_parameters(std::cout,
                             ParameterHandler::PRM |
                               ParameterHandler::KeepDeclarationOrder);
        return;
      }
    const Parameters parameters =
      read_scene(prm, command_line.parameter_file, command_line.overrides);
    run_scene(parameters);
  }


  Parameters read_parameters(const std::string              &parameter_file,
                             const std::vector<std::string> &overrides)
  {
    std::vector<std::string> arguments = {"contact"};
    for (const std::string &assignment : overrides)
      {
        arguments.push_back("--set");
        arguments.push_back(assignment);
      }
    arguments.push_back(parameter_file);
    std::vector<const char *> argv;
    for (const std::string &argument : arguments)
      argv.push_back(argument.c_str());

    const CommandLine command_line =
      read_command_line(argv.size(), argv.data());
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    return read_scene(prm, command_line.parameter_file, command_line.overrides);
  }
} // namespace Contact
