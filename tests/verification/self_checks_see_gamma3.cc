/* The self-checks see errors in the contact itself: each run injects one
   error in the friction solver's map of Gamma_3 or in its compliance
   through the faults of faults.h, and must end with 'Self-check
   failed', naming the checks that caught it (the summary's lines marked
   FAILED):
     - D times 1.5 on the Delassus path (a wrong compliance of Gamma_3): the
       solver's slip velocities are not those of the stored w_n, so the
       friction law or the sticking nodes' rest fails at the stored
       velocities;
     - the same on the constraints path (every solve's solution times 1.5):
       w_n is not the solution of the step's equations, so (5.2) from the
       stored fields fails;
     - the nodes' weights m_p times 1.1: the law with the checks' own
       weights fails;
     - the first tangent of the middle node of Gamma_3 turned towards its
       normal by 5 degrees: the force and velocity in the tangent plane of
       the checks' own normal break the law there;
     - the first sticking node moved by 1e-3 of max |w_n| after each step:
       the sticking nodes' rest, and (5.2);
   on the paper's scene (h = k = 1/16), on it with a = b = 1 (a rate
   independent law), on the constant friction scene, and on the bushing of
   prm/bushing.prm with a = b (8 x 4 cells, k = 1/16, Q2 on a curved
   Gamma_3). Each scene also runs intact. Last, the Delassus operator of
   the old k kept after a step cut, on the scene of
   tests/scenes/step_cut_incompressible (a cut in step 5): the law at the
   stored velocities fails from the cut on. On two processes (the Delassus
   operator then from solves with MUMPS) every error is caught by the same
   checks. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/contact_problem.h>

#include "faults.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

template <int dim>
void run(const std::string              &name,
         const std::string              &scene,
         const std::vector<std::string> &settings,
         const Faults<dim>              &faults)
{
  std::vector<std::string> all_settings = {"Output/VTU interval=0",
                                           "Output/Progress interval=0",
                                           "Output/Print timings=false",
                                           "Output/Report times=",
                                           "Output/Output directory=" + name};
  all_settings.insert(all_settings.end(), settings.begin(), settings.end());
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/" + scene, all_settings);
  FaultyProblem<dim> problem(parameters, faults);
  std::ostringstream console_output;
  auto *const        console = std::cout.rdbuf(console_output.rdbuf());
  std::string        outcome = "ended normally";
  try
    {
      problem.run();
    }
  catch (const dealii::ExceptionBase &error)
    {
      std::ostringstream message;
      error.print_info(message);
      outcome = message.str().find("Self-check failed") != std::string::npos ?
                  "self-check failed" :
                  "stopped: " + message.str();
    }
  std::cout.rdbuf(console);
  // Every process knows the outcome; the first one prints it (the summary
  // comes from it alone).
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << name << ": " << outcome << std::endl;
  // The summary's lines of the checks that failed.
  std::istringstream lines(console_output.str());
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("  ", 0) == 0 && line.find("FAILED") != std::string::npos)
      std::cout << "  " << line.substr(2, line.find(':') - 2) << std::endl;
}


template <int dim>
void run_all_errors(const std::string              &label,
                    const std::string              &scene,
                    const std::vector<std::string> &settings)
{
  run<dim>(label + "_intact", scene, settings, {});

  for (const std::string path : {"Delassus", "constraints"})
    {
      Faults<dim> compliance;
      compliance.compliance_factor = 1.5;
      std::vector<std::string> on_path(settings);
      on_path.push_back("Solver/Contact solver=" + path);
      run<dim>(label + "_compliance_times_1.5_" + path,
               scene,
               on_path,
               compliance);
    }

  Faults<dim> weights;
  weights.weight_factor = 1.1;
  run<dim>(label + "_weights_times_1.1", scene, settings, weights);

  Faults<dim> tangent;
  tangent.tangent_turn = 5. * M_PI / 180.;
  run<dim>(label + "_tangent_turned_5_degrees", scene, settings, tangent);

  Faults<dim> moving;
  moving.stick_node_velocity = 1e-3;
  run<dim>(label + "_sticking_node_moving", scene, settings, moving);
}


int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           paper = {"Geometry/Cell size=0.0625",
                                                    "Time/Time step=0.0625"};
  run_all_errors<2>("paper", "barboteu2015.prm", paper);

  std::vector<std::string> rate_independent(paper);
  rate_independent.push_back("Friction/b=1");
  run_all_errors<2>("a_equals_b", "barboteu2015.prm", rate_independent);

  run_all_errors<2>("constant_friction", "constant_friction.prm", paper);

  run_all_errors<2>("bushing_a_equals_b",
                    "bushing.prm",
                    {"Geometry/Mesh refinements=1",
                     "Time/Time step=0.0625",
                     "Friction/b=1"});

  Faults<2> stale;
  stale.stale_delassus_after_step_cut     = true;
  const std::vector<std::string> step_cut = {"Geometry/Cell size=0.0625",
                                             "Time/Time step=0.0625",
                                             "Material/Poisson ratio=0.4999",
                                             "Solver/Max active set "
                                             "iterations=100",
                                             "Solver/Step cuts=3"};
  run<2>("step_cut_intact", "barboteu2015.prm", step_cut, {});
  run<2>("step_cut_stale_delassus", "barboteu2015.prm", step_cut, stale);
}
