/* Every self-check of a run can fail: the paper's scene at h = k = 1/16
   runs once as it is and once with each error that a self-check is there
   to catch:
     - the velocity doubled behind the scheme's back after step 3, as a bug
       in the time stepping would do (through the step observer),
   and, injected through the test-only Sabotage hooks,
     - the friction force applied (and reported) with the wrong sign,
     - the friction coefficient 10% too large in the solver,
     - the load vector 10% too large in the time stepping.
   Each run must end with 'Self-check failed' (a non-zero exit of the
   program), naming the check that caught the error: the doubled velocity
   by both energy identities, the sign by the friction law, the sticking
   nodes' rest and the decreasing friction dissipation, the coefficient by
   the friction law,
   the load by the energy identity by quadrature. The energy identity from
   the matrices misses the last three: each step still solves its own
   linear system.
   The bushing of prm/bushing.prm (8 x 4 cells, k = 1/16), where the rigid
   rotation about the axis lies in V_h and the balance of moments about it
   is a self-check too, runs as it is, with the doubled velocity and with
   the 10% larger load: the balance of moments catches both. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <app/run.h>

#include <iostream>
#include <sstream>
#include <string>

using namespace Contact;

void run(const std::string &name,
         const Sabotage<2> &sabotage,
         const bool         double_velocity_after_step_3 = false,
         const std::string &scene                        = "barboteu2015.prm",
         const std::string &refinement = "Geometry/Cell size=0.0625")
{
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/" + scene,
                    {refinement,
                     "Time/Time step=0.0625",
                     "Output/VTU interval=0",
                     "Output/Progress interval=0",
                     "Output/Print timings=false",
                     "Output/Report times=",
                     "Output/Output directory=" + name});
  ContactProblem<2> problem(parameters, sabotage);
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

  Sabotage<2> reversed;
  reversed.reversed_friction_force = true;
  run("reversed_friction_force", reversed);

  Sabotage<2> larger_coefficient;
  larger_coefficient.bound_factor = [](const dealii::Point<2> &) {
    return 1.1;
  };
  run("friction_coefficient_times_1.1", larger_coefficient);

  Sabotage<2> larger_load;
  larger_load.load_factor = 1.1;
  run("load_times_1.1", larger_load);

  const std::string bushing = "bushing.prm",
                    cells   = "Geometry/Mesh refinements=1";
  run("bushing_intact", {}, false, bushing, cells);
  run("bushing_velocity_doubled", {}, true, bushing, cells);
  run("bushing_load_times_1.1", larger_load, false, bushing, cells);
}
