/* doc/plot_run.py on output it cannot draw as it is: a directory without
   any output of the program, --times that are not times of the run, a
   run killed part-way (its time series cut in a row, its last states
   missing), a VTU piece cut short, one with flipped bytes, a missing piece
   of a PVTU, a damaged row of the time series, and numpy missing. Each
   must end with a message that names what is wrong (for a damaged file:
   the file; the Python or zlib error after it is not printed here, since
   its words vary between versions) and exit non-zero, except the killed
   run, which is drawn up to its last step with notes. */

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  // Runs the plot script on `directory`; prints its exit status and the
  // lines it printed other than 'wrote ...' (its notes and its error, up
  // to the name of the file it could not read).
  void plot(const std::string &what,
            const std::string &directory,
            const std::string &options     = "",
            const std::string &environment = "")
  {
    const std::string log = directory + "_plot.log";
    const int         status =
      std::system(("env -u DISPLAY MPLCONFIGDIR=matplotlib " + environment +
                   " /usr/bin/python3 " + CONTACT_DOC_DIR + "/plot_run.py " +
                   directory + " " + options + " > " + log + " 2>&1")
                    .c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::cout << what << ": exit " << (code == 0 ? "0" : "non-zero")
              << std::endl;
    std::ifstream in(log);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("wrote ", 0) != 0)
        {
          const std::size_t file = line.find("cannot read ");
          const std::size_t cut  = file == std::string::npos ?
                                     std::string::npos :
                                     line.find(": ", file);
          std::cout << "  " << line.substr(0, cut) << std::endl;
        }
  }

  void copy(const std::string &from, const std::string &to)
  {
    fs::remove_all(to);
    fs::copy(from, to, fs::copy_options::recursive);
  }

  // The first `bytes` bytes of `file`, written back.
  void cut(const std::string &file, const std::size_t bytes)
  {
    std::ifstream in(file, std::ios::binary);
    std::string   text(bytes, '\0');
    in.read(text.data(), bytes);
    std::ofstream(file, std::ios::binary) << text;
  }
} // namespace

int main()
{
  fs::remove_all("paper");
  std::system((std::string(CONTACT_BINARY) +
               " --set 'Output/Output directory=paper' --set "
               "'Geometry/Cell size=0.0625' --set 'Time/Time step=0.0625' "
               "--set 'Output/VTU interval=4' --set 'Output/Progress "
               "interval=0' " CONTACT_PRM_DIR "/barboteu2015.prm > run.log")
                .c_str());

  fs::remove_all("empty");
  fs::create_directories("empty");
  plot("a directory without output", "empty");
  plot("--times abc", "paper", "--times abc");
  plot("--times nan", "paper", "--times nan");
  plot("--times -1", "paper", "--times -1");
  plot("--times 1e9", "paper", "--times 1e9");

  // Killed after step 6: the time series cut inside the row of step 7,
  // the states after it gone.
  copy("paper", "killed");
  {
    std::ifstream            in("paper/time_series.csv");
    std::vector<std::string> rows;
    for (std::string line; std::getline(in, line);)
      rows.push_back(line);
    std::ofstream out("killed/time_series.csv");
    for (unsigned int i = 0; i <= 7; ++i)
      out << rows[i] << '\n';
    out << rows[8].substr(0, rows[8].size() / 2);
  }
  for (const std::string step : {"00008", "00012", "00013", "00016", "00018"})
    {
      fs::remove("killed/solution_" + step + ".pvtu");
      fs::remove("killed/solution_" + step + ".0.vtu");
    }
  plot("a run killed in step 7 (VTU files up to step 5)", "killed");

  copy("paper", "cut_vtu");
  cut("cut_vtu/solution_00005.0.vtu", 2000);
  plot("a VTU piece cut short", "cut_vtu");

  copy("paper", "flipped_vtu");
  {
    std::fstream file("flipped_vtu/solution_00008.0.vtu",
                      std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(fs::file_size("flipped_vtu/solution_00008.0.vtu") / 2);
    file.write("AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA", 40);
  }
  plot("a VTU piece with bytes overwritten", "flipped_vtu");

  copy("paper", "no_piece");
  fs::remove("no_piece/solution_00005.0.vtu");
  plot("a piece of a PVTU missing", "no_piece");

  copy("paper", "bad_row");
  {
    std::ifstream            in("paper/time_series.csv");
    std::vector<std::string> rows;
    for (std::string line; std::getline(in, line);)
      rows.push_back(line);
    rows[4] = "1,abc,3";
    std::ofstream out("bad_row/time_series.csv");
    for (const std::string &row : rows)
      out << row << '\n';
  }
  plot("a damaged row in time_series.csv", "bad_row");

  // numpy hidden behind a module of that name that cannot be imported.
  fs::create_directories("no_numpy/numpy");
  std::ofstream("no_numpy/numpy/__init__.py")
    << "raise ImportError(\"No module named 'numpy'\")\n";
  plot("without numpy", "paper", "", "PYTHONPATH=no_numpy");
}
