/* doc/plot_run.py draws every run: the paper's scene, a 2 x 0.5 block, the
   3D scene and a convergence study, each on a coarse grid, run by the
   program and then plotted with no display (DISPLAY unset). For each the
   test prints which PNG files the script wrote (each must start with the
   PNG signature and be more than a few kilobytes) and the figures it
   skipped, with the script's exit status. A script that fails on any of
   these outputs, writes an empty or a broken file, or stops writing a
   figure changes this output. */

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
                  const std::string &plot_directory)
{
  fs::remove_all(name);
  const int run = exit_status(
    std::string(CONTACT_BINARY) + " --set 'Output/Output directory=" + name +
    "' --set 'Output/Progress interval=0' " +
    "--set 'Output/Print timings=false' " + settings + " " CONTACT_PRM_DIR "/" +
    scene + " > " + name + ".log 2>&1");
  const int plot =
    exit_status("env -u DISPLAY MPLCONFIGDIR=matplotlib /usr/bin/python3 " +
                std::string(CONTACT_DOC_DIR) + "/plot_run.py " +
                plot_directory + " > " + name + "_plot.log 2>&1");
  std::cout << name << ": run exit " << run << ", plot exit " << plot
            << std::endl;

  std::vector<std::string> written;
  const fs::path           figures = fs::path(plot_directory) / "figures";
  if (fs::exists(figures))
    for (const auto &entry : fs::directory_iterator(figures))
      written.push_back(entry.path().filename().string() +
                        (is_png(entry.path()) ? "" : " (not a PNG)"));
  std::sort(written.begin(), written.end());
  for (const std::string &file : written)
    std::cout << "  wrote " << file << std::endl;

  std::ifstream log(name + "_plot.log");
  for (std::string line; std::getline(log, line);)
    if (line.rfind("skipped ", 0) == 0)
      std::cout << "  " << line.substr(0, line.find(':')) << std::endl;
    else if (line.rfind("wrote ", 0) != 0)
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
  run_and_plot("block",
               "barboteu2015.prm",
               coarse + "--set 'Geometry/Upper corner=2, 0.5' "
                        "--set 'Output/Report times=0.4, 0.7, 1.1'",
               "block");
  run_and_plot("three_d",
               "barboteu2015_3d.prm",
               "--set 'Geometry/Cell size=0.125' "
               "--set 'Time/Time step=0.125'",
               "three_d");
  run_and_plot("study",
               "barboteu2015_convergence.prm",
               "--set 'Convergence study/Levels=2'",
               "study");
  run_and_plot("study_level",
               "barboteu2015_convergence.prm",
               "--set 'Convergence study/Levels=2'",
               "study_level/level-2");
}
