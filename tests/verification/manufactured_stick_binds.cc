/* The manufactured solution's stick zone binds: on x < 1/2 its friction
   force is xi(x) S mu(0) with 0 < xi < 1, a force strictly inside the
   bound, so that the stick condition decides the solution there. At
   h = k = 1/32 the program runs it once as it is and once with the
   friction removed on x < 1/2 (a fault of faults.h sets the bound
   to 0 there; the self-check of the friction law then fails, as it must).
   Without the stick condition the largest V-error must grow more than
   tenfold, to the order of the solution itself, ||eps(u(T))|| (more than a
   fifth of it), while with it it stays below a twentieth. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <parts/manufactured/manufactured_solution.h>
#include <app/run.h>

#include "faults.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

using namespace Contact;

Parameters scene(const std::string &directory)
{
  return read_parameters(CONTACT_PRM_DIR "/manufactured_slip_front.prm",
                         {"Geometry/Cell size=0.03125",
                          "Time/Time step=0.03125",
                          "Output/Print timings=false",
                          "Output/Output directory=" + directory});
}

// The largest V-error over the steps, from the summary line of the run.
double largest_V_error(const std::string &directory, const Faults<2> &faults)
{
  FaultyProblem<2>   problem(scene(directory), faults);
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
      outcome = message.str().substr(0, message.str().find(':'));
      while (!outcome.empty() && outcome.front() == ' ')
        outcome.erase(0, 1);
    }
  std::cout.rdbuf(console);
  std::cout << directory << ": " << outcome << std::endl;
  const std::string marker = "||eps(u - u_h)|| ";
  const std::string output = console_output.str();
  const auto        where  = output.find(marker);
  AssertThrow(where != std::string::npos, dealii::ExcInternalError());
  return std::stod(output.substr(where + marker.size()));
}

// ||eps(u(T))|| of the exact solution on [0, 1] x [0, 1/2], by a Gauss
// rule on 64 x 32 cells.
double solution_V_norm(const Parameters &parameters)
{
  const ManufacturedSolution<2> exact(parameters);
  const dealii::QGauss<1>       gauss(4);
  const unsigned int            nx = 64, ny = 32;
  double                        sum = 0;
  for (unsigned int i = 0; i < nx; ++i)
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int a = 0; a < gauss.size(); ++a)
        for (unsigned int b = 0; b < gauss.size(); ++b)
          {
            const dealii::Point<2>              p((i + gauss.point(a)[0]) / nx,
                                     0.5 * (j + gauss.point(b)[0]) / ny);
            const dealii::SymmetricTensor<2, 2> eps =
              exact.displacement_strain(p, parameters.time.end_time);
            sum +=
              (eps * eps) * gauss.weight(a) * gauss.weight(b) * 0.5 / (nx * ny);
          }
  return std::sqrt(sum);
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double with_stick = largest_V_error("with_stick", {});
  Faults<2>    no_stick;
  no_stick.bound_factor = [](const dealii::Point<2> &p) {
    return p[0] < 0.5 ? 0. : 1.;
  };
  const double without_stick = largest_V_error("without_stick", no_stick);
  const double norm          = solution_V_norm(scene("unused"));
  std::cout << std::setprecision(3)
            << "largest V-error with the stick condition: " << with_stick
            << "\nlargest V-error without it on x < 1/2:   " << without_stick
            << "\n||eps(u(T))|| of the exact solution:      " << norm
            << "\nerror without the stick condition > 10 x error with it: "
            << (without_stick > 10 * with_stick ? "yes" : "no")
            << "\nerror without the stick condition > ||eps(u(T))|| / 5: "
            << (without_stick > 0.2 * norm ? "yes" : "no")
            << "\nerror with it < ||eps(u(T))|| / 20: "
            << (with_stick < 0.05 * norm ? "yes" : "no") << std::endl;
}
