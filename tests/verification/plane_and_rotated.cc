/* Invariance checks, on the paper's scene at h = k = 1/16:

   (a) the block extruded to (0,1) x (0,0.5) x (0,0.5) with both z faces as
       symmetry planes is the 2D (plane strain) problem: per step, the 3D
       stick/slip counts are 9 times the 2D ones (9 node layers across),
       energies, momentum and friction force half the 2D ones (thickness
       0.5), probe displacements equal and u_z = 0;
   (b) the 2D scene rotated by 30 degrees (an inclined Gamma_3, loads
       rotated with it) gives the same counts, energies and friction force,
       and rotated momentum and probe displacements;
   (c) the 3D scene of (a) rotated by 30 degrees about the normal of Gamma_3
       (the y axis): the slip now has two components in the nodes' tangent
       bases, and the symmetry planes are inclined. Same comparison with (a).

   The discrete problems are the same up to an orthogonal change of basis
   (and an extrusion of a z-independent solution), so the results agree up
   to round-off and the stopping tests of the nonlinear solvers
   (convexification tolerance 1e-10 relative to the velocity); they are
   required to agree to 1e-8 relative to each quantity's largest value over
   the run. */

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <app/run.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using Columns = std::map<std::string, std::vector<double>>;

const double angle = M_PI / 6;

Columns run(const std::string &name, const std::vector<std::string> &sets)
{
  std::vector<std::string> arguments = {"contact"};
  for (const std::string &set : sets)
    {
      arguments.push_back("--set");
      arguments.push_back(set);
    }
  for (const std::string &set :
       std::vector<std::string>{"Geometry/Cell size=0.0625",
                                "Time/Time step=0.0625",
                                "Output/VTU interval=0",
                                "Output/Progress interval=0",
                                "Output/Print timings=false",
                                "Output/Report times=",
                                "Output/Output directory=run-" + name})
    {
      arguments.push_back("--set");
      arguments.push_back(set);
    }
  arguments.push_back(CONTACT_PRM_DIR "/barboteu2015.prm");
  std::vector<const char *> argv;
  for (const std::string &argument : arguments)
    argv.push_back(argument.c_str());

  // The runs' console output is not part of this test's output.
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  Contact::run_from_command_line(argv.size(), argv.data());
  std::cout.rdbuf(console);

  std::ifstream csv("run-" + name + "/time_series.csv");
  std::string   line;
  std::getline(csv, line);
  const std::vector<std::string> header =
    dealii::Utilities::split_string_list(line);
  Columns columns;
  while (std::getline(csv, line))
    {
      const auto values = dealii::Utilities::split_string_list(line);
      for (unsigned int i = 0; i < header.size(); ++i)
        columns[header[i]].push_back(std::stod(values[i]));
    }
  return columns;
}

// Compares `column` of b with the combination sum_i weight_i column_i of a
// (a linear map of a's results) at every step, relative to the largest
// value of b's column over the run.
struct Comparison
{
  double largest_difference = 0;

  void compare(const Columns                                     &a,
               const Columns                                     &b,
               const std::string                                 &column,
               const std::vector<std::pair<std::string, double>> &map)
  {
    const std::vector<double> &values = b.at(column);
    double                     scale  = 1e-300;
    for (const double v : values)
      scale = std::max(scale, std::abs(v));
    for (unsigned int n = 0; n < values.size(); ++n)
      {
        double expected = 0;
        for (const auto &[name, weight] : map)
          expected += weight * a.at(name)[n];
        largest_difference =
          std::max(largest_difference, std::abs(values[n] - expected) / scale);
      }
  }
};

void report(const std::string &name,
            const Columns     &a,
            const Columns     &b,
            const double       count_factor,
            const Comparison  &comparison)
{
  bool counts_agree = (a.at("step").size() == b.at("step").size());
  for (unsigned int n = 0; counts_agree && n < a.at("step").size(); ++n)
    for (const std::string column : {"n_stick", "n_slip"})
      counts_agree =
        counts_agree && (b.at(column)[n] == count_factor * a.at(column)[n]);
  std::cout << name << ": " << a.at("step").size() - 1
            << " steps; stick/slip counts agree at every step: "
            << (counts_agree ? "yes" : "no")
            << "; energies, momentum, friction force and probe "
               "displacements agree to 1e-8: "
            << (comparison.largest_difference < 1e-8 ? "yes" : "no")
            << std::endl;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                   c = std::cos(angle), s = std::sin(angle);
  const std::vector<std::string> energies = {"kinetic_energy",
                                             "elastic_energy",
                                             "external_work",
                                             "viscous_dissipation",
                                             "friction_dissipation",
                                             "numerical_dissipation"};

  const Columns plane =
    run("2d",
        {"Output/Probe points=0.96875, 0.46875; 0.5, 0.25; 0.78125, 0.03125"});

  const std::string box_3d[] = {
    "Dimension=3",
    "Geometry/Lower corner=0, 0, 0",
    "Geometry/Upper corner=1, 0.5, 0.5",
    "Boundary conditions/Symmetry boundary ids=4, 5",
    "Boundary conditions/Tractions=3: 0; -600*t; 0",
    "Loads and initial values/Body force=0; -1e-5; 0",
    "Loads and initial values/Initial "
    "displacement=0; 0; 0",
    "Loads and initial values/Initial "
    "velocity=0; 0; 0"};
  std::vector<std::string> extruded_sets(std::begin(box_3d), std::end(box_3d));
  extruded_sets.push_back(
    "Output/Probe points=0.96875, 0.46875, 0.25; 0.5, 0.25, "
    "0.46875; 0.78125, 0.03125, 0.03125");
  const Columns extruded = run("3d", extruded_sets);
  {
    Comparison comparison;
    for (const std::string &e : energies)
      comparison.compare(plane, extruded, e, {{e, 0.5}});
    for (const std::string column :
         {"friction_force", "momentum_x", "momentum_y"})
      comparison.compare(plane, extruded, column, {{column, 0.5}});
    comparison.compare(plane,
                       extruded,
                       "max_slip_rate",
                       {{"max_slip_rate", 1}});
    for (const std::string probe : {"probe1", "probe2", "probe3"})
      {
        comparison.compare(plane,
                           extruded,
                           probe + "_u_x",
                           {{probe + "_u_x", 1}});
        comparison.compare(plane,
                           extruded,
                           probe + "_u_y",
                           {{probe + "_u_y", 1}});
      }
    report("(a) 3D extruded vs 2D", plane, extruded, 9, comparison);
    double largest_u_z = 0;
    for (const std::string probe : {"probe1", "probe2", "probe3"})
      for (const double u_z : extruded.at(probe + "_u_z"))
        largest_u_z = std::max(largest_u_z, std::abs(u_z));
    std::cout << "    u_z at the probes below 1e-12: "
              << (largest_u_z < 1e-12 ? "yes" : "no") << std::endl;
  }

  // (b) Rotation by 30 degrees about the origin: loads R f, points R x.
  const auto rotated = [&](const double x, const double y) {
    std::ostringstream text;
    text << std::setprecision(17) << c * x - s * y << ", " << s * x + c * y;
    return text.str();
  };
  std::ostringstream traction, body_force;
  traction << std::setprecision(17);
  body_force << std::setprecision(17);
  traction << "Boundary conditions/Tractions=3: " << 600 * s << "*t; "
           << -600 * c << "*t";
  body_force << "Loads and initial values/Body force=" << 1e-5 * s << "; "
             << -1e-5 * c;
  const Columns inclined =
    run("2d-rotated",
        {"Geometry/Rotation angle=30",
         traction.str(),
         body_force.str(),
         "Output/Probe points=" + rotated(0.96875, 0.46875) + "; " +
           rotated(0.5, 0.25) + "; " + rotated(0.78125, 0.03125)});
  {
    Comparison comparison;
    for (const std::string &e : energies)
      comparison.compare(plane, inclined, e, {{e, 1}});
    for (const std::string column : {"friction_force", "max_slip_rate"})
      comparison.compare(plane, inclined, column, {{column, 1}});
    comparison.compare(plane,
                       inclined,
                       "momentum_x",
                       {{"momentum_x", c}, {"momentum_y", -s}});
    comparison.compare(plane,
                       inclined,
                       "momentum_y",
                       {{"momentum_x", s}, {"momentum_y", c}});
    for (const std::string probe : {"probe1", "probe2", "probe3"})
      {
        comparison.compare(plane,
                           inclined,
                           probe + "_u_x",
                           {{probe + "_u_x", c}, {probe + "_u_y", -s}});
        comparison.compare(plane,
                           inclined,
                           probe + "_u_y",
                           {{probe + "_u_x", s}, {probe + "_u_y", c}});
      }
    report(
      "(b) 2D inclined by 30 degrees vs 2D", plane, inclined, 1, comparison);
  }

  // (c) Rotation of the 3D block by 30 degrees about the y axis: x' =
  // (c x + s z, y, -s x + c z). The loads along y do not change.
  const auto rotated_3d = [&](const double x, const double y, const double z) {
    std::ostringstream text;
    text << std::setprecision(17) << c * x + s * z << ", " << y << ", "
         << -s * x + c * z;
    return text.str();
  };
  std::vector<std::string> turned_sets(std::begin(box_3d), std::end(box_3d));
  turned_sets.push_back("Geometry/Rotation angle=30");
  turned_sets.push_back("Geometry/Rotation axis=0, 1, 0");
  turned_sets.push_back(
    "Output/Probe points=" + rotated_3d(0.96875, 0.46875, 0.25) + "; " +
    rotated_3d(0.5, 0.25, 0.46875) + "; " +
    rotated_3d(0.78125, 0.03125, 0.03125));
  const Columns turned = run("3d-rotated", turned_sets);
  {
    Comparison comparison;
    for (const std::string &e : energies)
      comparison.compare(extruded, turned, e, {{e, 1}});
    for (const std::string column : {"friction_force", "max_slip_rate"})
      comparison.compare(extruded, turned, column, {{column, 1}});
    const std::vector<std::vector<std::pair<std::string, double>>> R = {
      {{"x", c}, {"z", s}}, {{"y", 1}}, {{"x", -s}, {"z", c}}};
    const std::string axes[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < 3; ++d)
      for (const std::string prefix :
           {"momentum_", "probe1_u_", "probe2_u_", "probe3_u_"})
        {
          std::vector<std::pair<std::string, double>> map;
          for (const auto &[axis, weight] : R[d])
            map.emplace_back(prefix + axis, weight);
          comparison.compare(extruded, turned, prefix + axes[d], map);
        }
    report("(c) 3D rotated by 30 degrees about the normal of Gamma_3 vs 3D",
           extruded,
           turned,
           1,
           comparison);
  }
}
