/* Every self-check of a run can fail: the paper's scene at h = k = 1/16
   runs once as it is and once with each error that a self-check is there
   to catch:
     - the velocity doubled behind the scheme's back after step 3, as a bug
       in the time stepping would do (through the step observer),
   and, injected through the the faults of faults.h,
     - the friction force applied (and reported) with the wrong sign,
     - the friction coefficient 10% too large in the solver, also with a
       loose 'Solver/Convexification tolerance' (1e-2), whose allowance in
       the check of the law stops at 1e-3 of max g(0),
     - the load vector 10% too large in the time stepping,
     - the stiffness matrix B 1% too large in the assembly,
     - a velocity off the constraints of V_h (a node of Gamma_3 given a
       normal velocity of 1e-3 of max |w_n| after the step).
   Each run must end with 'Self-check failed' (a non-zero exit of the
   program), naming the check that caught the error: the doubled velocity
   by the energy identity of its step, the sign by the friction law, the
   sticking nodes' rest and the decreasing friction dissipation, the
   coefficient by the friction law, the load by the load vector against
   the loads' integral, the stiffness by the matrices against their forms,
   the velocity off the constraints by the constraints' check. The energy
   identity misses all but the doubled velocity (and the velocity off the
   constraints, which the step did not solve for): each step still solves
   its own linear system.
   The bushing of prm/bushing.prm (8 x 4 cells, k = 1/16), where the rigid
   rotation about the axis lies in V_h and the balance of moments about it
   is a self-check too, runs as it is, with the doubled velocity and with
   the 10% larger load: the balance of moments catches both. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <app/run.h>

#include "faults.h"

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

void run(const std::string &name,
         const Faults<2>   &faults,
         const bool         double_velocity_after_step_3 = false,
         const std::string &scene                        = "barboteu2015.prm",
         const std::string &refinement = "Geometry/Cell size=0.0625",
         const std::vector<std::string> &more_settings = {})
{
  std::vector<std::string> settings = {refinement,
                                       "Time/Time step=0.0625",
                                       "Output/VTU interval=0",
                                       "Output/Progress interval=0",
                                       "Output/Print timings=false",
                                       "Output/Report times=",
                                       "Output/Output directory=" + name};
  settings.insert(settings.end(), more_settings.begin(), more_settings.end());
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/" + scene, settings);
  FaultyProblem<2> problem(parameters, faults);
  if (double_velocity_after_step_3)
    problem.add_postprocessor(
      std::make_unique<StepObserver<2>>([](const ContactProblem<2> &p) {
        if (p.get_step_number() == 3)
          const_cast<VectorType &>(p.get_velocity()) *= 2.;
      }));
  std::ostringstream console_output;
  auto *const        console = std::cout.rdbuf(console_output.rdbuf());
  try
    {
      problem.run();
      std::cout.rdbuf(console);
      std::cout << name << ": ended normally" << std::endl;
    }
  catch (const dealii::ExceptionBase &error)
    {
      std::cout.rdbuf(console);
      std::ostringstream message;
      error.print_info(message);
      std::cout << name << ": " << message.str() << std::endl;
    }
  // The summary's lines of the checks, each with its largest value.
  std::istringstream lines(console_output.str());
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("  ", 0) == 0 && line.find(": ") != std::string::npos)
      std::cout << line << std::endl;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run("intact", {});
  run("velocity_doubled", {}, true);

  Faults<2> reversed;
  reversed.reversed_friction_force = true;
  run("reversed_friction_force", reversed);

  Faults<2> larger_coefficient;
  larger_coefficient.bound_factor = [](const dealii::Point<2> &) {
    return 1.1;
  };
  run("friction_coefficient_times_1.1", larger_coefficient);
  run("friction_coefficient_times_1.1_loose_tolerance",
      larger_coefficient,
      false,
      "barboteu2015.prm",
      "Geometry/Cell size=0.0625",
      {"Solver/Friction method=convexification",
       "Solver/Convexification tolerance=0.01"});

  Faults<2> stiffer;
  stiffer.stiffness_factor = 1.01;
  run("stiffness_matrix_times_1.01", stiffer);

  Faults<2> off_constraints;
  off_constraints.normal_velocity = 1e-3;
  run("velocity_off_the_constraints", off_constraints);

  Faults<2> larger_load;
  larger_load.load_factor = 1.1;
  run("load_times_1.1", larger_load);

  const std::string bushing = "bushing.prm",
                    cells   = "Geometry/Mesh refinements=1";
  run("bushing_intact", {}, false, bushing, cells);
  run("bushing_velocity_doubled", {}, true, bushing, cells);
  run("bushing_load_times_1.1", larger_load, false, bushing, cells);
}
