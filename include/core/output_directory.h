/**
 * The output directory of a run: a lock that keeps two runs out of one
 * directory, and the registry of the names of everything this program
 * writes there, so that a fresh run removes what an earlier one left
 * (output_directory.cc). Each part of the program registers the files and
 * directories it writes in its own file:
 *
 *   const ResultFiles files("time_series\\.csv(\\.tmp)?");
 */
#ifndef contact_output_directory_h
#define contact_output_directory_h

#include <mpi.h>

#include <memory>
#include <string>

namespace Contact
{
  /** Registers a regular expression for the names of files that a part of
   *  the program writes into an output directory (a static object of its
   *  file). */
  struct ResultFiles
  {
    explicit ResultFiles(const std::string &pattern);
  };

  /** The same for the directories of runs that a driver starts inside the
   *  output directory; those of a target's pilots (`pilots`) are kept by
   *  the run the target chose. A directory is removed only if it holds the
   *  parameters.prm that every run writes (a user's own 'level-1' folder
   *  is not one). */
  struct ResultDirectories
  {
    ResultDirectories(const std::string &pattern, const bool pilots = false);
  };

  /** Creates `directory` and locks it for this process while the returned
   *  handle lives (collective; throws, naming the holder, when another
   *  process has it). The kernel releases the lock however the process
   *  ends. */
  std::shared_ptr<const int> lock_output_directory(const std::string &directory,
                                                   const MPI_Comm communicator);

  /** Removes what earlier runs left in `directory`: the registered files
   *  and directories (unless `keep_pilots`, also the pilots'), and the
   *  unfinished output in .partial/; other files stay. On the first
   *  process. */
  void remove_results(const std::string &directory,
                      const bool         keep_pilots,
                      const MPI_Comm     communicator);
} // namespace Contact

#endif
