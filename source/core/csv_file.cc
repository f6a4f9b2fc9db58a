/* A table of one row per step, flushed row by row and continued on
   --resume. */

#include <deal.II/base/exceptions.h>

#include <core/csv_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>

namespace Contact
{
  using namespace dealii;

  void CsvFile::open(const std::string &file_name,
                     const std::string &header,
                     const bool         resumed,
                     const unsigned int step)
  {
    name = file_name;
    if (resumed && std::filesystem::exists(name))
      {
        cut_back(step);
        file.open(name, std::ios::app);
      }
    else
      {
        file.open(name);
        file << header << '\n';
        file.flush();
      }
  }


  bool CsvFile::is_open() const
  {
    return file.is_open();
  }


  std::ofstream &CsvFile::stream()
  {
    return file;
  }


  void CsvFile::check()
  {
    file.flush();
    AssertThrow(file,
                ExcMessage("Cannot write '" + name +
                           "': " + std::strerror(errno) + "."));
  }


  namespace
  {
    // The step a row starts with, if its first field is one.
    std::optional<unsigned int> step_of(const std::string &row)
    {
      const std::string field = row.substr(0, row.find(','));
      if (field.empty() || field.size() > 9 ||
          field.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
      return std::stoul(field);
    }
  } // namespace


  // The killed run may have written rows after its last checkpoint (the
  // last one perhaps cut short); the resumed run recomputes those steps,
  // so the file keeps the rows up to the checkpoint's step. Those rows
  // must all be there, one step after the other (a step may have several
  // rows): a damaged file is refused, naming its line, before anything is
  // rewritten. It is rewritten atomically.
  std::string CsvFile::rows_up_to(const std::string &name,
                                  const unsigned int step)
  {
    std::ifstream               in(name);
    std::string                 kept, line;
    std::optional<unsigned int> previous;
    unsigned int                line_number = 1;
    const auto                  damaged     = [&](const std::string &what) {
      return ExcMessage(
        "'" + name + "', line " + std::to_string(line_number) + ", " + what +
        ": resuming would lose the rows after "
                             "it. Restore the file, or delete it: the resumed "
                             "run then starts a new one after the checkpoint's step.");
    };
    AssertThrow(std::getline(in, line), damaged("the header, is missing"));
    kept = line + '\n';
    while (std::getline(in, line))
      {
        ++line_number;
        const std::optional<unsigned int> row_step = step_of(line);
        // Past the checkpoint's rows anything may follow.
        if (previous == step && row_step != step)
          break;
        AssertThrow(row_step,
                    damaged(line.empty() ? "is blank" :
                                           "does not start with a step"));
        AssertThrow(!previous ||
                      (*row_step >= *previous && *row_step <= *previous + 1),
                    damaged("has step " + std::to_string(*row_step) +
                            " after step " + std::to_string(*previous)));
        // (A file begun after the checkpoint, by an earlier resume.)
        if (*row_step > step)
          break;
        kept += line + '\n';
        previous = row_step;
      }
    AssertThrow(!previous || *previous == step,
                damaged("ends at step " + std::to_string(*previous) +
                        ", before the checkpoint's step " +
                        std::to_string(step)));
    return kept;
  }


  void CsvFile::cut_back(const unsigned int step) const
  {
    const std::string kept = rows_up_to(name, step);
    std::ofstream     out(name + ".tmp");
    out << kept;
    out.flush();
    AssertThrow(out,
                ExcMessage("Cannot write '" + name +
                           ".tmp': " + std::strerror(errno) + "."));
    std::filesystem::rename(name + ".tmp", name);
  }
} // namespace Contact
