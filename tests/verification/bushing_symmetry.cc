/* The bushing of prm/bushing.prm, a ring on a rigid shaft turned by a
   uniform torque, on its mesh of 8 x 4^2 cells, which is invariant under
   rotations by 360/32 degrees (the Q2 nodes of Gamma_3 are 64 points
   5.625 degrees apart), with k = 1/32. The exact solution is invariant
   under rotations about the axis; the discrete one on this mesh must be
   too, to round-off:
   - at every step the state, the slip rate and the friction traction of
     every node of Gamma_3 are those of every other (gamma3_history.csv;
     the traction along the node's tangent, which turns with the node);
   - the displacement is a rotation of itself: at every step its radial and
     its circumferential component are the same at every support point of
     one radius;
   - the moments about the axis balance (the self-check, time_series.csv):
     the reaction moment stays at round-off of the applied one;
   - two probes on the outer circle 11.25 degrees apart, between the
     cells' vertices (so outside the curved cells by their geometry error:
     each is evaluated at the nearest point of its cell), have the same
     radial and circumferential displacement at every step.
   The same run with a load that is not a torque (a uniform force 5 t
   along x added on the outer circle) shows that the symmetry checks can
   fail, while the moment balance still holds: the shaft takes the force
   by normal reactions, which pass through the axis.
   Last, the 3D tube of prm/bushing_3d.prm (the same cross-section, rollers
   on the end faces) at one refinement less: its angular momentum, moments
   and energies per unit length, its number of slipping nodes per layer,
   largest slip rate and first slip agree with the 2D ring's at every
   step. */

#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values.h>

#include <boost/serialization/array.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/utility.hpp>

#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <app/run.h>

#include <array>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

bool root()
{
  return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
}

// A CSV file as columns by name.
std::map<std::string, std::vector<double>> read_csv(const std::string &name)
{
  std::ifstream                              file(name);
  std::string                                line;
  std::vector<std::string>                   header;
  std::map<std::string, std::vector<double>> columns;
  std::getline(file, line);
  std::istringstream names(line);
  for (std::string field; std::getline(names, field, ',');)
    header.push_back(field);
  while (std::getline(file, line))
    {
      std::istringstream fields(line);
      unsigned int       c = 0;
      for (std::string field; std::getline(fields, field, ','); ++c)
        columns[header.at(c)].push_back(std::stod(field));
    }
  return columns;
}

double largest_magnitude(const std::vector<double> &values)
{
  double result = 1e-300;
  for (const double value : values)
    result = std::max(result, std::abs(value));
  return result;
}

// The mesh of 8 cells around, refined twice, is invariant under rotations
// by 360/32 degrees; points related by them have the same radius and the
// same angle modulo 360/32 degrees (a vertex and an edge's midpoint are
// not related: their Q2 nodes differ, as their nodal weights do). The key
// of a point's class: its radius and that angle, to 1e-9 and 1e-6 of it.
using Orbit = std::pair<long long, long long>;

Orbit orbit(const double x, const double y)
{
  const double    symmetry_angle = 2 * M_PI / 32;
  const long long turns = std::llround(std::atan2(y, x) / symmetry_angle * 1e6);
  return {std::llround(std::hypot(x, y) * 1e9),
          ((turns % 1000000) + 1000000) % 1000000};
}

// Smallest and largest values of each class.
template <std::size_t n>
using Ranges = std::map<Orbit, std::array<std::pair<double, double>, n>>;

template <std::size_t n>
void add_to_range(Ranges<n>                   &ranges,
                  const Orbit                 &key,
                  const std::array<double, n> &values)
{
  std::array<std::pair<double, double>, n> single;
  for (unsigned int i = 0; i < n; ++i)
    single[i] = {values[i], values[i]};
  auto &range = ranges.emplace(key, single).first->second;
  for (unsigned int i = 0; i < n; ++i)
    range[i] = {std::min(range[i].first, values[i]),
                std::max(range[i].second, values[i])};
}

template <std::size_t n>
double largest_spread(const Ranges<n> &ranges)
{
  double spread = 0;
  for (const auto &[key, range] : ranges)
    for (const auto &[low, high] : range)
      spread = std::max(spread, high - low);
  return spread;
}

// The largest spread (max - min) over each class of nodes of Gamma_3 at
// one step of a column of gamma3_history.csv, relative to the column's
// largest value.
double largest_spread(const std::map<std::string, std::vector<double>> &rows,
                      const std::string                                &name)
{
  const std::vector<double> &steps = rows.at("step"), &x = rows.at("x"),
                            &y = rows.at("y"), &values = rows.at(name);
  std::map<double, Ranges<1>> by_step;
  for (unsigned int i = 0; i < steps.size(); ++i)
    add_to_range<1>(by_step[steps[i]], orbit(x[i], y[i]), {{values[i]}});
  double spread = 0;
  for (const auto &[step, ranges] : by_step)
    spread = std::max(spread, largest_spread(ranges));
  return spread / largest_magnitude(values);
}

// How far the displacement is from a rotation of itself: the largest
// spread of u_r and u_theta over each class of support points, relative
// to the largest |u|.
double rotation_defect(const ContactProblem<2> &problem)
{
  const auto         &dof_handler = problem.get_dof_handler();
  const auto         &fe          = dof_handler.get_fe();
  const auto          u           = problem.ghosted(problem.get_displacement());
  dealii::FEValues<2> values(
    problem.get_mapping(),
    fe,
    dealii::Quadrature<2>(fe.get_unit_support_points()),
    dealii::update_values | dealii::update_quadrature_points);
  std::vector<dealii::Vector<double>> at_points(fe.n_dofs_per_cell(),
                                                dealii::Vector<double>(2));
  Ranges<2>                           ranges;
  double                              largest = 1e-300;
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        values.reinit(cell);
        values.get_function_values(u, at_points);
        for (unsigned int q = 0; q < at_points.size(); ++q)
          {
            const dealii::Point<2> &x = values.quadrature_point(q);
            const double            r = x.norm();
            const double            u_r =
              (x[0] * at_points[q][0] + x[1] * at_points[q][1]) / r;
            const double u_theta =
              (x[0] * at_points[q][1] - x[1] * at_points[q][0]) / r;
            largest = std::max(largest, at_points[q].l2_norm());
            add_to_range<2>(ranges, orbit(x[0], x[1]), {{u_r, u_theta}});
          }
      }
  Ranges<2> all;
  for (const Ranges<2> &part :
       dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, ranges))
    for (const auto &[key, range] : part)
      {
        auto &merged = all.emplace(key, range).first->second;
        for (unsigned int i = 0; i < 2; ++i)
          merged[i] = {std::min(merged[i].first, range[i].first),
                       std::max(merged[i].second, range[i].second)};
      }
  return largest_spread(all) /
         dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
}


struct Ring
{
  double                                     largest_rotation_defect = 0;
  double                                     first_slip              = 0;
  std::map<std::string, std::vector<double>> series;
  std::map<std::string, std::vector<double>> gamma3;
};

template <int dim>
Ring run(const std::string &scene, const std::vector<std::string> &sets)
{
  std::vector<std::string> all_sets = {"Time/Time step=0.03125",
                                       "Output/VTU interval=0",
                                       "Output/Progress interval=0",
                                       "Output/Print timings=false",
                                       "Output/Report times="};
  all_sets.insert(all_sets.end(), sets.begin(), sets.end());
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/" + scene, all_sets);
  ContactProblem<dim> problem(parameters);
  Ring                ring;
  if constexpr (dim == 2)
    problem.add_postprocessor(
      std::make_unique<StepObserver<2>>([&](const ContactProblem<2> &p) {
        ring.largest_rotation_defect =
          std::max(ring.largest_rotation_defect, rotation_defect(p));
      }));
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  const RunSummary   summary = problem.run();
  std::cout.rdbuf(console);
  for (const auto &[name, value] : summary.final_quantities)
    if (name == "time of the first slip")
      ring.first_slip = value;
  if (root())
    {
      ring.series = read_csv(parameters.output.directory + "/time_series.csv");
      if (std::filesystem::exists(parameters.output.directory +
                                  "/gamma3_history.csv"))
        ring.gamma3 =
          read_csv(parameters.output.directory + "/gamma3_history.csv");
    }
  return ring;
}

const char *yes_no(const bool condition)
{
  return condition ? "yes" : "no";
}

void report_symmetry(const std::string &name, const Ring &ring)
{
  const double moment_balance =
    largest_magnitude(ring.series.at("reaction_moment")) /
    largest_magnitude(ring.series.at("applied_moment"));
  std::cout << name << ":\n"
            << "  state, slip rate, friction traction the same at every node "
               "of Gamma_3 (1e-10): "
            << yes_no(std::max(
                        {largest_spread(ring.gamma3, "state"),
                         largest_spread(ring.gamma3, "slip_rate"),
                         largest_spread(ring.gamma3, "friction_traction_t1")}) <
                      1e-10)
            << "\n  displacement a rotation of itself (1e-10): "
            << yes_no(ring.largest_rotation_defect < 1e-10)
            << "\n  moments balance (reaction moment below 1e-10 of the "
               "applied): "
            << yes_no(moment_balance < 1e-10) << std::endl;
}

// Whether the displacements of the two probes, at 15 and 26.25 degrees,
// have the same radial and circumferential components at every step,
// relative to the largest.
bool probes_turn(const std::map<std::string, std::vector<double>> &series)
{
  const double        angles[2] = {15 * M_PI / 180, 26.25 * M_PI / 180};
  std::vector<double> difference, size;
  for (unsigned int n = 0; n < series.at("step").size(); ++n)
    {
      double polar[2][2];
      for (unsigned int i = 0; i < 2; ++i)
        {
          const std::string name = "probe" + std::to_string(i + 1) + "_u_";
          const double      u_x  = series.at(name + "x")[n],
                       u_y       = series.at(name + "y")[n];
          polar[i][0] = std::cos(angles[i]) * u_x + std::sin(angles[i]) * u_y;
          polar[i][1] = std::cos(angles[i]) * u_y - std::sin(angles[i]) * u_x;
          size.push_back(std::hypot(u_x, u_y));
        }
      difference.push_back(std::abs(polar[0][0] - polar[1][0]));
      difference.push_back(std::abs(polar[0][1] - polar[1][1]));
    }
  return largest_magnitude(difference) < 1e-10 * largest_magnitude(size);
}


// The 3D tube against the 2D ring, step by step: the columns per unit
// length, relative to the 2D column's largest value.
void compare_2d_3d()
{
  const std::vector<std::string> coarser = {"Geometry/Mesh refinements=1",
                                            "Output/Gamma3 history=false"};
  std::vector<std::string>       sets_2d = coarser, sets_3d = coarser;
  sets_2d.push_back("Output/Output directory=run-ring");
  sets_3d.push_back("Output/Output directory=run-tube");
  const Ring   ring   = run<2>("bushing.prm", sets_2d);
  const Ring   tube   = run<3>("bushing_3d.prm", sets_3d);
  const double length = 2 * M_PI * 0.5 / 8;
  if (!root())
    return;
  double difference = 0;
  for (const std::string name : {"angular_momentum",
                                 "applied_moment",
                                 "friction_moment",
                                 "kinetic_energy",
                                 "elastic_energy",
                                 "friction_dissipation",
                                 "max_slip_rate"})
    {
      const std::vector<double> &a = ring.series.at(name),
                                &b = tube.series.at(name);
      const double per_length      = (name == "max_slip_rate" ? 1 : length);
      for (unsigned int n = 0; n < a.size(); ++n)
        difference = std::max(difference,
                              std::abs(a[n] - b.at(n) / per_length) /
                                largest_magnitude(a));
    }
  // The tube has 2 x 2 + 1 = 5 layers of nodes of Gamma_3 along z.
  bool same_slip =
    ring.series.at("n_slip").size() == tube.series.at("n_slip").size();
  for (unsigned int n = 0; same_slip && n < ring.series.at("n_slip").size();
       ++n)
    same_slip =
      (5 * ring.series.at("n_slip")[n] == tube.series.at("n_slip")[n]);
  std::cout << "3D tube against the 2D ring (one refinement less), "
            << ring.series.at("step").size() - 1 << " steps:\n"
            << "  angular momentum, moments, energies per unit length and "
               "largest slip rate agree to 1e-10: "
            << yes_no(difference < 1e-10)
            << "\n  slipping nodes: 5 layers of the ring's at every step: "
            << yes_no(same_slip)
            << "\n  first slip at t = " << std::setprecision(6)
            << ring.first_slip << " in 2D, " << tube.first_slip << " in 3D"
            << std::endl;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Two probes on the outer circle, 11.25 degrees apart (at 15 and 26.25
  // degrees, between the cells' vertices: outside the curved cells by the
  // geometry error, and given to 10 digits).
  const std::string probes = "Output/Probe points=0.9659258263, 0.2588190451; "
                             "0.8968727415, 0.4422886902";
  const Ring        torque = run<2>("bushing.prm",
                             {"Output/Gamma3 history=true",
                                     probes,
                                     "Output/Output directory=run-torque"});
  const Ring        not_a_torque =
    run<2>("bushing.prm",
           {"Output/Gamma3 history=true",
            "Output/Output directory=run-not-a-torque",
            "Boundary conditions/Tractions=1: -40*t*y/sqrt(x*x + y*y) + 5*t; "
            "40*t*x/sqrt(x*x + y*y)"});
  if (root())
    {
      report_symmetry("uniform torque", torque);
      std::cout << "  probes on the outer circle 11.25 degrees apart turn "
                   "with it (their u_theta and u_r agree to 1e-10): "
                << yes_no(probes_turn(torque.series)) << std::endl;
      std::cout << "  first slip at t = " << std::setprecision(6)
                << torque.first_slip << std::endl;
      report_symmetry("torque and a force along x", not_a_torque);
    }
  compare_2d_3d();
}
