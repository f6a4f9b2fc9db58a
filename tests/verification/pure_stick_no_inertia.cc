/* pure_stick (tests/scenes) with a thousand times less inertia
   (rho = 1e-9): the body is held against rigid sliding by the friction
   alone, K is close to singular and the tangential velocity of the
   sticking nodes is the solve's round-off amplified to about 1e-7 of the
   friction force's scale. The self-checks must not take that for a
   violated friction law (a sticking node is checked by |eta| <= g, its
   velocity is not the law's business), and the results are those of
   pure_stick. The friction dissipation, sum k eta . C w over sticking
   nodes, is that amplified round-off (its digits depend on the BLAS
   kernel): it is printed as a bound, relative to the external work. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/contact_problem.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

// The last row of a CSV file, by column name.
std::map<std::string, double> last_row(const std::string &name)
{
  std::ifstream            file(name);
  std::string              header, line, last;
  std::vector<std::string> columns;
  std::getline(file, header);
  while (std::getline(file, line))
    if (!line.empty())
      last = line;
  std::map<std::string, double> row;
  std::istringstream            names(header), values(last);
  for (std::string column, value;
       std::getline(names, column, ',') && std::getline(values, value, ',');)
    row[column] = std::stod(value);
  return row;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Parameters                         parameters =
    read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm",
                    {"Geometry/Cell size=0.0625",
                     "Boundary conditions/Clamped boundary ids=",
                     "Boundary conditions/Tractions=",
                     "Material/Density=1e-9",
                     "Loads and initial values/Body force=2000; 0",
                     "Friction/Friction law=constant",
                     "Friction/Friction bound S=10000",
                     "Friction/a=1",
                     "Time/End time=0.2",
                     "Time/Time step=0.01",
                     "Output/Output directory=run-pure_stick_no_inertia",
                     "Output/VTU interval=0",
                     "Output/Progress interval=0",
                     "Output/Print timings=false"});
  ContactProblem<2>  problem(parameters);
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  std::string        outcome = "yes";
  try
    {
      problem.run();
    }
  catch (const dealii::ExceptionBase &)
    {
      outcome = "no";
    }
  std::cout.rdbuf(console);

  auto         row  = last_row("run-pure_stick_no_inertia/time_series.csv");
  const double work = row["external_work"];
  std::cout << "run ended with every self-check passed: " << outcome
            << "\nat T: " << row["n_stick"] << " stick, " << row["n_slip"]
            << " slip; friction force " << std::setprecision(6)
            << row["friction_force"] << "\nelastic energy "
            << row["elastic_energy"] << ", external work " << work
            << ", viscous " << row["viscous_dissipation"] << ", numerical "
            << row["numerical_dissipation"]
            << "\n|friction dissipation| below 1e-6 of the external work: "
            << (std::abs(row["friction_dissipation"]) < 1e-6 * work ? "yes" :
                                                                      "no")
            << std::endl;
}
