/* The output directory: its lock, and the registry of the names of what
   the program writes there. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <core/parameters.h>
#include <core/output_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

namespace Contact
{
  using namespace dealii;

  namespace
  {
    // The output directory, created, and locked with flock() on its file
    // '.lock' (which then holds the pid): the kernel releases the lock when
    // the process ends, however it ends. Returns the reason on failure.
    std::string flock_output_directory(const std::string          &directory,
                                       const bool                  created,
                                       std::shared_ptr<const int> &lock)
    {
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      if (error)
        return "Cannot create the directory '" + directory +
               "' of the entry '" + Entry::output_directory +
               "': " + error.message();
      const std::string name = directory + "/.lock";
      const int         fd   = open(name.c_str(), O_RDWR | O_CREAT, 0644);
      if (fd < 0)
        return "Cannot create '" + name + "': " + std::strerror(errno);
      if (flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          if (errno != EWOULDBLOCK)
            {
              // A file system without flock (some parallel or network
              // ones): the run goes on unlocked.
              close(fd);
              return "";
            }
          std::ifstream holder(name);
          std::string   pid;
          std::getline(holder, pid);
          close(fd);
          return "The output directory '" + directory +
                 "' is in use by another run (process " +
                 (pid.empty() ? std::string("unknown") : pid) +
                 "). Wait for it to end, or give this run another "
                 "'" +
                 Entry::output_directory + "'.";
        }
      const std::string pid = std::to_string(getpid()) + "\n";
      if (ftruncate(fd, 0) != 0 || write(fd, pid.data(), pid.size()) < 0)
        {
          close(fd);
          return "Cannot write '" + name + "': " + std::strerror(errno);
        }
      // A directory this lock created and nothing but the lock went into
      // (a run refused in its setup) is removed with the lock, while it is
      // still held.
      lock = std::shared_ptr<const int>(
        new int(fd), [directory, name, created](const int *owned) {
          std::error_code listing_error;
          if (created)
            {
              unsigned int entries = 0;
              for (const auto &entry :
                   std::filesystem::directory_iterator(directory,
                                                       listing_error))
                entries += (entry.path().filename() == ".lock" ? 0 : 1);
              if (!listing_error && entries == 0)
                {
                  std::filesystem::remove(name, listing_error);
                  std::filesystem::remove(directory, listing_error);
                }
            }
          close(*owned);
          delete owned;
        });
      return "";
    }

    // The registered names of files and of run directories (pilots
    // apart), as alternatives of one regular expression each.
    struct Registry
    {
      std::string files, directories, pilots;
    };

    Registry &registry()
    {
      static Registry names;
      return names;
    }

    void add_alternative(std::string &alternatives, const std::string &pattern)
    {
      alternatives += (alternatives.empty() ? "" : "|") + pattern;
    }

    // The locks this process holds, by the canonical path of their
    // directory.
    std::map<std::string, std::weak_ptr<const int>> &held_locks()
    {
      static std::map<std::string, std::weak_ptr<const int>> held;
      return held;
    }

    std::string canonical_key(const std::filesystem::path &directory)
    {
      std::error_code error;
      return std::filesystem::weakly_canonical(
               std::filesystem::absolute(directory), error)
        .string();
    }

    // The first directory in or below `directory` whose lock another
    // process holds, with that process's pid; empty if there is none.
    std::pair<std::string, std::string>
    locked_by_another_run(const std::filesystem::path &directory)
    {
      std::error_code error;
      for (auto entry =
             std::filesystem::recursive_directory_iterator(directory, error);
           !error && entry != std::filesystem::recursive_directory_iterator();
           entry.increment(error))
        {
          if (entry->path().filename() != ".lock")
            continue;
          const std::filesystem::path owner = entry->path().parent_path();
          if (held_locks()[canonical_key(owner)].lock())
            continue;
          // (Read-write: where flock is emulated by POSIX locks, as on NFS,
          // an exclusive lock needs a descriptor open for writing.)
          const int fd = open(entry->path().c_str(), O_RDWR);
          if (fd < 0)
            continue;
          const bool free = flock(fd, LOCK_EX | LOCK_NB) == 0;
          close(fd);
          if (!free && errno == EWOULDBLOCK)
            {
              std::ifstream holder(entry->path());
              std::string   pid;
              std::getline(holder, pid);
              return {owner.string(), pid.empty() ? "unknown" : pid};
            }
        }
      return {};
    }
  } // namespace


  // A directory this process holds already is shared rather than locked
  // again (flock would refuse a second descriptor of the same process): an
  // error estimate's or a target's runs write under the lock of the run
  // that contains them.
  std::shared_ptr<const int> lock_output_directory(const std::string &directory,
                                                   const MPI_Comm communicator)
  {
    auto                      &held = held_locks();
    std::shared_ptr<const int> lock;
    std::string                failure;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        // The key of a directory that exists: 'out/' and 'out' alike.
        std::error_code error;
        const bool      created = !std::filesystem::exists(directory, error);
        std::filesystem::create_directories(directory, error);
        const std::string key = canonical_key(directory);
        lock                  = held[key].lock();
        if (!lock)
          {
            failure   = flock_output_directory(directory, created, lock);
            held[key] = lock;
          }
      }
    failure = Utilities::MPI::broadcast(communicator, failure, 0);
    AssertThrow(failure.empty(), ExcMessage(failure));
    return lock;
  }


  void remove_results(const std::string &directory,
                      const bool         keep_pilots,
                      const MPI_Comm     communicator)
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const std::regex files(registry().files),
      directories(registry().directories), pilots(registry().pilots);
    std::error_code                    error;
    std::vector<std::filesystem::path> removed;
    for (const auto &entry :
         std::filesystem::directory_iterator(directory, error))
      {
        const std::string name = entry.path().filename().string();
        const bool        run_directory =
          entry.is_directory() &&
          std::filesystem::exists(entry.path() / "parameters.prm") &&
          (std::regex_match(name, directories) ||
           (!keep_pilots && std::regex_match(name, pilots)));
        if ((entry.is_regular_file() && std::regex_match(name, files)) ||
            run_directory)
          removed.push_back(entry.path());
        // A run still writing into one of them keeps it, and this run
        // stops before it has removed anything.
        if (run_directory)
          {
            const auto [owner, pid] = locked_by_another_run(entry.path());
            AssertThrow(owner.empty(),
                        ExcMessage(
                          "The output directory '" + directory + "' holds '" +
                          owner + "', which another run is using (process " +
                          pid +
                          "): a fresh run here would remove its results. "
                          "Wait for it to end, or give this run another '" +
                          Entry::output_directory + "'."));
          }
      }
    for (const std::filesystem::path &path : removed)
      std::filesystem::remove_all(path, error);
    std::filesystem::remove_all(directory + "/.partial", error);
  }



  ResultFiles::ResultFiles(const std::string &pattern)
  {
    add_alternative(registry().files, pattern);
  }


  ResultDirectories::ResultDirectories(const std::string &pattern,
                                       const bool         pilots)
  {
    add_alternative(pilots ? registry().pilots : registry().directories,
                    pattern);
  }
} // namespace Contact
