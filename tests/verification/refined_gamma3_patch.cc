/* A patch test of the friction on a mesh refined on part of Gamma_3: a
   free slab (no clamp) on Gamma_3 = {y = 0}, sheared so that its friction
   is at the bound a S = 10 N/m^2 everywhere (u_0 = (gamma_0 y, 0[, 0]),
   mu_L gamma_0 = 10, the side tractions of that stress) and pushed along
   Gamma_3 by the body force f_0 = (2000, 0[, 0]). The exact solution slides
   rigidly on the sheared state, u = u_0 + s(t) e_x, with constant stress,
   and its discrete velocity is w_n = n k f_0 / rho on any mesh (the scheme
   integrates a constant acceleration exactly): every node of Gamma_3 slips
   at 0.02 n and carries the friction traction 10, exactly, if and only if
   the nodal weights are those of V_h's basis (doc/algorithm.md: a hanging
   node of Gamma_3 shares its weight with the nodes it follows). Each
   scene runs on a uniform mesh and on one graded towards a point of
   Gamma_3: in 2D (faces of several sizes on Gamma_3), in 3D (hanging
   nodes on Gamma_3) and in 3D with Q2. Printed: the nodes of Gamma_3, the
   largest deviation of the slip rates from 0.02 n and of the friction
   tractions from 10 (relative), the self-checks. Last, the 3D graded run
   with the hanging nodes' shares of the weights and of the normals
   dropped (a fault of faults.h): the self-check of the friction law,
   whose weights are V_h's, must fail. The same
   on two processes. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/contact_problem.h>

#include "faults.h"
#include "sliding_slab.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

template <int dim>
void run(const std::string              &name,
         const std::vector<std::string> &settings,
         const bool                      unshared_hanging_weights = false)
{
  std::vector<std::string> all_settings = slab_settings(dim);
  all_settings.insert(all_settings.end(),
                      {"Output/VTU interval=0",
                       "Output/Progress interval=0",
                       "Output/Print timings=false",
                       "Output/Report times=",
                       "Output/Output directory=" + name});
  all_settings.insert(all_settings.end(), settings.begin(), settings.end());
  const Parameters parameters =
    read_parameters(std::string(CONTACT_PRM_DIR) +
                      (dim == 2 ? "/barboteu2015.prm" : "/barboteu2015_3d.prm"),
                    all_settings);
  Faults<dim> faults;
  faults.unshared_hanging_weights = unshared_hanging_weights;
  FaultyProblem<dim> problem(parameters, faults);
  std::ostringstream console_output;
  auto *const        console = std::cout.rdbuf(console_output.rdbuf());
  std::string        error;
  try
    {
      problem.run();
    }
  catch (const dealii::ExceptionBase &exception)
    {
      error = exception.what();
    }
  std::cout.rdbuf(console);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return;

  std::cout << name << ":\n";
  std::istringstream lines(console_output.str());
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("Mesh:", 0) == 0 || line.find("FAILED") != line.npos)
      std::cout << "  " << line << "\n";
  if (!error.empty())
    std::cout << "  ended with: "
              << (error.find("Self-check failed") != error.npos ?
                    "Self-check failed" :
                    "another error")
              << "\n";
  else
    {
      const auto [rate, traction] = slab_deviations(name, dim);
      std::cout << "  slip rates against 0.02 n: " << bound_text(rate)
                << "\n  friction tractions against 10: " << bound_text(traction)
                << "\n";
    }
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           graded_2d = {
              "Geometry/Refinement points=0.375, 0", "Geometry/Refinement radius=0.3"};
  const std::vector<std::string> graded_3d = {
    "Geometry/Refinement points=0.375, 0, 0.375",
    "Geometry/Refinement radius=0.3"};

  run<2>("uniform_2d", {"Geometry/Cell size=0.0625"});
  std::vector<std::string> settings = graded_2d;
  settings.push_back("Geometry/Cell size=0.0625");
  run<2>("graded_2d", settings);

  run<3>("uniform_3d", {"Geometry/Cell size=0.125"});
  settings = graded_3d;
  settings.push_back("Geometry/Cell size=0.125");
  run<3>("graded_3d", settings);
  settings.push_back("Geometry/Finite element degree=2");
  run<3>("graded_3d_q2", settings);

  settings = graded_3d;
  settings.push_back("Geometry/Cell size=0.125");
  run<3>("graded_3d_hanging_weights_dropped", settings, true);
}
