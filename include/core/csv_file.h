/**
 * A table of one row per step (time_series.csv, gamma3_history.csv) whose
 * first column is the step: written row by row and flushed at once, so
 * that if a later step fails the file describes exactly the steps that
 * were computed; on --resume cut back to the checkpoint's step and
 * continued (csv_file.cc).
 */
#ifndef contact_csv_file_h
#define contact_csv_file_h

#include <fstream>
#include <string>

namespace Contact
{
  class CsvFile
  {
  public:
    /** Opens `name` on the first process: a resumed run keeps its rows up
     *  to `step` and appends (if the file is gone, a new one starts with
     *  the header at the checkpoint's step); a fresh run starts a new file
     *  with `header` (a line without its newline). */
    void open(const std::string &name,
              const std::string &header,
              const bool         resumed,
              const unsigned int step);

    bool is_open() const;

    /** The stream rows are written to; check() after each row. */
    std::ofstream &stream();

    /** Flushes the rows written, and throws naming the file if that
     *  failed. */
    void check();

    /** The text of the file `name` up to the rows of `step`; throws,
     *  naming the line, if a row before them is damaged. A resumed run
     *  checks every such file of its output directory before it rewrites
     *  any of them. */
    static std::string rows_up_to(const std::string &name,
                                  const unsigned int step);

  private:
    void cut_back(const unsigned int step) const;

    std::string   name;
    std::ofstream file;
  };
} // namespace Contact

#endif
