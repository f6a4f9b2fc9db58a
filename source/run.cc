/* Reading the command line and the .prm file, and choosing the dimension. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/utilities.h>

#include <contact_problem.h>
#include <run.h>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <iomanip>
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

    // @sect4{The convergence study}

    // Runs the scene 'Convergence study/Levels' + 1 times, halving h, k or
    // both from one run to the next (each run in its own subdirectory, with
    // its own parameters.prm), and prints the table of the largest errors
    // over the steps with their rates log2(e_{l-1}/e_l). Convergence of the
    // scheme is O(h + k) in the V-norm, Corollary 5.3 (5.26).
    void run_convergence_study(ParameterHandler &prm, const Parameters &base)
    {
      using Refine                  = ConvergenceStudyParameters::Refine;
      const auto             &study = base.convergence_study;
      ConvergenceTable        table;
      std::vector<ErrorNorms> errors;
      for (unsigned int level = 0; level <= study.levels; ++level)
        {
          const double       factor = std::pow(0.5, level);
          std::ostringstream h, k;
          h << std::setprecision(17)
            << base.geometry.cell_size *
                 (study.refine == Refine::time ? 1. : factor);
          k << std::setprecision(17)
            << base.time.time_step *
                 (study.refine == Refine::space ? 1. : factor);
          apply_override(prm, "Geometry/Cell size", h.str());
          apply_override(prm, "Time/Time step", k.str());
          apply_override(prm,
                         "Output/Output directory",
                         base.output.directory + "/level-" +
                           std::to_string(level));
          apply_override(prm, "Convergence study/Levels", "0");
          Parameters parameters;
          parameters.parse_parameters(prm);

          std::cout << "Convergence study, level " << level
                    << ": h = " << h.str() << ", k = " << k.str() << std::endl;
          const RunSummary run =
            (base.dimension == 2 ? ContactProblem<2>(parameters).run() :
                                   ContactProblem<3>(parameters).run());
          errors.push_back(run.max_errors);
          table.add_value("level", level);
          table.add_value("h", run.cell_size);
          table.add_value("k", run.time_step);
          table.add_value("unknowns", run.n_dofs);
          table.add_value("steps", run.n_steps);
          if (base.verification.manufactured_solution)
            {
              table.add_value("max |eps(u-u_h)|",
                              run.max_errors.displacement_V);
              table.add_value("max |w-w_h|", run.max_errors.velocity_L2);
              table.add_value("max |u-u_h|", run.max_errors.displacement_L2);
            }
          if (base.output.print_timings)
            table.add_value("wall time [s]", run.wall_time);
        }

      for (const std::string column : {"h", "k"})
        table.set_scientific(column, true);
      if (base.verification.manufactured_solution)
        for (const std::string column :
             {"max |eps(u-u_h)|", "max |w-w_h|", "max |u-u_h|"})
          {
            table.set_precision(column, 4);
            table.set_scientific(column, true);
            table.evaluate_convergence_rates(
              column, ConvergenceTable::reduction_rate_log2);
          }
      std::cout << std::endl
                << "Convergence study (refining "
                << (study.refine == Refine::space ? "h" :
                    study.refine == Refine::time  ? "k" :
                                                    "h and k")
                << "; rates log2(e_{l-1}/e_l)):" << std::endl;
      table.write_text(std::cout,
                       TableHandler::TextOutputFormat::org_mode_table);
      if (base.verification.manufactured_solution && study.levels > 0)
        {
          const auto last_rate = [&](const ErrorNorms &coarse,
                                     const ErrorNorms &fine,
                                     double ErrorNorms::*norm) {
            return std::log2(coarse.*norm / fine.*norm);
          };
          const ErrorNorms &coarse = errors[errors.size() - 2];
          const ErrorNorms &fine   = errors.back();
          std::cout << "Rates between the two finest levels: V-norm "
                    << std::fixed << std::setprecision(2)
                    << last_rate(coarse, fine, &ErrorNorms::displacement_V)
                    << ", velocity L2 "
                    << last_rate(coarse, fine, &ErrorNorms::velocity_L2)
                    << ", displacement L2 "
                    << last_rate(coarse, fine, &ErrorNorms::displacement_L2)
                    << std::defaultfloat << std::endl;
        }
      std::ofstream file(base.output.directory + "/convergence.txt");
      table.write_text(file, TableHandler::TextOutputFormat::org_mode_table);
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

    if (parameters.convergence_study.levels > 0)
      run_convergence_study(prm, parameters);
    else if (dimension == 2)
      ContactProblem<2>(parameters).run();
    else
      ContactProblem<3>(parameters).run();
  }
} // namespace Contact
