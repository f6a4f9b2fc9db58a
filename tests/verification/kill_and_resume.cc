/* Checkpoint and restart: the paper's scene at h = k = 1/64 (71
   steps, VTU every 10 steps) runs once uninterrupted, and once with a
   checkpoint every 5 steps, killed with SIGKILL after step 36 (so after
   the checkpoint of step 35 and with rows and VTU files written beyond it),
   then continued with --resume. The resumed run must reproduce the
   uninterrupted one exactly: the same time_series.csv (12 digits, every
   step), the same VTU/PVTU/PVD files with the same contents (the fields are
   written in binary, so this is bitwise; only deal.II's time stamp line
   differs), the same time of the first slip in its summary (checkpointed
   state), and no temporary or partial file left behind.

   The same on two processes (each writes its own checkpoint file and VTU
   piece), where the whole job, mpirun and both processes, is killed at
   once, as a batch system does. There the comparison is numerical:
   MUMPS's parallel factorisation is not bitwise reproducible from run to
   run (measured: of three identical uninterrupted runs one differed in
   round-off quantities such as a friction dissipation of 1e-26 while all
   stick), so the time series must agree to 1e-10 of each column's largest
   value (the energy residual: of the largest external work), and the
   PVTU and PVD records, which are text, exactly.

   Then the same on one process on a mesh adapted in two cycles ('Mesh
   adaptation/Cycles' = 2): the resumed run builds the mesh from the
   cycles its checkpoint stores, without the pilots, and must again
   reproduce the uninterrupted run.

   Last, on a mesh adapted during the run every 7 steps ('Mesh
   adaptation/Interval' = 7): the checkpoint of step 35 is written right
   after the adaptation of that step and stores the mesh's cycles; the
   resumed run is built on that mesh and must reproduce the uninterrupted
   run, including its later adaptations.

   A run adapted every 7 steps that ends at step 63, a step after which
   its mesh would adapt, is extended with --resume to the 71 steps of the
   uninterrupted run: the adaptation that its end left out comes first,
   and the extended run must reproduce the uninterrupted one.

   Last, a checkpoint written by an earlier version of the program
   (kill_and_resume_data/format_10: the same scene stopped after step 20,
   in checkpoint format 10) is refused: the message names its format and
   the one this version reads, the run exits with an error, and the files
   of the checkpointed run are left as they were. */

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

extern char **environ;

namespace fs = std::filesystem;

// Starts the program on this many processes, in a process group of its
// own, so that killing the group kills mpirun and every process.
pid_t start(const unsigned int              processes,
            const std::string              &directory,
            const std::vector<std::string> &extra)
{
  std::vector<std::string> arguments = {CONTACT_BINARY};
  if (processes > 1)
    arguments = {"mpirun", "-np", std::to_string(processes), CONTACT_BINARY};
  for (const std::string &set : {std::string("Geometry/Cell size=0.015625"),
                                 std::string("Time/Time step=0.015625"),
                                 std::string("Output/VTU interval=10"),
                                 std::string("Output/Progress interval=0"),
                                 std::string("Output/Print timings=false"),
                                 "Output/Output directory=" + directory})
    {
      arguments.push_back("--set");
      arguments.push_back(set);
    }
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  arguments.push_back(CONTACT_PRM_DIR "/barboteu2015.prm");
  std::vector<char *> argv;
  for (std::string &argument : arguments)
    argv.push_back(argument.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // The console output goes to a log next to the output directory, which
  // the test shows when a run fails.
  const std::string log = directory + ".log";
  posix_spawn_file_actions_addopen(
    &actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = 0;
  if (posix_spawnp(
        &pid, argv[0], &actions, &attributes, argv.data(), environ) != 0)
    pid = -1;
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

int wait_for(const pid_t pid)
{
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

unsigned int count_lines(const std::string &name)
{
  std::ifstream file(name);
  return std::count(std::istreambuf_iterator<char>(file),
                    std::istreambuf_iterator<char>(),
                    '\n');
}

// The file's contents without deal.II's time stamp line.
std::string contents(const fs::path &name)
{
  std::ifstream file(name, std::ios::binary);
  std::string   text((std::istreambuf_iterator<char>(file)),
                   std::istreambuf_iterator<char>());
  const auto    stamp = text.find("generated by the deal.II library");
  if (stamp != std::string::npos)
    text.erase(stamp, text.find('\n', stamp) - stamp);
  return text;
}

std::set<std::string> output_files(const std::string &directory)
{
  std::set<std::string> names;
  for (const auto &entry : fs::directory_iterator(directory))
    {
      const std::string extension = entry.path().extension().string();
      if (extension == ".vtu" || extension == ".pvtu" || extension == ".pvd")
        names.insert(entry.path().filename().string());
    }
  return names;
}

std::vector<std::vector<double>> read_time_series(const std::string &name)
{
  std::ifstream                    file(name);
  std::string                      line;
  std::vector<std::vector<double>> rows;
  std::getline(file, line);
  while (std::getline(file, line))
    {
      std::vector<double> row;
      std::istringstream  fields(line);
      for (std::string field; std::getline(fields, field, ',');)
        row.push_back(std::stod(field));
      rows.push_back(row);
    }
  return rows;
}

// The position of a column in the header of a time series.
unsigned int column(const std::string &file_name, const std::string &name)
{
  std::ifstream file(file_name);
  std::string   header;
  unsigned int  index = 0;
  std::getline(file, header);
  std::istringstream fields(header);
  for (std::string field; std::getline(fields, field, ','); ++index)
    if (field == name)
      return index;
  throw std::runtime_error("no column '" + name + "' in " + file_name);
}

// The columns of two time series of the same shape agree to 1e-10 of each
// column's largest value; the round-off columns on their own scale: the
// energy residual on that of the external work, the other self-checks'
// columns (relative already) on 1.
bool same_time_series(const std::string &a_name, const std::string &b_name)
{
  const auto a = read_time_series(a_name), b = read_time_series(b_name);
  if (a.empty() || a.size() != b.size())
    return false;
  const unsigned int  n_columns = a[0].size();
  std::vector<double> scale(n_columns, 1e-300);
  for (const auto &row : a)
    for (unsigned int c = 0; c < n_columns; ++c)
      scale[c] = std::max(scale[c], std::abs(row[c]));
  scale[column(a_name, "algebraic_energy_residual")] =
    scale[column(a_name, "external_work")];
  for (const std::string check : {"load_power_residual",
                                  "constraint_residual",
                                  "equation_residual",
                                  "friction_law_residual",
                                  "stick_speed"})
    scale[column(a_name, check)] = 1.;
  for (unsigned int n = 0; n < a.size(); ++n)
    for (unsigned int c = 0; c < n_columns; ++c)
      if (b[n].size() != n_columns ||
          std::abs(a[n][c] - b[n][c]) > 1e-10 * scale[c])
        return false;
  return true;
}

// The processes whose parent is `parent`, from /proc. Open MPI's mpirun
// starts each rank in a process group of its own, so killing mpirun's
// group leaves the ranks running on their own for a second or two (they
// then went on writing into the output directory while the resumed run
// started, which that run refused as locked): the ranks are killed by
// their process ids as well, as a batch system kills the whole job.
// The state and the parent of a process from /proc/<pid>/stat
// ("pid (command) state ppid ...", the command may contain blanks); state
// 'X' if there is no such process.
std::pair<char, pid_t> process_state(const std::string &pid)
{
  std::ifstream stat("/proc/" + pid + "/stat");
  std::string   line;
  std::getline(stat, line);
  const auto closing = line.rfind(')');
  if (closing == std::string::npos)
    return {'X', 0};
  std::istringstream fields(line.substr(closing + 1));
  char               state = 'X';
  pid_t              ppid  = 0;
  fields >> state >> ppid;
  return {state, ppid};
}

std::vector<pid_t> children(const pid_t parent)
{
  std::vector<pid_t> result;
  for (const auto &entry : fs::directory_iterator("/proc"))
    {
      const std::string name = entry.path().filename().string();
      if (name.find_first_not_of("0123456789") == std::string::npos &&
          process_state(name).second == parent)
        result.push_back(std::stoi(name));
    }
  return result;
}

// Kills the job and every process it started, and waits until they are
// gone.
int kill_job(const pid_t job)
{
  const std::vector<pid_t> ranks = children(job);
  kill(-job, SIGKILL);
  // Each rank, and the group it leads.
  for (const pid_t rank : ranks)
    {
      kill(rank, SIGKILL);
      kill(-rank, SIGKILL);
    }
  const int status = wait_for(job);
  // Gone, or a zombie (which the container's init may never reap); at
  // most ten seconds.
  const auto deadline =
    std::chrono::steady_clock::now() + std::chrono::seconds(10);
  for (const pid_t rank : ranks)
    for (char state = 'R';
         (state = process_state(std::to_string(rank)).first) != 'X' &&
         state != 'Z' && std::chrono::steady_clock::now() < deadline;)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return status;
}

bool killed_by_sigkill(const int status)
{
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

const char *yes_no(const bool condition)
{
  return condition ? "yes" : "no";
}

// The uninterrupted run and the killed and resumed one, in directories
// named after the number of processes, compared.
void kill_and_resume(const unsigned int       processes,
                     const std::string       &name    = "",
                     std::vector<std::string> variant = {})
{
  const std::string full   = "run-full-" + std::to_string(processes) + name,
                    killed = "run-killed-" + std::to_string(processes) + name;
  const auto with_variant  = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), variant.begin(), variant.end());
    return extra;
  };
  for (const std::string &directory : {full, killed})
    {
      fs::remove_all(directory);
      fs::remove(directory + ".log");
    }
  wait_for(start(processes, full, with_variant({})));

  // A loaded machine may let the run finish before the kill comes: then it
  // is started again, at most three times.
  int kill_status = 0;
  for (unsigned int attempt = 0; attempt < 3 && !killed_by_sigkill(kill_status);
       ++attempt)
    {
      fs::remove_all(killed);
      fs::remove(killed + ".log");
      const pid_t job =
        start(processes,
              killed,
              with_variant({"--set", "Output/Checkpoint interval=5"}));
      bool still_running = true;
      // Header and steps 0 ... 36: 38 lines.
      while (still_running && count_lines(killed + "/time_series.csv") < 38)
        {
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
          still_running = (waitpid(job, &kill_status, WNOHANG) == 0);
        }
      if (still_running)
        {
          kill_status = kill_job(job);
        }
    }
  std::cout << "killed by SIGKILL mid-run: "
            << yes_no(killed_by_sigkill(kill_status)) << std::endl;

  const int resume_status = wait_for(
    start(processes,
          killed,
          with_variant({"--set", "Output/Checkpoint interval=5", "--resume"})));
  const bool resumed =
    WIFEXITED(resume_status) && WEXITSTATUS(resume_status) == 0;
  std::cout << "resumed run exited with status 0: " << yes_no(resumed)
            << std::endl;
  if (!resumed)
    std::cerr << "The resumed run ended with status " << resume_status
              << "; its console output and that of the killed run:\n"
              << contents(killed + ".log") << std::endl;

  const std::set<std::string> files = output_files(full);
  bool                        same  = (files == output_files(killed));
  if (processes == 1)
    {
      std::cout << "time_series.csv identical to the uninterrupted run: "
                << yes_no(contents(full + "/time_series.csv") ==
                          contents(killed + "/time_series.csv"))
                << std::endl;
      for (const std::string &name : files)
        same =
          same && contents(full + "/" + name) == contents(killed + "/" + name);
      std::cout << "VTU, PVTU and PVD files: " << files.size()
                << " in both, identical contents: " << yes_no(same)
                << std::endl;
    }
  else
    {
      std::cout << "time_series.csv equal to the uninterrupted run to 1e-10: "
                << yes_no(same_time_series(full + "/time_series.csv",
                                           killed + "/time_series.csv"))
                << std::endl;
      for (const std::string &name : files)
        if (fs::path(name).extension() != ".vtu")
          same = same &&
                 contents(full + "/" + name) == contents(killed + "/" + name);
      std::cout << "VTU, PVTU and PVD files: " << files.size()
                << " in both, identical PVTU and PVD records: " << yes_no(same)
                << std::endl;
    }

  bool leftovers =
    fs::exists(killed + "/.partial") && !fs::is_empty(killed + "/.partial");
  for (const auto &entry : fs::directory_iterator(killed))
    leftovers = leftovers || entry.path().extension() == ".tmp";
  std::cout << "no temporary or partial files left: " << yes_no(!leftovers)
            << std::endl;

  // The first slip is part of the checkpointed state: the resumed run's
  // summary (the last in its log, after the killed run's) must give the
  // uninterrupted run's.
  const auto last_first_slip = [](const std::string &log) {
    std::istringstream lines(contents(log));
    std::string        found;
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("First slip", 0) == 0)
        found = line;
    return found;
  };
  const std::string first_slip = last_first_slip(full + ".log");
  std::cout << "the same first slip as the uninterrupted run: "
            << yes_no(!first_slip.empty() &&
                      first_slip == last_first_slip(killed + ".log"))
            << std::endl;
}


// A finished run extended to the end of the uninterrupted run of the case
// `name` with the same `variant`, against that run.
void extend_finished_run(const std::string              &name,
                         const std::vector<std::string> &variant)
{
  const std::string extended = "run-extended-1" + name;
  fs::remove_all(extended);
  fs::remove(extended + ".log");
  std::vector<std::string> longer = variant;
  for (const std::string set : {"--set", "Output/Checkpoint interval=5"})
    longer.push_back(set);
  // 63 of the uninterrupted run's 71 steps of k = 1.1/71.
  std::vector<std::string> shorter = longer;
  for (const std::string set : {"--set", "Time/End time=0.9760563380281692"})
    shorter.push_back(set);
  const int first = wait_for(start(1, extended, shorter));
  longer.push_back("--resume");
  const int  second = wait_for(start(1, extended, longer));
  const bool exited = WIFEXITED(first) && WEXITSTATUS(first) == 0 &&
                      WIFEXITED(second) && WEXITSTATUS(second) == 0;
  std::cout << "both runs exited with status 0: " << yes_no(exited)
            << std::endl;
  if (!exited)
    std::cerr << contents(extended + ".log") << std::endl;
  std::cout << "time_series.csv identical to the uninterrupted run: "
            << yes_no(contents("run-full-1" + name + "/time_series.csv") ==
                      contents(extended + "/time_series.csv"))
            << std::endl;
}


// The checkpoint of an earlier version: refused by its format, with the
// checkpointed run's files left as they were.
void refuse_earlier_version()
{
  const std::string resumed = "run-format-10";
  fs::remove_all(resumed);
  fs::remove(resumed + ".log");
  fs::copy(CONTACT_TEST_DATA_DIR "/kill_and_resume_data/format_10", resumed);
  const std::string before = contents(resumed + "/time_series.csv");
  const int         status = wait_for(start(1, resumed, {"--resume"}));
  std::cout << "resumed run exited with an error: "
            << yes_no(WIFEXITED(status) && WEXITSTATUS(status) != 0)
            << std::endl;
  const std::string log = contents(resumed + ".log");
  std::cout << "the message names format 10 and format 12: "
            << yes_no(log.find("checkpoint of format 10") !=
                        std::string::npos &&
                      log.find("reads format 12 only") != std::string::npos)
            << std::endl;
  std::cout << "time_series.csv left as it was: "
            << yes_no(contents(resumed + "/time_series.csv") == before)
            << std::endl;
}


int main()
{
  kill_and_resume(1);
  // Open MPI refuses root without the first two; the third lets two
  // processes start on a machine with one core.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 0);
  std::cout << "On two processes (mpirun -np 2):" << std::endl;
  kill_and_resume(2);
  // The run on a mesh adapted by two pilots: --resume takes the mesh from
  // its checkpoint instead of running the pilots again.
  std::cout << "On a mesh adapted in two cycles, one process:" << std::endl;
  kill_and_resume(1, "-adapted", {"--set", "Mesh adaptation/Cycles=2"});
  const std::vector<std::string> during = {
    "--set",
    "Mesh adaptation/Interval=7",
    "--set",
    "Mesh adaptation/Max levels=1",
    "--set",
    "Mesh adaptation/Coarsen fraction=0.2"};
  std::cout << "On a mesh adapted during the run every 7 steps, one process:"
            << std::endl;
  kill_and_resume(1, "-during", during);
  std::cout << "The same, ended at step 63 (a step after which the mesh "
               "adapts) and extended to step 71:"
            << std::endl;
  extend_finished_run("-during", during);
  std::cout << "A checkpoint of format 10, written by an earlier version:"
            << std::endl;
  refuse_earlier_version();
}
