/* Reading a scene's .prm file (include/app/prm_reader.h). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <app/prm_reader.h>
#include <base/printed_entries.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace Contact
{
  namespace
  {
    // @sect4{Did you mean}

    // Every declared subsection ("A/B/") and entry ("A/B/name") of the
    // handler, from its own listing.
    std::set<std::string> declared_paths(const ParameterHandler &prm)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::set<std::string> paths;
      for (const auto &[entry, value] : read_printed_entries(listing.str()))
        {
          paths.insert(entry);
          for (auto slash = entry.find('/'); slash != std::string::npos;
               slash      = entry.find('/', slash + 1))
            paths.insert(entry.substr(0, slash + 1));
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
              const bool         same =
                std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
              row[j] = std::min(
                {row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
              diagonal = above;
            }
        }
      return row[b.size()];
    }

    // The name that ParameterHandler's message says is not declared, and
    // whether it is a subsection; empty for other messages.
    std::pair<std::string, bool> undeclared_name(const std::string &message)
    {
      for (const std::string marker :
           {"No entry with name <", "You can't ask for entry <"})
        if (const auto at = message.find(marker); at != std::string::npos)
          {
            const auto begin = at + marker.size();
            return {message.substr(begin, message.find('>', begin) - begin),
                    false};
          }
      const std::string marker = "There is no such subsection to be entered: ";
      if (const auto at = message.find(marker); at != std::string::npos)
        {
          const std::string name =
            Utilities::trim(message.substr(at + marker.size()));
          return {name.substr(0, name.find('\n')), true};
        }
      return {"", false};
    }

    // For ParameterHandler's message about an undeclared entry or
    // subsection: the declared ones whose names are closest to it (within
    // a third of its length), as " Did you mean 'A/B/name'?", or "".
    std::string closest_declared(const ParameterHandler &prm,
                                 const std::string      &message)
    {
      const auto [name, section] = undeclared_name(message);
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


    // @sect4{Include}

    // The file a .prm file names in 'include', relative to the including
    // file `file` (a scene includes the one next to it wherever the
    // program runs; ParameterHandler alone would take it relative to the
    // working directory).
    std::filesystem::path included_file(const std::string &statement,
                                        const std::string &file,
                                        const unsigned int line_number)
    {
      AssertThrow(statement.size() > 7,
                  ExcMessage("In '" + file + "', line " +
                             std::to_string(line_number) +
                             ": 'include' needs the name of a file."));
      std::filesystem::path included(Utilities::trim(statement.substr(7)));
      if (included.is_relative())
        included = std::filesystem::path(file).parent_path() / included;
      AssertThrow(std::ifstream(included).good(),
                  ExcMessage("In '" + file + "': cannot open the file '" +
                             included.string() + "' it includes."));
      return included;
    }

    // `chain` holds the files that include `file`: a file that includes
    // itself, directly or through others, is refused instead of being read
    // until the stack overflows. On return `file` is in the chain.
    void enter_chain(const std::string                  &file,
                     std::vector<std::filesystem::path> &chain)
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
    }

    std::string mesh_file_of(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      const std::string name = prm.get("Mesh file");
      prm.leave_subsection();
      return Utilities::trim(name);
    }

    // Parses the text of `file` between two includes. A relative
    // 'Geometry/Mesh file' that it sets is taken relative to `file`, as an
    // include is.
    void parse_text(ParameterHandler  &prm,
                    const std::string &text,
                    const std::string &file)
    {
      const std::string  mesh_before = mesh_file_of(prm);
      std::istringstream in(text);
      try
        {
          prm.parse_input(in, file);
        }
      catch (const ExceptionBase &exc)
        {
          rethrow_with_suggestion(prm, exc, "");
        }
      const std::filesystem::path mesh = mesh_file_of(prm);
      if (!mesh.empty() && mesh.string() != mesh_before && mesh.is_relative())
        {
          prm.enter_subsection("Geometry");
          // Absolute, so that the parameters.prm a run writes into its
          // output directory finds the mesh when it is run again.
          prm.set("Mesh file",
                  std::filesystem::absolute(
                    std::filesystem::path(file).parent_path() / mesh)
                    .lexically_normal()
                    .string());
          prm.leave_subsection();
        }
    }

    // Parses a .prm file in which 'include other.prm' (at the top level,
    // outside subsections) is read relative to it. The text between
    // includes goes to ParameterHandler with the lines before it blanked,
    // so that its error messages keep the line numbers of the file.
    // Returns the number of 'set' statements, its includes' counted.
    unsigned int
    parse_parameter_file(ParameterHandler                  &prm,
                         const std::string                 &file,
                         std::vector<std::filesystem::path> chain = {})
    {
      enter_chain(file, chain);
      std::ifstream in(file);
      AssertThrow(in,
                  ExcMessage("Cannot open the parameter file '" + file + "'."));
      std::string  chunk, blank_lines;
      unsigned int depth = 0, line_number = 0, n_sets = 0;
      for (std::string line; std::getline(in, line);)
        {
          // A UTF-8 byte order mark, as some editors write it, is no text.
          if (++line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3);
          const std::string statement =
            Utilities::trim(line.substr(0, line.find('#')));
          // A keyword ends at any white space: ParameterHandler reads
          // "include<TAB>file" as an include too, but relative to the
          // working directory and past the cycle check.
          const std::string keyword =
            statement.substr(0, statement.find_first_of(" \t\v\f\r"));
          if (keyword == "set" || keyword == "SET")
            ++n_sets;
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
          parse_text(prm, chunk, file);
          n_sets +=
            parse_parameter_file(prm,
                                 included_file(statement, file, line_number),
                                 chain);
          blank_lines += '\n';
          chunk = blank_lines;
        }
      AssertThrow(!in.bad(),
                  ExcMessage("Reading the parameter file '" + file +
                             "' failed after line " +
                             std::to_string(line_number) + ": " +
                             std::strerror(errno) + "."));
      parse_text(prm, chunk, file);
      return n_sets;
    }


    // @sect4{Overrides}

    // Sets "Section/Subsection/Entry" = value; ParameterHandler itself
    // rejects entries that are not declared and values that do not match
    // the entry's pattern.
    void apply_override(ParameterHandler  &prm,
                        const std::string &path,
                        const std::string &value)
    {
      // A mesh file given here is relative to the working directory; made
      // absolute as one read from a file is (parse_text()).
      const bool relative_mesh_file =
        path == Entry::mesh_file && !Utilities::trim(value).empty() &&
        std::filesystem::path(Utilities::trim(value)).is_relative();
      try
        {
          set_entry(prm,
                    path,
                    relative_mesh_file ?
                      std::filesystem::absolute(Utilities::trim(value))
                        .lexically_normal()
                        .string() :
                      value);
        }
      catch (const ExceptionBase &exc)
        {
          rethrow_with_suggestion(prm,
                                  exc,
                                  "--set '" + path + "=" + value + "': ");
        }
    }
  } // namespace


  // @sect4{read_scene}

  Parameters
  read_scene(ParameterHandler                                       &prm,
             const std::string                                      &file,
             const std::vector<std::pair<std::string, std::string>> &overrides)
  {
    // (No file: the defaults, e.g. for --print-parameters.) A file that
    // sets nothing would run the default scene into its output directory,
    // replacing what is there: a file emptied by mistake, not a scene.
    if (!file.empty())
      AssertThrow(parse_parameter_file(prm, file) > 0,
                  ExcMessage("The parameter file '" + file +
                             "' sets no entry (it is empty or holds only "
                             "comments and subsections). Give a scene: for "
                             "the paper's example 'prm/barboteu2015.prm'; "
                             "'contact --print-parameters' lists every "
                             "entry with its default."));
    for (const auto &[path, value] : overrides)
      apply_override(prm, path, value);
    Parameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }
} // namespace Contact
