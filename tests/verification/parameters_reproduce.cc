/* The parameters.prm that a run writes into its output directory must run
   it again, from there, in every mode (the target's chosen run:
   verification/target_error_reproduce). Each run below is small (h = 1/16
   or a mesh file refined once, 8 to 16 steps) and runs again from its
   parameters.prm into another directory:
   - a scene read through a relative path whose mesh file is relative to it
     (the written mesh file must not depend on the working directory);
   - a run with its error estimate (the same error_estimate.txt);
   - a convergence study (the study's own parameters.prm; the same table
     without its wall times);
   - a run resumed from its checkpoint with a later End time (run again, it
     must compute the whole run, not resume, and give the same
     time_series.csv).
   Each parameters.prm begins with a comment that names the program's
   version and the date it was written. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>

#include "scene_files.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  // The table of convergence.txt without its last column, the wall times.
  std::string without_wall_times(const std::string &table)
  {
    std::istringstream lines(table);
    std::string        result;
    for (std::string line; std::getline(lines, line);)
      result += line.substr(0, line.rfind('|', line.size() - 3)) + '\n';
    return result;
  }

  // Runs the program as the command line does; the error's text, or empty.
  std::string run(const std::vector<std::string> &arguments)
  {
    std::vector<const char *> argv = {"contact"};
    for (const std::string &argument : arguments)
      argv.push_back(argument.c_str());
    try
      {
        Contact::run_from_command_line(argv.size(), argv.data());
      }
    catch (const dealii::ExceptionBase &error)
      {
        std::ostringstream text;
        error.print_info(text);
        return text.str();
      }
    return "";
  }

  const std::vector<std::string> small = {"--set",
                                          "Output/VTU interval=0",
                                          "--set",
                                          "Output/Progress interval=0",
                                          "--set",
                                          "Output/Print timings=false"};

  // Runs `scene` with `sets` into `directory`, then its parameters.prm
  // into `directory`-again; whether `file` is the same in both.
  std::string reproduces(const std::string              &scene,
                         const std::vector<std::string> &sets,
                         const std::string              &directory,
                         const std::string              &file)
  {
    std::vector<std::string> arguments = small;
    arguments.insert(arguments.end(), sets.begin(), sets.end());
    arguments.insert(arguments.end(),
                     {"--set", "Output/Output directory=" + directory, scene});
    std::string error = run(arguments);
    if (!error.empty())
      return "the first run failed: " + error;
    error = run({"--set",
                 "Output/Output directory=" + directory + "-again",
                 directory + "/parameters.prm"});
    if (!error.empty())
      return "no: " + error;
    std::string first  = contents(directory + "/" + file),
                second = contents(directory + "-again/" + file);
    if (file == "convergence.txt")
      {
        first  = without_wall_times(first);
        second = without_wall_times(second);
      }
    return !first.empty() && first == second ? "yes" : "no";
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostringstream                       console_output;
  auto *const console = std::cout.rdbuf(console_output.rdbuf());

  // A scene and its mesh file in a folder of their own, read through a
  // relative path.
  copy_mesh_file_scene("scene");
  const std::string mesh_file = reproduces(
    "scene/inclined_foundation.prm",
    {"--set", "Geometry/Mesh refinements=1", "--set", "Time/Time step=0.1375"},
    "run-mesh-file",
    "time_series.csv");

  // The same mesh file given with --set, relative to the working
  // directory.
  const std::string mesh_file_set =
    reproduces("scene/inclined_foundation.prm",
               {"--set",
                "Geometry/Mesh file=scene/inclined_foundation.msh",
                "--set",
                "Geometry/Mesh refinements=1",
                "--set",
                "Time/Time step=0.1375"},
               "run-mesh-file-set",
               "time_series.csv");

  const std::string              paper  = CONTACT_PRM_DIR "/barboteu2015.prm";
  const std::vector<std::string> coarse = {"--set",
                                           "Geometry/Cell size=0.0625",
                                           "--set",
                                           "Time/Time step=0.0625"};
  std::vector<std::string>       sets   = coarse;
  sets.insert(sets.end(), {"--set", "Accuracy/Estimate error=true"});
  const std::string estimate =
    reproduces(paper, sets, "run-estimate", "error_estimate.txt");

  sets = coarse;
  sets.insert(sets.end(), {"--set", "Convergence study/Levels=1"});
  const std::string study =
    reproduces(paper, sets, "run-study", "convergence.txt");

  // Half of the run with a checkpoint, then the rest resumed.
  sets = coarse;
  sets.insert(
    sets.end(),
    {"--set", "Output/Checkpoint interval=4", "--set", "Time/End time=0.5"});
  std::vector<std::string> arguments = small;
  arguments.insert(arguments.end(), sets.begin(), sets.end());
  arguments.insert(arguments.end(),
                   {"--set", "Output/Output directory=run-resumed", paper});
  std::string resumed = run(arguments);
  if (resumed.empty())
    {
      sets = coarse;
      sets.insert(sets.end(),
                  {"--set",
                   "Output/Checkpoint interval=4",
                   "--set",
                   "Time/End time=1",
                   "--resume"});
      resumed = reproduces(paper, sets, "run-resumed", "time_series.csv");
    }
  std::cout.rdbuf(console);
  std::ifstream written("run-estimate/parameters.prm");
  std::string   first_line;
  std::getline(written, first_line);

  std::cout << "a scene with a relative mesh file, run again from its "
            << "parameters.prm, gives the same time_series.csv: " << mesh_file
            << std::endl
            << "the same with the mesh file given by --set: " << mesh_file_set
            << std::endl
            << "a run with its error estimate, run again, gives the same "
            << "error_estimate.txt: " << estimate << std::endl
            << "a convergence study, run again, gives the same table: " << study
            << std::endl
            << "a resumed run, run again, computes the whole run with the "
            << "same time_series.csv: " << resumed << std::endl
            << "parameters.prm begins with the program's version and the "
            << "date: "
            << (first_line.rfind("# Written by contact ", 0) == 0 &&
                    first_line.find(" UTC. ") != std::string::npos ?
                  "yes" :
                  "no: " + first_line)
            << std::endl;
}
