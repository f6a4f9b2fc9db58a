/* doc/plot_run.py draws every run: the paper's scene, a 2 x 0.5 block, the
   paper's scene with Q2 on a mesh adapted during the run (mesh.png shows
   cells of two sizes, each Q2 cell as one), the 3D scene, the 3D scene
   graded towards a point of Gamma_3 (faces of several sizes there), P2
   triangles, P1 tetrahedra, a run without Gamma_3, a run
   without VTU and Gamma_3 history, a convergence study and one of its
   levels, each on a coarse grid, run by the program and then plotted with
   no display (DISPLAY unset), once with the options --times, --field and
   --coordinate. For each figure the test prints what the script says it
   drew (cells, stick/slip nodes at each time, nodes above their bound,
   when slip starts, ...: numbers taken from the data the figure shows)
   and whether the file is a PNG of more than a few kilobytes; and the
   figures the script skipped, with the reason. */

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int exit_status(const std::string &command)
{
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool is_png(const fs::path &file)
{
  std::ifstream in(file, std::ios::binary);
  char          signature[8] = {};
  in.read(signature, 8);
  return std::string(signature, 8) == "\x89PNG\r\n\x1a\n" &&
         fs::file_size(file) > 4000;
}

void run_and_plot(const std::string &name,
                  const std::string &scene,
                  const std::string &settings,
                  const std::string &plot_directory,
                  const std::string &plot_options = "")
{
  fs::remove_all(name);
  const int run = exit_status(
    std::string(CONTACT_BINARY) + " --set 'Output/Output directory=" + name +
    "' --set 'Output/Progress interval=0' " +
    "--set 'Output/Print timings=false' " + settings + " " CONTACT_PRM_DIR "/" +
    scene + " > " + name + ".log 2>&1");
  const int plot = exit_status(
    "env -u DISPLAY MPLCONFIGDIR=matplotlib /usr/bin/python3 " +
    std::string(CONTACT_DOC_DIR) + "/plot_run.py " + plot_directory + " " +
    plot_options + " > " + name + "_plot.log 2>&1");
  std::cout << name << (plot_options.empty() ? "" : " (" + plot_options + ")")
            << ": run exit " << run << ", plot exit " << plot << std::endl;

  // "wrote <directory>/figures/<file>: <what it shows>"
  std::ifstream log(name + "_plot.log");
  for (std::string line; std::getline(log, line);)
    if (line.rfind("wrote ", 0) == 0)
      {
        const std::size_t colon = line.find(": ");
        const fs::path    file(line.substr(6, colon - 6));
        std::cout << "  " << file.filename().string()
                  << (is_png(file) ? "" : " (not a PNG)") << ": "
                  << line.substr(colon + 2) << std::endl;
      }
    else if (line.rfind("skipped ", 0) == 0)
      std::cout << "  " << line << std::endl;
    else
      std::cout << "  script says: " << line << std::endl;
}

int main()
{
  const std::string coarse =
    "--set 'Geometry/Cell size=0.0625' --set 'Time/Time step=0.0625' ";
  run_and_plot("paper",
               "barboteu2015.prm",
               coarse + "--set 'Output/VTU interval=4'",
               "paper");
  run_and_plot("paper_options",
               "barboteu2015.prm",
               coarse + "--set 'Output/VTU interval=4'",
               "paper_options",
               "--times 0.5,1.1 --field displacement --coordinate x");
  run_and_plot("block",
               "barboteu2015.prm",
               coarse + "--set 'Geometry/Upper corner=2, 0.5' "
                        "--set 'Output/Report times=0.4, 0.7, 1.1'",
               "block");
  run_and_plot("p2_triangles",
               "barboteu2015.prm",
               coarse + "--set 'Geometry/Cell shape=simplex' "
                        "--set 'Geometry/Finite element degree=2'",
               "p2_triangles");
  run_and_plot("adapted_during_run_q2",
               "barboteu2015.prm",
               coarse + "--set 'Geometry/Finite element degree=2' "
                        "--set 'Mesh adaptation/Interval=6' "
                        "--set 'Mesh adaptation/Coarsen fraction=0.1' "
                        "--set 'Mesh adaptation/Max levels=1' "
                        "--set 'Output/VTU interval=6'",
               "adapted_during_run_q2");
  run_and_plot("no_gamma3",
               "barboteu2015.prm",
               coarse + "--set 'Boundary conditions/Contact boundary ids='",
               "no_gamma3");
  run_and_plot("no_vtu_no_history",
               "barboteu2015.prm",
               coarse + "--set 'Output/VTU interval=0' "
                        "--set 'Output/Gamma3 history=false'",
               "no_vtu_no_history");
  const std::string coarse_3d =
    "--set 'Geometry/Cell size=0.125' --set 'Time/Time step=0.125' ";
  run_and_plot("three_d", "barboteu2015_3d.prm", coarse_3d, "three_d");
  run_and_plot("three_d_graded",
               "barboteu2015_3d.prm",
               coarse_3d + "--set 'Geometry/Refinement points=0.5, 0, 0.5' "
                           "--set 'Geometry/Refinement radius=0.3'",
               "three_d_graded");
  run_and_plot("tetrahedra",
               "barboteu2015_3d.prm",
               coarse_3d + "--set 'Geometry/Cell shape=simplex'",
               "tetrahedra");
  run_and_plot("study",
               "barboteu2015_convergence.prm",
               "--set 'Convergence study/Levels=2'",
               "study");
  run_and_plot("study_level",
               "barboteu2015_convergence.prm",
               "--set 'Convergence study/Levels=2'",
               "study_level/level-2");
}
