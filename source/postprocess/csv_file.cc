/* A table of one row per step, flushed row by row and continued on
   --resume. */

#include <deal.II/base/exceptions.h>

#include <postprocess/csv_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

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


  // The killed run may have written rows after its last checkpoint; the
  // resumed run recomputes those steps, so the file keeps the rows up to
  // the checkpoint's step. It is rewritten atomically.
  void CsvFile::cut_back(const unsigned int step) const
  {
    std::ifstream in(name);
    std::ofstream out(name + ".tmp");
    std::string   line;
    if (std::getline(in, line))
      out << line << '\n';
    while (std::getline(in, line) && in.good() && !line.empty())
      {
        const unsigned int row_step =
          std::stoul(line.substr(0, line.find(',')));
        if (row_step > step)
          break;
        out << line << '\n';
      }
    out.flush();
    AssertThrow(out,
                ExcMessage("Cannot write '" + name +
                           ".tmp': " + std::strerror(errno) + "."));
    std::filesystem::rename(name + ".tmp", name);
  }
} // namespace Contact
