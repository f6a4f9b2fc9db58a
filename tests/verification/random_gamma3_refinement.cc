/* Convergence against the manufactured slip front on meshes refined at
   random on Gamma_3: at each of h = k = 1/8, 1/16, 1/32, every cell with a
   face on Gamma_3 is refined once or not by a coin (a hash of its CellId
   and the level, so the same cells on any number of processes), and the
   scene runs on that mesh (a MeshPlan of one cycle). In 2D Gamma_3 then
   has faces of two sizes, in 3D (the slab of
   manufactured_space_time_3d_q1) also hanging nodes, whose friction the
   nodes they follow carry (doc/algorithm.md, "Hanging nodes on Gamma_3").
   Printed per level: the unknowns, the largest errors over the steps of
   ||eps(u - u_h)||, ||w - w_h|| and ||u - u_h|| and their rates, next to
   the uniform meshes' (the same program), and two verdicts: the rates
   between the two finest levels within 0.1 of the uniform meshes' in each
   norm (about 1 in each, with k = h), and the V-error at most the uniform
   mesh's of the same h at every level (the random mesh contains it). */

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <app/run.h>
#include <core/contact_problem.h>
#include <core/mesh_plan.h>
#include <core/geometry.h>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

// FNV-1a of the text: the same coin on every process and machine.
bool coin(const std::string &text)
{
  std::uint64_t hash = 1469598103934665603ull;
  for (const char c : text)
    {
      hash ^= static_cast<unsigned char>(c);
      hash *= 1099511628211ull;
    }
  return (hash >> 63) == 0;
}

// One cycle refining the cells at Gamma_3 that the coin picks.
template <int dim>
MeshPlan random_gamma3_plan(const Parameters  &parameters,
                            const unsigned int level)
{
  dealii::parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
  create_geometry<dim>(parameters, MPI_COMM_WORLD)->create_mesh(mesh);
  const std::set<dealii::types::boundary_id> contact(
    parameters.boundary.contact_ids.begin(),
    parameters.boundary.contact_ids.end());
  for (const auto &cell : mesh.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            contact.count(cell->face(f)->boundary_id()) != 0 &&
            coin(cell->id().to_string() + "/" + std::to_string(level)))
          cell->set_refine_flag();
  MeshPlan plan;
  plan.add_cycle_from_flags(mesh);
  return plan;
}

template <int dim>
void study(const std::vector<std::string> &scene)
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << dim << "D:\n"
              << "| h | mesh | unknowns | V-error | rate | w L2 error | rate | "
                 "u L2 error | rate |\n";
  std::vector<RunSummary> last(2);
  bool                    rates_agree = true, no_larger_V_error = true;
  // The errors of the level before: uniform, random.
  std::vector<ErrorNorms> coarser(2);
  for (unsigned int level = 0; level < 3; ++level)
    {
      const double h = 0.125 / (1 << level);
      for (const bool random : {false, true})
        {
          std::vector<std::string> settings = scene;
          settings.insert(
            settings.end(),
            {"Geometry/Cell size=" + std::to_string(h),
             "Time/Time step=" + std::to_string(h),
             "Convergence study/Levels=0",
             "Output/VTU interval=0",
             "Output/Progress interval=0",
             "Output/Print timings=false",
             "Output/Output directory=run-" + std::to_string(dim) + "d-" +
               std::to_string(level) + (random ? "-random" : "-uniform")});
          const Parameters parameters =
            read_parameters(CONTACT_PRM_DIR "/manufactured_slip_front.prm",
                            settings);
          ContactProblem<dim> problem(parameters);
          if (random)
            problem.adapt_mesh(random_gamma3_plan<dim>(parameters, level));
          std::streambuf  *console = std::cout.rdbuf(nullptr);
          const RunSummary summary = problem.run();
          std::cout.rdbuf(console);
          const ErrorNorms &e      = summary.max_errors,
                           &before = last[random].max_errors;
          const auto rate = [&](const double now, const double earlier) {
            std::ostringstream text;
            if (level == 0)
              text << "-";
            else
              text << std::fixed << std::setprecision(2)
                   << std::log2(earlier / now);
            return text.str();
          };
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::cout << "| 1/" << (8 << level) << " | "
                      << (random ? "random at Gamma_3" : "uniform") << " | "
                      << summary.n_dofs << " | " << std::scientific
                      << std::setprecision(3) << e.displacement_V << " | "
                      << rate(e.displacement_V, before.displacement_V) << " | "
                      << std::scientific << e.velocity_L2 << " | "
                      << rate(e.velocity_L2, before.velocity_L2) << " | "
                      << std::scientific << e.displacement_L2 << " | "
                      << rate(e.displacement_L2, before.displacement_L2) << " |"
                      << std::defaultfloat << "\n";
          last[random] = summary;
        }
      const ErrorNorms &uniform = last[0].max_errors,
                       &random  = last[1].max_errors;
      no_larger_V_error =
        no_larger_V_error && random.displacement_V <= uniform.displacement_V;
      if (level == 2)
        for (const auto member : {&ErrorNorms::displacement_V,
                                  &ErrorNorms::velocity_L2,
                                  &ErrorNorms::displacement_L2})
          rates_agree =
            rates_agree &&
            std::abs(std::log2(coarser[0].*member / uniform.*member) -
                     std::log2(coarser[1].*member / random.*member)) <= 0.1;
      coarser = {uniform, random};
    }
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "rates at the finest level within 0.1 of the uniform "
                 "meshes': "
              << (rates_agree ? "yes" : "no")
              << "\nV-error at most the uniform mesh's at every h: "
              << (no_larger_V_error ? "yes" : "no") << "\n";
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  study<2>({});
  study<3>({"Dimension=3",
            "Geometry/Lower corner=0, 0, 0",
            "Geometry/Upper corner=1, 0.5, 0.125",
            "Loads and initial values/Body force=0; 0; 0",
            "Loads and initial values/Initial displacement=0; 0; 0",
            "Loads and initial values/Initial velocity=0; 0; 0"});
}
