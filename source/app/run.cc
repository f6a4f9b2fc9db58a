/* Reading the command line and the .prm file, and choosing the dimension. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>



#include <core/contact_problem.h>
#include <drivers/error_estimate.h>
#include <drivers/target_error.h>
#include <drivers/reference_interpolation.h>
#include <app/run.h>

#include <filesystem>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  namespace
  {
    // The console of a convergence study: the first process's standard
    // output (the stream of the others is never opened, so it drops what
    // it is given).
    std::ostream &console()
    {
      static std::ofstream dropped;
      return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? std::cout :
                                                                     dropped;
    }

    const char *usage =
      "Usage: contact [--set 'Section/Entry=value']... [--resume] "
      "scene.prm\n"
      "       contact --print-parameters [scene.prm]\n"
      "       contact --help\n"
      "  --resume continues from the checkpoint in the output directory\n"
      "  --set overrides an entry of the .prm file, e.g.\n"
      "  --set 'Friction/Friction bound S=2.5'\n"
      "  --print-parameters prints every entry with its value (the default, or "
      "scene.prm's), range and documentation";

    struct CommandLine
    {
      bool                                             print_parameters = false;
      bool                                             help             = false;
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
          else if (argument == "--resume")
            command_line.overrides.emplace_back(Entry::resume, "true");
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
      AssertThrow(command_line.help || command_line.print_parameters ||
                    !command_line.parameter_file.empty(),
                  ExcMessage(std::string("No parameter file given.\n") +
                             usage));
      return command_line;
    }

    // Every declared subsection ("A/B/") and entry ("A/B/name") of the
    // handler, from its own listing.
    std::vector<std::string> declared_paths(const ParameterHandler &prm)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::vector<std::string> sections, paths;
      const auto               prefix = [&]() {
        std::string path;
        for (const std::string &section : sections)
          path += section + '/';
        return path;
      };
      std::istringstream lines(listing.str());
      for (std::string line; std::getline(lines, line);)
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            {
              sections.push_back(Utilities::trim(line.substr(11)));
              paths.push_back(prefix());
            }
          else if (line == "end" && !sections.empty())
            sections.pop_back();
          else if (line.rfind("set ", 0) == 0)
            paths.push_back(
              prefix() + Utilities::trim(line.substr(4, line.find('=') - 4)));
        }
      return paths;
    }

    // The number of single-character edits between two names, ignoring
    // case.
    unsigned int edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int above = row[j];
              row[j]                   = std::min(
                {row[j] + 1,
                                   row[j - 1] + 1,
                                   diagonal +
                                     (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1)});
              diagonal = above;
            }
        }
      return row[b.size()];
    }

    // For ParameterHandler's message about an undeclared entry or
    // subsection: the declared ones whose names are closest to it (within
    // a third of its length), as " Did you mean 'A/B/name'?", or "".
    std::string closest_declared(const ParameterHandler &prm,
                                 const std::string      &message)
    {
      const std::string entry_markers[] = {"No entry with name <",
                                           "You can't ask for entry <"};
      const std::string section_marker =
        "There is no such subsection to be entered: ";
      std::string name;
      bool        section = false;
      for (const std::string &marker : entry_markers)
        if (const auto at = message.find(marker);
            name.empty() && at != std::string::npos)
          {
            const auto begin = at + marker.size();
            name = message.substr(begin, message.find('>', begin) - begin);
          }
      if (const auto at = message.find(section_marker);
          name.empty() && at != std::string::npos)
        {
          name    = Utilities::trim(message.substr(at + section_marker.size()));
          name    = name.substr(0, name.find('\n'));
          section = true;
        }
      if (name.empty())
        return "";
      std::vector<std::pair<unsigned int, std::string>> candidates;
      for (const std::string &path : declared_paths(prm))
        {
          const bool is_section = (path.back() == '/');
          if (is_section != section)
            continue;
          const std::string trimmed =
            is_section ? path.substr(0, path.size() - 1) : path;
          const std::string  last     = trimmed.substr(trimmed.rfind('/') + 1);
          const unsigned int distance = edit_distance(name, last);
          if (distance <= std::max<std::size_t>(1, name.size() / 3))
            candidates.emplace_back(distance, trimmed);
        }
      if (candidates.empty())
        return "";
      std::sort(candidates.begin(), candidates.end());
      std::string suggestion = " Did you mean ";
      for (unsigned int i = 0; i < std::min<std::size_t>(3, candidates.size());
           ++i)
        suggestion += (i == 0 ? "'" : " or '") + candidates[i].second + "'";
      return suggestion + "?";
    }

    // A ParameterHandler error with the closest declared names added.
    [[noreturn]] void rethrow_with_suggestion(const ParameterHandler &prm,
                                              const ExceptionBase    &exc,
                                              const std::string      &context)
    {
      std::ostringstream reason;
      exc.print_info(reason);
      std::string       text       = Utilities::trim(reason.str());
      const std::string suggestion = closest_declared(prm, text);
      if (!suggestion.empty() && text.back() != '.')
        text += '.';
      // A value outside its pattern is shown with the allowed ones already.
      const bool undeclared =
        text.find("declared") != std::string::npos ||
        text.find("no such subsection") != std::string::npos;
      AssertThrow(false,
                  ExcMessage(context + text + suggestion +
                             (undeclared || !context.empty() ?
                                " (contact --print-parameters lists every "
                                "entry with its allowed values)" :
                                "")));
      std::abort();
    }


  } // namespace


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
        rethrow_with_suggestion(prm,
                                exc,
                                "--set '" + path + "=" + value + "': ");
      }
  }


  namespace
  {

    // Parses a .prm file in which 'include other.prm' (at the top level,
    // outside subsections) takes the path relative to the including file,
    // so that a scene can include the one next to it wherever the program
    // runs (ParameterHandler alone would take it relative to the working
    // directory). The text between includes goes to ParameterHandler with
    // the lines before it blanked, so its error messages keep the line
    // numbers of the file.
    //
    // A relative 'Geometry/Mesh file' is made relative to the file that sets
    // it, for the same reason (only in the full parse, where it is
    // declared).
    //
    // `chain` holds the files that include this one: a file that includes
    // itself, directly or through others, is refused instead of being read
    // until the stack overflows.
    void parse_parameter_file(ParameterHandler                  &prm,
                              const std::string                 &file,
                              const bool                         skip_undefined,
                              std::vector<std::filesystem::path> chain = {})
    {
      std::error_code             error;
      const std::filesystem::path canonical =
        std::filesystem::weakly_canonical(file, error);
      std::string cycle;
      for (const std::filesystem::path &including : chain)
        cycle += (cycle.empty() ? "" : " -> ") + including.string();
      AssertThrow(std::find(chain.begin(), chain.end(), canonical) ==
                    chain.end(),
                  ExcMessage("The parameter files include each other in a "
                             "cycle: " +
                             cycle + " -> " + canonical.string() +
                             ". Remove the 'include' that closes it."));
      chain.push_back(canonical);
      AssertThrow(!std::filesystem::is_directory(file, error),
                  ExcMessage("The parameter file '" + file +
                             "' is a directory; give a .prm file."));
      std::ifstream in(file);
      AssertThrow(in,
                  ExcMessage("Cannot open the parameter file '" + file + "'."));
      const std::filesystem::path directory =
        std::filesystem::path(file).parent_path();
      std::string  chunk, blank_lines;
      unsigned int depth     = 0;
      const auto   mesh_file = [&]() {
        prm.enter_subsection("Geometry");
        const std::string name = prm.get("Mesh file");
        prm.leave_subsection();
        return Utilities::trim(name);
      };
      const auto flush = [&]() {
        const std::string  mesh_before = skip_undefined ? "" : mesh_file();
        std::istringstream text(chunk);
        try
          {
            prm.parse_input(text, file, "", skip_undefined);
          }
        catch (const ExceptionBase &exc)
          {
            rethrow_with_suggestion(prm, exc, "");
          }
        chunk.clear();
        if (skip_undefined)
          return;
        const std::filesystem::path mesh = mesh_file();
        if (!mesh.empty() && mesh.string() != mesh_before && mesh.is_relative())
          {
            prm.enter_subsection("Geometry");
            prm.set("Mesh file",
                    (directory / mesh).lexically_normal().string());
            prm.leave_subsection();
          }
      };
      unsigned int line_number = 0;
      for (std::string line; std::getline(in, line);)
        {
          // A UTF-8 byte order mark, as some editors write it, is no text.
          if (++line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3);
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
          AssertThrow(statement.size() > 7,
                      ExcMessage("In '" + file + "', line " +
                                 std::to_string(line_number) +
                                 ": 'include' needs the name of a file."));
          std::filesystem::path included(Utilities::trim(statement.substr(7)));
          if (included.is_relative())
            included = directory / included;
          AssertThrow(std::ifstream(included).good(),
                      ExcMessage("In '" + file + "': cannot open the file '" +
                                 included.string() + "' it includes."));
          parse_parameter_file(prm, included.string(), skip_undefined, chain);
          blank_lines += '\n';
          chunk = blank_lines;
        }
      AssertThrow(!in.bad(),
                  ExcMessage("Reading the parameter file '" + file +
                             "' failed after line " +
                             std::to_string(line_number) + ": " +
                             std::strerror(errno) + "."));
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

    // The whole .prm file, checked, with the --set overrides applied.
    Parameters read_parameters(const CommandLine &command_line,
                               ParameterHandler  &prm)
    {
      const unsigned int dimension = read_dimension(command_line);
      parse_parameter_file(prm, command_line.parameter_file, false);
      for (const auto &[path, value] : command_line.overrides)
        apply_override(prm, path, value);

      Parameters parameters;
      parameters.parse_parameters(prm);
      AssertThrow(parameters.dimension == dimension, ExcInternalError());
      return parameters;
    }

    // @sect4{The convergence study}

    // One level of a convergence study: its run, and (without an exact
    // solution) its displacements at the times of the coarsest level's
    // grid, interpolated onto the finest mesh.
    struct LevelResult
    {
      RunSummary              run;
      std::vector<VectorType> displacements;
    };

    // Sets the entries that differ from one level to the next, and parses.
    Parameters parameters_of_level(ParameterHandler  &prm,
                                   const Parameters  &base,
                                   const unsigned int level,
                                   const bool         announce = true)
    {
      using Refine               = ConvergenceStudyParameters::Refine;
      const auto        &study   = base.convergence_study;
      const unsigned int n_steps = base.time.n_steps();
      const double       factor  = std::pow(0.5, level);
      std::ostringstream h, k;
      h << std::setprecision(17)
        << base.geometry.cell_size *
             (study.refine == Refine::time ? 1. : factor);
      k << std::setprecision(17)
        << base.time.end_time / n_steps *
             (study.refine == Refine::space ? 1. : factor);
      // A mesh read from a file is refined globally instead of by the
      // cell size of a box.
      const bool        mesh_file = !base.geometry.is_box();
      const std::string refinements =
        std::to_string(base.geometry.mesh_refinements +
                       (study.refine == Refine::time ? 0 : level));
      apply_override(prm, Entry::cell_size, h.str());
      if (mesh_file)
        apply_override(prm, Entry::mesh_refinements, refinements);
      apply_override(prm, Entry::time_step, k.str());
      apply_override(prm,
                     Entry::output_directory,
                     base.output.directory + "/level-" + std::to_string(level));
      apply_override(prm, Entry::levels, "0");
      Parameters parameters;
      parameters.parse_parameters(prm);
      if (!announce)
        return parameters;
      console() << "Convergence study, level " << level << ": "
                << (mesh_file ? "mesh refinements = " + refinements :
                                "h = " + h.str())
                << ", k = " << k.str() << std::endl;
      return parameters;
    }

    // Runs the scene 'Convergence study/Levels' + 1 times, halving h, k or
    // both from one level to the next (each run in its own subdirectory,
    // with its own parameters.prm; the time steps are T/(N 2^l), so that the
    // time grids are nested), and prints the errors with their rates
    // log2(e_{l-1}/e_l). Corollary 5.3, (5.26): O(h + k) in the V-norm.
    //
    // With a manufactured solution the errors are exact. Otherwise the
    // finest level is the reference (run first and kept, so that the coarser
    // solutions can be interpolated onto its mesh), the errors are taken at
    // t = T and over the common time grid (the coarsest level's), and the
    // differences of successive levels give an estimate that needs no
    // reference (a reference only twice as fine flatters the last rate).
    template <int dim>
    void run_convergence_study(ParameterHandler &prm, const Parameters &base)
    {
      using Refine                   = ConvergenceStudyParameters::Refine;
      const auto              &study = base.convergence_study;
      const unsigned int       L     = study.levels;
      const bool               exact = base.verification.manufactured_solution;
      std::vector<LevelResult> results(L + 1);
      // Every level's entries are checked before the first level runs, so
      // that a study does not fail at its finest level (e.g. over
      // 'Time/Max steps' or the number of VTU files).
      for (unsigned int level = 0; level <= L; ++level)
        parameters_of_level(prm, base, level, /*announce=*/false);
      // The study owns its directory while it runs (a plain run there
      // would clean away its levels), and starts it afresh: a study with
      // fewer levels than the last one leaves none of that one's levels or
      // table behind.
      const auto lock =
        lock_output_directory(base.output.directory, MPI_COMM_WORLD);
      remove_results(base.output.directory, false, MPI_COMM_WORLD);

      // Collects the displacement at the common times (every 2^l-th step of
      // level l when k is refined), interpolated onto the reference mesh.
      // The reference's nodes are gathered at its first step (it runs
      // first), and located in a level's mesh at the level's first step.
      std::unique_ptr<ContactProblem<dim>>         reference;
      std::unique_ptr<ReferenceInterpolation<dim>> interpolate;
      using NodesInCells =
        std::vector<typename ReferenceInterpolation<dim>::NodeInCell>;
      const auto collect = [&](const unsigned int level) {
        const unsigned int stride =
          (study.refine == Refine::space ? 1 : 1u << level);
        return [&, stride, level, located = std::optional<NodesInCells>()](
                 const ContactProblem<dim> &problem) mutable {
          if (problem.get_step_number() % stride != 0)
            return;
          if (!interpolate)
            interpolate =
              std::make_unique<ReferenceInterpolation<dim>>(*reference);
          if (!located)
            located = interpolate->locate(problem);
          results[level].displacements.push_back(
            (*interpolate)(*located, problem, problem.get_displacement()));
        };
      };

      if (!exact)
        {
          if (study.reference_degree > 0)
            apply_override(prm,
                           Entry::finite_element_degree,
                           std::to_string(study.reference_degree));
          reference = std::make_unique<ContactProblem<dim>>(
            parameters_of_level(prm, base, L));
          apply_override(prm,
                         Entry::finite_element_degree,
                         std::to_string(base.geometry.fe_degree));
          reference->set_step_observer(collect(L));
          results[L].run = reference->run();
        }
      for (unsigned int level = 0; level < (exact ? L + 1 : L); ++level)
        {
          ContactProblem<dim> problem(parameters_of_level(prm, base, level));
          if (!exact)
            problem.set_step_observer(collect(level));
          results[level].run = problem.run();
        }

      // Per level: each error with the name of its column and of its rate
      // column (log2 of the ratio to the level before).
      struct Error
      {
        std::string name;
        std::string rate_name;
        double      value;
      };
      const auto difference_norm = [&](const VectorType &a,
                                       const VectorType &b) {
        VectorType difference(a);
        difference -= b;
        return reference->strain_norm(difference);
      };
      const unsigned int              n_levels = (exact ? L + 1 : L);
      std::vector<std::vector<Error>> errors(n_levels);
      for (unsigned int level = 0; level < n_levels; ++level)
        if (exact)
          {
            const ErrorNorms &e = results[level].run.max_errors;
            errors[level]       = {{"max V-error", "V rate", e.displacement_V},
                                   {"max L2 velocity error",
                                    "velocity rate",
                                    e.velocity_L2},
                                   {"max L2 displacement error",
                                    "displacement rate",
                                    e.displacement_L2}};
          }
        else
          {
            const auto &u       = results[level].displacements;
            const auto &u_ref   = results[L].displacements;
            double      largest = 0;
            for (unsigned int n = 0; n < u.size(); ++n)
              largest = std::max(largest, difference_norm(u[n], u_ref[n]));
            errors[level] = {
              {"V-error at T",
               "rate at T",
               difference_norm(u.back(), u_ref.back())},
              {"max V-error", "max rate", largest},
              {"V-difference to next level at T",
               "difference rate",
               difference_norm(u.back(),
                               results[level + 1].displacements.back())}};
          }
      // The scale of the V-errors: ||eps(u_h(T))|| of the finest level.
      const double solution_norm = results[L].run.displacement_V_norm;

      TableHandler table;
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          const RunSummary &run = results[level].run;
          table.add_value("level", level);
          table.add_value("h", run.cell_size);
          table.add_value("k", run.time_step);
          table.add_value("unknowns", run.n_dofs);
          table.add_value("steps", run.n_steps);
          for (unsigned int i = 0; i < errors[level].size(); ++i)
            {
              const Error &e = errors[level][i];
              table.add_value(e.name, e.value);
              table.set_precision(e.name, 4);
              table.set_scientific(e.name, true);
              if (level == 0)
                table.add_value(e.rate_name, std::string("-"));
              else
                table.add_value(e.rate_name,
                                std::log2(errors[level - 1][i].value /
                                          e.value));
              table.set_precision(e.rate_name, 2);
            }
          table.add_value("relative V-error",
                          errors[level][0].value /
                            std::max(solution_norm,
                                     std::numeric_limits<double>::min()));
          table.set_precision("relative V-error", 2);
          table.set_scientific("relative V-error", true);
          if (base.output.print_timings)
            table.add_value("wall time [s]", run.wall_time);
        }
      for (const std::string column : {"h", "k"})
        table.set_scientific(column, true);
      console() << std::endl
                << "Convergence study (refining "
                << (study.refine == Refine::space ? "h" :
                    study.refine == Refine::time  ? "k" :
                                                    "h and k")
                << "; rates log2(e_{l-1}/e_l); relative V-error: the first "
                << "error column over ||eps(u_h(T))|| = "
                << std::setprecision(4) << solution_norm
                << " of the finest level";
      if (!exact)
        console() << "; reference: level " << L << std::setprecision(6)
                  << ", h = " << results[L].run.cell_size
                  << ", k = " << results[L].run.time_step << ", "
                  << results[L].run.n_dofs << " unknowns";
      console() << "):" << std::endl;
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          table.write_text(std::cout,
                           TableHandler::TextOutputFormat::org_mode_table);
          std::ofstream file(base.output.directory + "/convergence.txt");
          table.write_text(file,
                           TableHandler::TextOutputFormat::org_mode_table);
        }

      if (exact && L > 0)
        {
          const ErrorNorms &coarse = results[L - 1].run.max_errors;
          const ErrorNorms &fine   = results[L].run.max_errors;
          console() << "Rates between the two finest levels: V-norm "
                    << std::fixed << std::setprecision(2)
                    << std::log2(coarse.displacement_V / fine.displacement_V)
                    << ", velocity L2 "
                    << std::log2(coarse.velocity_L2 / fine.velocity_L2)
                    << ", displacement L2 "
                    << std::log2(coarse.displacement_L2 / fine.displacement_L2)
                    << std::defaultfloat << std::endl;
        }
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
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    if (command_line.print_parameters)
      {
        if (!command_line.parameter_file.empty())
          read_parameters(command_line, prm);
        prm.print_parameters(std::cout,
                             ParameterHandler::PRM |
                               ParameterHandler::KeepDeclarationOrder);
        return;
      }

    const Parameters   parameters = read_parameters(command_line, prm);
    const unsigned int dimension  = parameters.dimension;
    if (parameters.convergence_study.levels > 0 && dimension == 2)
      run_convergence_study<2>(prm, parameters);
    else if (parameters.convergence_study.levels > 0)
      run_convergence_study<3>(prm, parameters);
    else if (parameters.accuracy.target_error > 0 && dimension == 2)
      run_to_target<2>(prm, parameters);
    else if (parameters.accuracy.target_error > 0)
      run_to_target<3>(prm, parameters);
    else if (parameters.accuracy.estimate_error && dimension == 2)
      run_with_error_estimate<2>(prm, parameters);
    else if (parameters.accuracy.estimate_error)
      run_with_error_estimate<3>(prm, parameters);
    else if (dimension == 2)
      ContactProblem<2>(parameters).run();
    else
      ContactProblem<3>(parameters).run();
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

    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    return read_parameters(read_command_line(argv.size(), argv.data()), prm);
  }
} // namespace Contact
