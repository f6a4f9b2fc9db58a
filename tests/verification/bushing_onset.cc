/* The slip onset of the bushing (prm/bushing.prm: the ring on the shaft,
   a torque growing in time) under refinement of the mesh, for Q1 and Q2
   elements on a polygonal Gamma_3 ('Geometry/Mapping degree = 1': the
   cells' edges are the chords of the circles) and on a curved one
   (mapping degree 2), at k = 1/256 for all. The first slip is
   extrapolated within its step ("First slip at t = ..." of the summary),
   so at a fixed k it moves with h alone; the differences of three meshes
   (8 x 4^m cells, m = 1, 2, 3) give the observed order in h, from the
   coarser and the finer pair:
     order = log2(|t_1 - t_2| / |t_2 - t_3|).
   What the test asserts (doc/verification.md has the study to m = 5):
   - Q2 on the polygon converges at about first order (Gamma_3's corners
     between the chords), the three others at second order or above;
   - at every level a curved Gamma_3 gives a smaller change from the next
     coarser level than the polygon with the same element, i.e. a smaller
     error. */

#include <deal.II/base/mpi.h>

#include <core/contact_problem.h>
#include <app/run.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

double first_slip(const unsigned int element_degree,
                  const unsigned int mapping_degree,
                  const unsigned int refinements)
{
  const Parameters parameters = read_parameters(
    CONTACT_PRM_DIR "/bushing.prm",
    {"Geometry/Finite element degree=" + std::to_string(element_degree),
     "Geometry/Mapping degree=" + std::to_string(mapping_degree),
     "Geometry/Mesh refinements=" + std::to_string(refinements),
     "Time/Time step=0.00390625",
     "Output/VTU interval=0",
     "Output/Time series=false",
     "Output/Progress interval=0",
     "Output/Print timings=false",
     "Output/Report times=",
     "Output/Output directory=run-onset"});
  ContactProblem<2>  problem(parameters);
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  const RunSummary   summary = problem.run();
  std::cout.rdbuf(console);
  for (const auto &[name, value] : summary.final_quantities)
    if (name == "time of the first slip")
      return value;
  return std::nan("");
}

const char *yes_no(const bool condition)
{
  return condition ? "yes" : "no";
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  // changes[element degree - 1][mapping degree - 1]: |t_m - t_{m-1}|.
  std::vector<std::vector<std::vector<double>>> changes(
    2, std::vector<std::vector<double>>(2));
  for (unsigned int element = 1; element <= 2; ++element)
    for (unsigned int mapping = 1; mapping <= 2; ++mapping)
      {
        std::vector<double> t;
        for (unsigned int m = 1; m <= 3; ++m)
          t.push_back(first_slip(element, mapping, m));
        for (unsigned int m = 1; m < t.size(); ++m)
          changes[element - 1][mapping - 1].push_back(
            std::abs(t[m] - t[m - 1]));
        const std::vector<double> &d = changes[element - 1][mapping - 1];
        if (root)
          std::cout << "Q" << element << ", mapping degree " << mapping
                    << ": first slip at t = " << std::setprecision(8) << t[0]
                    << ", " << t[1] << ", " << t[2] << "; order " << std::fixed
                    << std::setprecision(1) << std::log2(d[0] / d[1])
                    << std::defaultfloat << std::endl;
      }
  const auto order = [&](const unsigned int element,
                         const unsigned int mapping) {
    const std::vector<double> &d = changes[element - 1][mapping - 1];
    return std::log2(d[0] / d[1]);
  };
  bool curved_closer = true;
  for (unsigned int element = 0; element < 2; ++element)
    for (unsigned int m = 0; m < 2; ++m)
      curved_closer =
        curved_closer && changes[element][1][m] < changes[element][0][m];
  if (root)
    std::cout << "Q2 on the polygon below order 1.5, the others above 1.5: "
              << yes_no(order(2, 1) < 1.5 && order(1, 1) > 1.5 &&
                        order(1, 2) > 1.5 && order(2, 2) > 1.5)
              << "\ncurved Gamma_3 changes less than the polygon at every "
                 "level: "
              << yes_no(curved_closer) << std::endl;
}
