/* Reading the command line and the .prm file, and choosing the dimension. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <contact_problem.h>
#include <run.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  namespace
  {
    const char *usage =
      "Usage: contact [--set 'Section/Entry=value']... scene.prm\n"
      "       contact --print-parameters\n"
      "  --set overrides an entry of the .prm file, e.g.\n"
      "  --set 'Friction/Friction bound S=2.5'\n"
      "  --print-parameters prints every entry with its default, range and "
      "documentation";

    struct CommandLine
    {
      bool                                             print_parameters = false;
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
          else if (argument == "--set" && i + 1 < argc)
            {
              const std::string assignment = argv[++i];
              const auto        equal      = assignment.find('=');
              AssertThrow(equal != std::string::npos,
                          ExcMessage("'--set " + assignment +
                                     "' is not of the form "
                                     "'Section/Entry=value'.\n" +
                                     usage));
              command_line.overrides.emplace_back(
                Utilities::trim(assignment.substr(0, equal)),
                Utilities::trim(assignment.substr(equal + 1)));
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
      AssertThrow(
        command_line.print_parameters || !command_line.parameter_file.empty(),
        ExcMessage(std::string("No parameter file given.\n") + usage));
      return command_line;
    }

    // Sets "Section/Subsection/Entry" = value; ParameterHandler itself
    // rejects entries that are not declared and values that do not match
    // the entry's pattern.
    void apply_override(ParameterHandler  &prm,
                        const std::string &path,
                        const std::string &value)
    {
      const std::vector<std::string> names =
        Utilities::split_string_list(path, '/');
      try
        {
          for (unsigned int i = 0; i + 1 < names.size(); ++i)
            prm.enter_subsection(names[i]);
          prm.set(names.back(), value);
          for (unsigned int i = 0; i + 1 < names.size(); ++i)
            prm.leave_subsection();
        }
      catch (const ExceptionBase &exc)
        {
          std::ostringstream reason;
          exc.print_info(reason);
          AssertThrow(false,
                      ExcMessage("--set '" + path + "=" + value +
                                 "': " + Utilities::trim(reason.str()) +
                                 " (contact --print-parameters lists every "
                                 "entry with its allowed values)"));
        }
    }

    // Parses a .prm file in which 'include other.prm' (at the top level,
    // outside subsections) takes the path relative to the including file,
    // so that a scene can include the one next to it wherever the program
    // runs (ParameterHandler alone would take it relative to the working
    // directory). The text between includes goes to ParameterHandler with
    // the lines before it blanked, so its error messages keep the line
    // numbers of the file.
    void parse_parameter_file(ParameterHandler  &prm,
                              const std::string &file,
                              const bool         skip_undefined)
    {
      std::ifstream in(file);
      AssertThrow(in,
                  ExcMessage("Cannot open the parameter file '" + file + "'."));
      const std::filesystem::path directory =
        std::filesystem::path(file).parent_path();
      std::string  chunk, blank_lines;
      unsigned int depth = 0;
      const auto   flush = [&]() {
        std::istringstream text(chunk);
        prm.parse_input(text, file, "", skip_undefined);
        chunk.clear();
      };
      for (std::string line; std::getline(in, line);)
        {
          const std::string statement =
            Utilities::trim(line.substr(0, line.find('#')));
          const std::string keyword = statement.substr(0, statement.find(' '));
          if (keyword == "subsection")
            ++depth;
          else if (keyword == "end" && depth > 0)
            --depth;
          if (keyword != "include" && keyword != "INCLUDE")
            {
              chunk += line + '\n';
              blank_lines += '\n';
              continue;
            }
          AssertThrow(depth == 0,
                      ExcMessage("In '" + file +
                                 "': 'include' is allowed "
                                 "only outside of subsections."));
          flush();
          std::filesystem::path included(Utilities::trim(statement.substr(7)));
          if (included.is_relative())
            included = directory / included;
          AssertThrow(std::ifstream(included).good(),
                      ExcMessage("In '" + file + "': cannot open the file '" +
                                 included.string() + "' it includes."));
          parse_parameter_file(prm, included.string(), skip_undefined);
          blank_lines += '\n';
          chunk = blank_lines;
        }
      flush();
    }

    unsigned int read_dimension(const CommandLine &command_line)
    {
      ParameterHandler prm;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3));
      parse_parameter_file(prm, command_line.parameter_file, true);
      for (const auto &[path, value] : command_line.overrides)
        if (path == "Dimension")
          prm.set(path, value);
      return prm.get_integer("Dimension");
    }
  } // namespace


  void run_from_command_line(const int argc, const char *const *argv)
  {
    const CommandLine command_line = read_command_line(argc, argv);
    ParameterHandler  prm;
    Parameters::declare_parameters(prm);
    if (command_line.print_parameters)
      {
        prm.print_parameters(std::cout,
                             ParameterHandler::PRM |
                               ParameterHandler::KeepDeclarationOrder);
        return;
      }

    const unsigned int dimension = read_dimension(command_line);
    parse_parameter_file(prm, command_line.parameter_file, false);
    for (const auto &[path, value] : command_line.overrides)
      apply_override(prm, path, value);

    Parameters parameters;
    parameters.parse_parameters(prm);
    AssertThrow(parameters.dimension == dimension, ExcInternalError());

    if (dimension == 2)
      ContactProblem<2>(parameters).run();
    else
      ContactProblem<3>(parameters).run();
  }
} // namespace Contact
