/* The move of a run to a mesh adapted during it (ContactProblem::
   adapt_mesh_during_run(), 'Mesh adaptation/Interval'), with the cells
   chosen here instead of by the indicators: after every step (every third
   on the paper's scene), alternately the cells near one point of Gamma_3
   are refined, and the refined cells are coarsened back while those near
   another point are refined, so that Gamma_3 gets and loses hanging nodes
   and cells are both refined and coarsened.

   - The sliding slab of refined_gamma3_patch (2D, and 3D with hanging
     nodes on Gamma_3): its exact solution, u = u_0 + s(t) e_x with u_0
     linear, is in V_h of every mesh, so the transfers must be exact (the
     summary's mesh transfers at round-off) and every node of Gamma_3 must
     slip at the exact rate 0.02 n with the exact friction traction 10 on
     every mesh.
   - The paper's scene (2D, h = k = 1/16): the transfers change the energy
     (a coarsened cell keeps its children's values at its nodes only), the
     change is booked as its own term, and every self-check passes on
     every mesh, the energy identity of the step after each change
     included.
   - The same with the energies of the old mesh kept after each change (a
     fault of faults.h): the energy identity of the step after a change
     must fail.
   The same on two processes. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/contact_problem.h>

#include "faults.h"
#include "sliding_slab.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

// Flags the cells of the problem's mesh: at the first, third, ... call
// those within `radius` of `first`; at the others the cells refined before
// for coarsening and those near `second` for refinement.
template <int dim>
std::function<void()> alternating_cells(const ContactProblem<dim> &problem,
                                        const dealii::Point<dim>  &first,
                                        const dealii::Point<dim>  &second,
                                        const double               radius)
{
  return [&problem, first, second, radius, call = 0u, base = 0u]() mutable {
    auto &mesh = const_cast<dealii::Triangulation<dim> &>(
      problem.get_dof_handler().get_triangulation());
    if (call == 0)
      {
        unsigned int coarsest = std::numeric_limits<unsigned int>::max();
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            coarsest = std::min<unsigned int>(coarsest, cell->level());
        base = dealii::Utilities::MPI::min(coarsest, MPI_COMM_WORLD);
      }
    const bool refine_first = (call++ % 2 == 0);
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const dealii::Point<dim> &near = refine_first ? first : second;
          if (cell->center().distance(near) < radius &&
              static_cast<unsigned int>(cell->level()) == base)
            cell->set_refine_flag();
          else if (!refine_first &&
                   static_cast<unsigned int>(cell->level()) > base)
            cell->set_coarsen_flag();
        }
  };
}

template <int dim>
void run(const std::string              &name,
         const std::string              &scene,
         const std::vector<std::string> &settings,
         const unsigned int              interval,
         const dealii::Point<dim>       &first,
         const dealii::Point<dim>       &second,
         const double                    radius,
         const bool                      is_slab,
         const bool                      stale_energies = false)
{
  // The entry as a user sets it (the summary and the time series then
  // carry the transfers' term); the cells are chosen here.
  std::vector<std::string> all_settings = {"Mesh adaptation/Interval=" +
                                             std::to_string(interval),
                                           "Output/VTU interval=0",
                                           "Output/Progress interval=0",
                                           "Output/Print timings=false",
                                           "Output/Report times=",
                                           "Output/Output directory=" + name};
  all_settings.insert(all_settings.end(), settings.begin(), settings.end());
  const Parameters parameters =
    read_parameters(std::string(CONTACT_PRM_DIR) + "/" + scene, all_settings);
  Faults<dim> faults;
  faults.stale_energies_after_mesh_change = stale_energies;
  FaultyProblem<dim> problem(parameters, faults);
  problem.adapt_mesh_during_run(
    interval, alternating_cells<dim>(problem, first, second, radius));
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
    {
      const auto transfers = line.find("mesh transfers");
      if (line.rfind("Mesh", 0) == 0 || line.find("FAILED") != line.npos)
        std::cout << "  " << line << "\n";
      else if (line.rfind("Energy at", 0) == 0 && transfers != line.npos)
        std::cout << "  " << line.substr(transfers) << "\n";
    }
  if (!error.empty())
    std::cout << "  ended with: "
              << (error.find("Self-check failed") != error.npos ?
                    "Self-check failed" :
                    "another error: " + error)
              << "\n";
  else if (is_slab)
    {
      const auto [rate, traction] = slab_deviations(name, dim);
      std::cout << "  slip rates against 0.02 n: " << bound_text(rate)
                << "\n  friction tractions against 10: " << bound_text(traction)
                << "\n";
    }
}

// The slab of sliding_slab.h on the scene's coarse mesh.
std::vector<std::string> slab(const int dim)
{
  std::vector<std::string> settings = slab_settings(dim);
  settings.push_back(dim == 2 ? "Geometry/Cell size=0.0625" :
                                "Geometry/Cell size=0.125");
  return settings;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using dealii::Point;

  run<2>("slab_2d",
         "barboteu2015.prm",
         slab(2),
         1,
         Point<2>(0.375, 0),
         Point<2>(0.75, 0),
         0.15,
         true);
  run<3>("slab_3d",
         "barboteu2015_3d.prm",
         slab(3),
         1,
         Point<3>(0.375, 0, 0.375),
         Point<3>(0.75, 0, 0.5),
         0.25,
         true);

  const std::vector<std::string> paper = {"Geometry/Cell size=0.0625",
                                          "Time/Time step=0.0625"};
  run<2>("paper_2d",
         "barboteu2015.prm",
         paper,
         3,
         Point<2>(0.75, 0),
         Point<2>(0, 0.5),
         0.3,
         false);
  run<2>("paper_2d_stale_energies",
         "barboteu2015.prm",
         paper,
         3,
         Point<2>(0.75, 0),
         Point<2>(0, 0.5),
         0.3,
         false,
         true);
}
