/* What the program does with an output directory and its checkpoint when
   they are not what the run expects (the paper's scene, h = k = 1/16 unless
   said otherwise; the program runs as a separate process):
   - a checkpoint with bytes flipped, or cut short, is refused by name;
   - a checkpoint of another problem (other Young's modulus, other friction
     bound S) with the same mesh and time step is refused, naming the
     entries that differ; a longer End time is accepted (and the longer
     run reports the report times after its checkpoint, also those that
     the shorter run met at its last step as lying beyond its end), also where
     time_series.csv was deleted (a new one starts with its header), and
     a time series damaged before the checkpoint's step is refused, naming
     the line;
   - a checkpoint of one process resumed on two says so;
   - a fresh run in a directory holding another run's results (VTU files of
     more steps, a checkpoint) says which entries differ and removes them:
     its PVD lists only its own files, and a later --resume finds no
     checkpoint of the earlier run;
   - a write that fails (a full disk, here a file size limit) names the
     file and the system's error;
   - a second run in a directory that a running one uses is refused,
     naming the first run's process, and so is a fresh run into a
     directory around it (which would remove its results);
   - a run refused in its setup (a probe point outside the body) leaves
     no directory behind where there was none. */

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "scene_files.h"

namespace fs = std::filesystem;

const std::string scene = CONTACT_PRM_DIR "/barboteu2015.prm";

// All that the last run printed.
std::string whole_output;

// Runs the program with these --set entries in `directory`; returns its
// exit status and its last line of output (the error, if it failed).
std::pair<int, std::string> run(const std::string              &directory,
                                const std::vector<std::string> &sets,
                                const std::string              &launcher = "",
                                const std::string &scene_file = scene)
{
  std::string command = launcher + CONTACT_BINARY;
  for (const std::string &set :
       std::vector<std::string>{"Geometry/Cell size=0.0625",
                                "Time/Time step=0.0625",
                                "Output/Progress interval=0",
                                "Output/Print timings=false",
                                "Output/Output directory=" + directory})
    command += " --set \"" + set + "\"";
  for (const std::string &set : sets)
    command += " --set \"" + set + "\"";
  command += " " + scene_file + " 2>&1";
  whole_output.clear();
  FILE                  *pipe = popen(command.c_str(), "r");
  std::string            last, error;
  bool                   in_error = false;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    {
      const std::string line = buffer.data();
      whole_output += line;
      const bool blank = line.find_first_not_of(" \n") == std::string::npos;
      if (!blank)
        last = line;
      // The error and the lines that continue it, of the first process
      // that reports.
      in_error =
        (in_error && !blank) || (error.empty() && line.rfind("Error", 0) == 0);
      if (in_error)
        error += line;
    }
  const int status = pclose(pipe);
  if (!error.empty())
    {
      last = error;
      // Which of several processes reports first varies (and names its
      // own checkpoint file).
      const std::size_t piece = last.find("/checkpoint.");
      if (piece != std::string::npos)
        last.replace(piece + 12, 1, "N");
      const std::size_t process = last.find(" (process ");
      if (process != std::string::npos &&
          last.find(" of ", process) < last.find(')', process))
        last.erase(process, last.find(')', process) + 1 - process);
    }
  while (!last.empty() && last.back() == '\n')
    last.pop_back();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, last};
}

void report(const std::string &what, const std::pair<int, std::string> &result)
{
  // The error of a failed run; nothing of a run that ended normally.
  const std::size_t text = result.second.find_first_not_of(' ');
  std::cout << what << ": exit " << (result.first == 0 ? "0" : "non-zero")
            << std::endl;
  if (result.first != 0 && text != std::string::npos)
    std::cout << "  " << result.second.substr(text) << std::endl;
}

// Starts a long run (the scene to t = 1000, which a test kills long before
// its end: the scene's own 141 steps take well under a second now) into
// `directory` in the background and returns once it holds the directory's
// lock and has written its parameters.
pid_t start_long_run(const std::string &directory)
{
  const pid_t pid = fork();
  if (pid == 0)
    {
      execl("/bin/sh",
            "sh",
            "-c",
            (std::string("exec ") + CONTACT_BINARY +
             " --set 'Output/Output directory=" + directory +
             "' --set 'Output/VTU interval=0' --set 'Time/End time=1000' " +
             scene + " > /dev/null 2>&1")
              .c_str(),
            nullptr);
      _exit(127);
    }
  while (!fs::exists(directory + "/.lock") ||
         fs::file_size(directory + "/.lock") == 0 ||
         !fs::exists(directory + "/parameters.prm"))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return pid;
}

// The run's result with the pid of `first` replaced by a name.
std::pair<int, std::string> without_pid(std::pair<int, std::string> result,
                                        const pid_t                 first)
{
  const std::string pid = std::to_string(first);
  const auto        at  = result.second.find(pid);
  if (at != std::string::npos)
    result.second.replace(at, pid.size(), "<pid of the first run>");
  return result;
}

void copy(const std::string &from, const std::string &to)
{
  fs::remove_all(to);
  fs::copy(from, to, fs::copy_options::recursive);
}

int main()
{
  const std::vector<std::string> checkpoint = {"Output/Checkpoint interval=6",
                                               "Output/VTU interval=6",
                                               "Time/End time=0.75"};
  fs::remove_all("original");
  report("run with a checkpoint at step 12", run("original", checkpoint));
  std::cout << "  .partial/ left: "
            << (fs::exists("original/.partial") ? "yes" : "no") << std::endl;

  // Damaged checkpoints.
  copy("original", "flipped");
  {
    std::fstream file("flipped/checkpoint",
                      std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(fs::file_size("flipped/checkpoint") / 2);
    file.write("\x55\xAA\x55\xAA\x55\xAA\x55\xAA", 8);
  }
  report("8 bytes flipped", run("flipped", {"Output/Resume=true"}));
  copy("original", "truncated");
  fs::resize_file("truncated/checkpoint",
                  fs::file_size("truncated/checkpoint") - 100);
  report("100 bytes cut off", run("truncated", {"Output/Resume=true"}));

  // Another problem, and a legitimate change.
  copy("original", "other");
  report("other Young's modulus and S",
         run("other",
             {"Output/Resume=true",
              "Time/End time=0.75",
              "Material/Young's modulus=3000",
              "Friction/Friction bound S=50"}));
  report("End time 1.1, not a multiple of the checkpoint's k",
         run("other", {"Output/Resume=true", "Time/End time=1.1"}));
  report("longer End time (16 steps of the same k)",
         run("other", {"Output/Resume=true", "Time/End time=1"}));
  // The run to 0.75 met the report times 0.8 and 1.1 at its last step,
  // since they lay beyond its end; the extended run has its own: 0.8 at
  // step 13 (t = 0.8125) and 1.1 at its last step, 16.
  std::cout << "  its VTU records after t = 0.75:";
  {
    std::ifstream pvd("other/solution.pvd");
    for (std::string line; std::getline(pvd, line);)
      {
        const std::size_t at = line.find("timestep=\"");
        if (at != std::string::npos)
          {
            const double t = std::stod(line.substr(at + 10));
            if (t > 0.75 + 1e-9)
              std::cout << ' ' << t;
          }
      }
  }
  std::cout << std::endl;
  // k = 1.1/141, and End time 3.3 = 3 T: k = 3.3/423 differs from it in
  // the last digit, and is the same step.
  const std::vector<std::string> ragged = {"Time/Time step=0.0078125",
                                           "Output/Checkpoint interval=47"};
  run("ragged", ragged);
  std::vector<std::string> resume_ragged = ragged;
  resume_ragged.insert(resume_ragged.end(),
                       {"Output/Resume=true", "Time/End time=3.3"});
  report("k = 1.1/141 resumed to End time 3.3 (k = 3.3/423)",
         run("ragged", resume_ragged));
  copy("original", "no_series");
  fs::remove("no_series/time_series.csv");
  report("resume after time_series.csv was deleted",
         run("no_series", {"Output/Resume=true", "Time/End time=1"}));
  std::ifstream series("no_series/time_series.csv");
  std::string   header;
  std::getline(series, header);
  unsigned int rows = 0;
  for (std::string row; std::getline(series, row);)
    ++rows;
  std::cout << "  time_series.csv: header "
            << (header.rfind("step,time", 0) == 0 ? "yes" : "no") << ", rows "
            << rows << " (steps 13 to 16)" << std::endl;
  // VTU files of a step before the checkpoint deleted (to save space):
  // the resumed run's PVD lists only the records whose files are there,
  // and the run says which it dropped.
  copy("original", "no_vtu");
  fs::remove("no_vtu/solution_00006.pvtu");
  fs::remove("no_vtu/solution_00006.0.vtu");
  report("resume after the VTU files of step 6 were deleted",
         run("no_vtu", {"Output/Resume=true", "Time/End time=1"}));
  {
    std::ifstream     pvd("no_vtu/solution.pvd");
    std::string       records((std::istreambuf_iterator<char>(pvd)),
                        std::istreambuf_iterator<char>());
    const std::size_t warning = whole_output.find("Warning: ");
    std::cout << "  PVD lists step 6: "
              << (records.find("solution_00006") != std::string::npos ? "yes" :
                                                                        "no")
              << ", step 12: "
              << (records.find("solution_00012") != std::string::npos ? "yes" :
                                                                        "no")
              << std::endl
              << "  "
              << (warning == std::string::npos ?
                    "(no warning)\n" :
                    whole_output.substr(warning,
                                        whole_output.find('\n', warning) + 1 -
                                          warning));
  }

  // A mesh file whose vertex moved after the checkpoint was written: the
  // same numbers of cells and unknowns, another problem.
  copy_mesh_file_scene("moved");
  const std::vector<std::string> mesh_file_run = {
    "Geometry/Mesh refinements=1",
    "Time/Time step=0.1375",
    "Output/Checkpoint interval=4",
    "Time/End time=0.55"};
  run("moved/run", mesh_file_run, "", "moved/inclined_foundation.prm");
  {
    // Node 81, inside the body, moved by 0.01 in x.
    std::ifstream            in("moved/inclined_foundation.msh");
    std::vector<std::string> lines;
    bool                     nodes = false;
    for (std::string line; std::getline(in, line);)
      {
        nodes = (nodes || line == "$Nodes") && line != "$EndNodes";
        lines.push_back(nodes && line.rfind("81 ", 0) == 0 ?
                          "81 0.3225000000004771 0.3906250000006179 0" :
                          line);
      }
    std::ofstream out("moved/inclined_foundation.msh");
    for (const std::string &line : lines)
      out << line << '\n';
  }
  report("resume after a vertex of the mesh file moved",
         run("moved/run",
             {"Geometry/Mesh refinements=1",
              "Time/Time step=0.1375",
              "Output/Resume=true",
              "Time/End time=1.1"},
             "",
             "moved/inclined_foundation.prm"));

  // A time series damaged before the checkpoint's step (its line 4, the
  // row of step 2, blank or without its step): refused, naming the line,
  // before the file is touched.
  for (const auto &[what, damage] :
       std::vector<std::pair<std::string, std::string>>{
         {"a blank line", ""}, {"a row without its step", "x,0"}})
    {
      copy("original", "damaged");
      std::vector<std::string> lines;
      {
        std::ifstream in("damaged/time_series.csv");
        for (std::string line; std::getline(in, line);)
          lines.push_back(line);
      }
      lines[3] = damage;
      {
        std::ofstream out("damaged/time_series.csv");
        for (const std::string &line : lines)
          out << line << '\n';
      }
      const auto size         = fs::file_size("damaged/time_series.csv");
      const auto history_size = fs::file_size("damaged/gamma3_history.csv");
      report("resume with " + what + " in time_series.csv",
             run("damaged", {"Output/Resume=true", "Time/End time=1"}));
      std::cout << "  time_series.csv unchanged: "
                << (fs::file_size("damaged/time_series.csv") == size ? "yes" :
                                                                       "no")
                << ", gamma3_history.csv unchanged: "
                << (fs::file_size("damaged/gamma3_history.csv") ==
                        history_size ?
                      "yes" :
                      "no")
                << ", time_series.csv.tmp left: "
                << (fs::exists("damaged/time_series.csv.tmp") ? "yes" : "no")
                << std::endl;
    }
  // (Both processes report; their lines may interleave, so only the
  // point of the message is printed.)
  copy("original", "two");
  const auto two = run("two",
                       {"Output/Resume=true", "Time/End time=0.75"},
                       "mpirun --allow-run-as-root --oversubscribe -np 2 ");
  std::cout << "one process's checkpoint on two: exit "
            << (two.first == 0 ? "0" : "non-zero") << ", says it was written "
            << "by 1 process: "
            << (whole_output.find("written by 1 process") != std::string::npos ?
                  "yes" :
                  "no")
            << std::endl;

  // A fresh run where another one left its results.
  copy("original", "reused");
  for (const std::string name : {"solution_notes.txt", "checkpoint.bak"})
    std::ofstream("reused/" + name) << "a user's file\n";
  report("fresh run of 4 steps in a directory of a 12-step run",
         run("reused", {"Time/End time=0.25", "Output/VTU interval=2"}));
  // It says what it replaces.
  const std::size_t replacing = whole_output.find("Replacing");
  std::cout << "  "
            << (replacing == std::string::npos ?
                  "(says nothing of the earlier run)\n" :
                  whole_output.substr(replacing,
                                      whole_output.find('\n', replacing) + 1 -
                                        replacing));
  unsigned int vtu = 0;
  for (const auto &entry : fs::directory_iterator("reused"))
    vtu += (entry.path().extension() == ".pvtu");
  std::ifstream pvd("reused/solution.pvd");
  std::string   records((std::istreambuf_iterator<char>(pvd)),
                      std::istreambuf_iterator<char>());
  std::cout << "  VTU records left: " << vtu << ", checkpoint left: "
            << (fs::exists("reused/checkpoint") ? "yes" : "no")
            << ", PVD lists step 12: "
            << (records.find("00012") != std::string::npos ? "yes" : "no")
            << ", the user's solution_notes.txt and checkpoint.bak kept: "
            << (fs::exists("reused/solution_notes.txt") &&
                    fs::exists("reused/checkpoint.bak") ?
                  "yes" :
                  "no")
            << std::endl;
  report("--resume there",
         run("reused", {"Output/Resume=true", "Time/End time=0.75"}));

  // Refused after the directory was locked, before anything was written
  // into it: the directory it created goes with the lock.
  fs::remove_all("refused");
  report("probe point outside the body",
         run("refused", {"Output/Probe points=5, 5"}));
  std::cout << "  its new directory removed: "
            << (fs::exists("refused") ? "no" : "yes") << std::endl;

  // A full disk, as a file size limit (2 blocks) makes it: the first file
  // written, parameters.prm, cannot be; the message names it and the
  // system's error.
  fs::remove_all("full");
  report("file size limit (ulimit -f 2)",
         run("full", {"Output/VTU interval=1"}, "ulimit -f 2; "));

  // Two runs in one directory at once: the first one runs long enough
  // (h = k = 1/128) for the second to start while it holds the lock.
  fs::remove_all("common_output");
  pid_t first = start_long_run("common_output");
  report("second run in the directory of a running one",
         without_pid(run("common_output", {}), first));
  kill(first, SIGKILL);
  waitpid(first, nullptr, 0);

  // A run in a directory of the kind a fresh run removes ('level-2', as a
  // convergence study writes), and a fresh run into the directory around
  // it: refused before it removes anything.
  fs::remove_all("around");
  first = start_long_run("around/level-2");
  report("fresh run around the directory of a running one",
         without_pid(run("around", {}), first));
  std::cout << "  the running one's parameters.prm kept: "
            << (fs::exists("around/level-2/parameters.prm") ? "yes" : "no")
            << std::endl;
  kill(first, SIGKILL);
  waitpid(first, nullptr, 0);
}
