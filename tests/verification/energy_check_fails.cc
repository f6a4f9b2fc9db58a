/* The energy identity is a check that can fail: the paper's scene at
   h = k = 1/16 runs once as it is (the identity holds, the run ends
   normally) and once with the velocity doubled behind the scheme's back
   after step 3, as a bug in the time stepping would do. The second run
   must end with the error 'Self-check failed' (a non-zero exit of the
   program), not with results presented as good. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_problem.h>
#include <run.h>

#include <iostream>
#include <sstream>
#include <string>

using namespace Contact;

void run(const bool sabotage)
{
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm",
                    {"Geometry/Cell size=0.0625",
                     "Time/Time step=0.0625",
                     "Output/VTU interval=0",
                     "Output/Progress interval=0",
                     "Output/Print timings=false",
                     "Output/Report times=",
                     std::string("Output/Output directory=") +
                       (sabotage ? "sabotaged" : "intact")});
  ContactProblem<2> problem(parameters);
  if (sabotage)
    problem.set_step_observer([](const ContactProblem<2> &p) {
      if (p.get_step_number() == 3)
        const_cast<VectorType &>(p.get_velocity()) *= 2.;
    });
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  try
    {
      problem.run();
      std::cout.rdbuf(console);
      std::cout << (sabotage ? "sabotaged" : "intact") << " run: ended normally"
                << std::endl;
    }
  catch (const dealii::ExceptionBase &error)
    {
      std::cout.rdbuf(console);
      std::ostringstream message;
      error.print_info(message);
      std::cout << (sabotage ? "sabotaged" : "intact")
                << " run: error: " << message.str() << std::endl;
    }
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run(false);
  run(true);
}
