/* What a target leaves behind must be usable: the manufactured solution
   with stick and slip and a target of 3e-3 times the size of ||eps(u_h)||
   (as verification/target_error_manufactured, cost model unknowns times
   steps).
   - The chosen run keeps the pilots' directories next to it.
   - The parameters.prm that the target run writes is the chosen run's,
     with its error estimate and without the target: running it again must
     reproduce the chosen run (the same time_series.csv) and choose nothing.
   - With 'Accuracy/Maximum predicted time' below the chosen run's predicted
     wall time (measured cost model), the program must stop before that run,
     naming the entry, and leave no estimate of a run behind. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <parts/studies/compose_study.h>
#include <app/run.h>
#include <parts/studies/study_parameters.h>

#include "scene_files.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

namespace
{
  std::vector<std::string> target_settings(const std::string &directory)
  {
    return {"Convergence study/Levels=0",
            "Accuracy/Target error=3e-3",
            "Output/Progress interval=0",
            "Output/Print timings=false",
            "Output/Output directory=" + directory};
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string  scene = CONTACT_PRM_DIR "/manufactured_slip_front.prm";
  std::ostringstream console_output;
  auto *const        console = std::cout.rdbuf(console_output.rdbuf());

  std::vector<std::string> settings = target_settings("run-target");
  settings.push_back("Accuracy/Cost model=unknowns times steps");
  const Parameters target = read_parameters(scene, settings);
  compose_study<2>(target)->run(target, {});
  const Parameters again =
    read_parameters("run-target/parameters.prm",
                    {"Output/Output directory=run-again"});
  compose_study<2>(again)->run(again, {});

  settings = target_settings("run-limited");
  settings.push_back("Accuracy/Maximum predicted time=1e-9");
  std::string message;
  try
    {
      const Parameters limited = read_parameters(scene, settings);
      compose_study<2>(limited)->run(limited, {});
    }
  catch (const dealii::ExceptionBase &error)
    {
      std::ostringstream text;
      error.print_info(text);
      message = text.str();
    }
  std::cout.rdbuf(console);

  std::cout << "the written parameters.prm has no target: "
            << (AccuracyParameters::of(again).target_error == 0 ? "yes" : "no")
            << "; runs with its error estimate: "
            << (AccuracyParameters::of(again).estimate_error ? "yes" : "no")
            << std::endl;
  const std::string chosen = contents("run-target/time_series.csv");
  std::cout << "the chosen run keeps the pilots it was chosen by: "
            << (std::filesystem::exists(
                  "run-target/pilot-q2-h-k/parameters.prm") ?
                  "yes" :
                  "no")
            << std::endl;
  std::cout << "running it again reproduces the chosen run's "
            << "time_series.csv: "
            << (!chosen.empty() &&
                    chosen == contents("run-again/time_series.csv") ?
                  "yes" :
                  "no")
            << std::endl;
  std::cout << "a predicted time above the limit stops before the chosen "
            << "run: "
            << (message.find("'Accuracy/Maximum predicted time'") !=
                      std::string::npos &&
                    message.find("it was not run") != std::string::npos ?
                  "yes" :
                  "no: " + message)
            << "; no estimate of a run left behind: "
            << (std::filesystem::exists("run-limited/error_estimate.txt") ?
                  "no" :
                  "yes")
            << std::endl;
}
