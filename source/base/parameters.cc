/* Declaration, parsing and checks of the .prm entries. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <base/dimensions.h>
#include <base/geometry_base.h>
#include <base/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace Contact
{
  std::string number_text(const double value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }


  // The one form of a user error about a single entry: it names the entry
  // (with its subsection), the value read and what is allowed.
  void check_entry(const bool         condition,
                   const std::string &entry,
                   const double       value,
                   const std::string &allowed)
  {
    AssertThrow(condition,
                ExcMessage("Invalid value " + number_text(value) +
                           " for the entry '" + entry + "': allowed is " +
                           allowed + "."));
  }


  namespace
  {
    std::vector<types::boundary_id> parse_boundary_ids(const std::string &text)
    {
      std::vector<types::boundary_id> ids;
      for (const int id :
           Utilities::string_to_int(Utilities::split_string_list(text)))
        ids.push_back(static_cast<types::boundary_id>(id));
      return ids;
    }

    // Each report prints the state of Gamma_3 (and with VTU output writes
    // a file): more than this many cannot be meant.
    constexpr unsigned int max_report_times = 10000;

    // Numbers separated by ',', read in one pass, at most
    // max_report_times of them.
    std::vector<double> parse_report_times(const std::string &text)
    {
      std::vector<double> times;
      if (Utilities::trim(text).empty())
        return times;
      for (std::size_t begin = 0; begin <= text.size();)
        {
          const std::size_t end = std::min(text.find(',', begin), text.size());
          AssertThrow(times.size() < max_report_times,
                      ExcMessage(
                        "Entry 'Output/Report times' has more than " +
                        std::to_string(max_report_times) +
                        " times; allowed are at most that many (each "
                        "prints the state of Gamma_3, and with VTU output "
                        "writes a file)."));
          const std::string number =
            Utilities::trim(text.substr(begin, end - begin));
          char        *stop = nullptr;
          const double t    = std::strtod(number.c_str(), &stop);
          AssertThrow(!number.empty() && *stop == '\0' && std::isfinite(t),
                      ExcMessage("Entry 'Output/Report times': cannot read '" +
                                 number +
                                 "' as a time; allowed are finite numbers "
                                 "separated by ','."));
          times.push_back(t);
          begin = end + 1;
        }
      return times;
    }

    // Points 'x, y[, z]' separated by ';', each of exactly dim numbers.
    std::vector<std::vector<double>> parse_points(const std::string &text,
                                                  const unsigned int dim,
                                                  const std::string &entry)
    {
      std::vector<std::vector<double>> points;
      for (const std::string &point : Utilities::split_string_list(text, ';'))
        {
          const auto          coordinates = Utilities::split_string_list(point);
          bool                numbers     = (coordinates.size() == dim);
          std::vector<double> values;
          for (const std::string &coordinate : coordinates)
            {
              char        *end   = nullptr;
              const double value = std::strtod(coordinate.c_str(), &end);
              numbers = numbers && *end == '\0' && std::isfinite(value);
              values.push_back(value);
            }
          AssertThrow(numbers,
                      ExcMessage("Entry '" + entry +
                                 "': cannot read the "
                                 "point '" +
                                 point +
                                 "'; allowed are points "
                                 "of exactly Dimension finite numbers "
                                 "'x, y[, z]', separated by ';'."));
          points.push_back(values);
        }
      return points;
    }
  } // namespace


  // @sect3{Geometry}

  const ChoiceTable<GeometryParameters::Domain> &GeometryParameters::domains()
  {
    static const ChoiceTable<Domain> table(Entry::domain,
                                           {{"box", Domain::box},
                                            {"shell", Domain::shell}});
    return table;
  }

  const ChoiceTable<GeometryParameters::CellShape> &
  GeometryParameters::cell_shapes()
  {
    static const ChoiceTable<CellShape> table(
      Entry::cell_shape,
      {{"hypercube", CellShape::hypercube}, {"simplex", CellShape::simplex}});
    return table;
  }

  const ChoiceTable<GeometryParameters::MassMatrix> &
  GeometryParameters::mass_matrices()
  {
    static const ChoiceTable<MassMatrix> table(
      "Geometry/Mass matrix",
      {{"consistent", MassMatrix::consistent}, {"lumped", MassMatrix::lumped}});
    return table;
  }

  // A function-local static: the geometries register their entries while
  // the library is loaded, in an order that is not defined.
  std::map<std::string, GeometryParameters::Entries> &
  GeometryParameters::registered_entries()
  {
    static std::map<std::string, Entries> entries;
    return entries;
  }

  bool GeometryParameters::register_entries(const std::string &name,
                                            const Entries     &entries)
  {
    registered_entries()[name] = entries;
    return true;
  }

  // The entries of every geometry; after each, those of the geometries
  // that follow it (source/geometry/).
  void GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    const auto declare_entry = [&prm](const std::string           &name,
                                      const std::string           &value,
                                      const Patterns::PatternBase &pattern,
                                      const std::string           &help) {
      prm.declare_entry(name, value, pattern, help);
      for (const auto &[geometry, entries] : registered_entries())
        if (entries.after == name)
          entries.declare(prm);
    };
    prm.enter_subsection("Geometry");
    {
      declare_entry(
        "Mesh file",
        "",
        Patterns::Anything(),
        "A gmsh .msh file (format 2.2 or 4) whose physical ids are the "
        "boundary ids of 'Boundary conditions'; a relative path is taken "
        "relative to the .prm file that sets it. Empty: the box of Lower and "
        "Upper corner with the Cell size.");
      declare_entry("Mesh refinements",
                    "0",
                    Patterns::Integer(0, 10),
                    "Global refinements of the mesh read from the Mesh "
                    "file, or of the shell's coarse mesh.");
      declare_entry(
        "Domain",
        domains().name(Domain::box),
        domains().pattern(),
        "box: Lower and Upper corner, divided by the Cell size; shell: the "
        "annulus (2D) or the tube along z from z = 0 to the Shell length "
        "(3D) between the Inner and the Outer radius around the origin, "
        "Cells around the circle, refined Mesh refinements times along "
        "the circles (boundary ids 0 inner, 1 outer, 2 z = 0, 3 z = "
        "length). A Mesh file replaces both.");
      declare_entry(
        "Mapping degree",
        "1",
        Patterns::Integer(1, 4),
        "Degree of the polynomial map of each cell: 1, straight edges (a "
        "polygon for a circle); 2 or more, edges that follow a curved "
        "boundary (the shell's circles) between the nodes. On a shell use "
        "2 or more: equal to the 'Finite element degree' keeps the rigid "
        "rotation about the axis in the discrete space (the moments balance "
        "to round-off, a self-check); above it (Q1) it gave the bushing's "
        "slip onset most accurately, but balances the moments only to "
        "O(h^2); below it Q2 loses an order on Gamma_3 "
        "(doc/verification.md).");
      declare_entry(
        "Cell shape",
        cell_shapes().name(CellShape::hypercube),
        cell_shapes().pattern(),
        "hypercube: quadrilaterals/hexahedra with Q_p elements; simplex: "
        "every box cell split into triangles (2) or tetrahedra (5), with "
        "P_p elements (FE_SimplexP).");
      declare_entry("Finite element degree",
                    "1",
                    Patterns::Integer(1, 4),
                    "Polynomial degree of the Lagrange elements Q_p.");
      declare_entry("Mass matrix",
                    mass_matrices().name(MassMatrix::consistent),
                    mass_matrices().pattern(),
                    "consistent: Gauss quadrature; lumped: Gauss-Lobatto "
                    "quadrature at the nodes, a diagonal M.");
      declare_entry(
        "Refinement points",
        "",
        Patterns::Anything(),
        "Points 'x, y[, z]' separated by ';' (a corner where the solution is "
        "singular) towards which the mesh is graded: cells closer than R to "
        "a point are refined until their size is at most h (r/R)^gamma, r the "
        "distance of their center to the point. The refinement may reach "
        "Gamma_3 (hanging nodes there carry no friction unknown; their weight "
        "goes to the nodes they follow).");
      declare_entry("Refinement radius",
                    "0",
                    Patterns::Double(0),
                    "R [m] of the grading; 0 switches it off.");
      declare_entry(
        "Refinement grading",
        "0.3333333333",
        Patterns::Double(0.05, 1),
        "gamma of the grading: for a singularity u ~ r^lambda, gamma = "
        "1 - lambda restores the rate of smooth solutions.");
      declare_entry(
        "Rotation angle",
        "0",
        Patterns::Double(-360, 360),
        "Rotates the mesh about the origin by this angle [degrees] (about "
        "the z axis in 2D, about the Rotation axis in 3D): an inclined "
        "Gamma_3. Loads, refinement and probe points are given in the "
        "rotated frame.");
      declare_entry("Rotation axis",
                    "0, 0, 1",
                    Patterns::List(Patterns::Double(), 3, 3),
                    "Axis of the rotation in 3D, three numbers, not all "
                    "zero.");
    }
    prm.leave_subsection();
  }

  void GeometryParameters::parse_parameters(ParameterHandler  &prm,
                                            const unsigned int dim)
  {
    prm.enter_subsection("Geometry");
    {
      mesh_file          = Utilities::trim(prm.get("Mesh file"));
      mesh_refinements   = prm.get_integer("Mesh refinements");
      domain             = domains().parse(prm.get("Domain"));
      mapping_degree     = prm.get_integer("Mapping degree");
      cell_shape         = cell_shapes().parse(prm.get("Cell shape"));
      fe_degree          = prm.get_integer("Finite element degree");
      mass_matrix        = mass_matrices().parse(prm.get("Mass matrix"));
      refinement_points  = parse_points(prm.get("Refinement points"),
                                       dim,
                                       "Geometry/Refinement points");
      refinement_radius  = prm.get_double("Refinement radius");
      refinement_grading = prm.get_double("Refinement grading");
      rotation_angle     = prm.get_double("Rotation angle");
      rotation_axis      = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Rotation axis")));
      check_entry(dim == 2 || rotation_angle == 0 || rotation_axis[0] != 0 ||
                    rotation_axis[1] != 0 || rotation_axis[2] != 0,
                  "Geometry/Rotation axis",
                  0.,
                  "a nonzero vector");
      for (const auto &[name, entries] : registered_entries())
        entries.parse(prm, *this, dim);
    }
    prm.leave_subsection();

    const bool simplices = (cell_shape == CellShape::simplex);
    // FE_SimplexP of deal.II 9.4 has degrees 1 and 2 only.
    check_entry(!simplices || fe_degree <= 2,
                "Geometry/Finite element degree",
                fe_degree,
                "1 or 2 with 'Cell shape = simplex'");
    // Gauss-Lobatto nodes and local refinement exist for hypercubes only
    // in deal.II 9.4.
    AssertThrow(!(simplices && mass_matrix == MassMatrix::lumped),
                ExcMessage("Entry 'Geometry/Mass matrix': lumped is "
                           "available for 'Cell shape = hypercube' only; "
                           "allowed with simplices is consistent."));
    check_entry(!simplices || mapping_degree == 1,
                "Geometry/Mapping degree",
                mapping_degree,
                "1 with 'Cell shape = simplex'");
    check_entry(!simplices || refinement_radius == 0.,
                "Geometry/Refinement radius",
                refinement_radius,
                "0 with 'Cell shape = simplex' (local refinement of "
                "simplices is not available)");
    AssertThrow(!simplices || refinement_points.empty(),
                ExcMessage("Entry 'Geometry/Refinement points': allowed is "
                           "none with 'Cell shape = simplex' (local "
                           "refinement of simplices is not available)."));
    // Points with R = 0 would grade nothing without a word.
    check_entry(refinement_points.empty() || refinement_radius > 0.,
                "Geometry/Refinement radius",
                refinement_radius,
                "a radius > 0 where 'Geometry/Refinement points' gives "
                "points (0 switches the grading off: remove the points to "
                "run without it)");
  }


  // @sect3{Boundary conditions}

  void BoundaryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry(
        "Clamped boundary ids",
        "0",
        Patterns::List(Patterns::Integer(0, 254)),
        "Boundary ids of Gamma_1, where u = 0. The box numbers its faces "
        "0: x = x0, 1: x = x1, 2: y = y0, 3: y = y1 (4, 5: z in 3D).");
      prm.declare_entry(
        "Contact boundary ids",
        "2",
        Patterns::List(Patterns::Integer(0, 254)),
        "Boundary ids of Gamma_3: bilateral contact (u.n = 0) with friction.");
      prm.declare_entry(
        "Symmetry boundary ids",
        "",
        Patterns::List(Patterns::Integer(0, 254)),
        "Boundary ids of symmetry planes (rollers): u.n = 0 and no tangential "
        "traction. The paper's block extruded in z with both z faces here is "
        "the 2D plane strain problem.");
      prm.declare_entry(
        "Tractions",
        "3: 0; -600*t",
        Patterns::Anything(),
        "Tractions f_2 on Gamma_2 [N/m^(dim-1)]: 'id: f_x; f_y[; f_z]', several "
        "separated by '|'. Expressions of x, y, z, t (muparser). Boundary "
        "parts not named anywhere are traction free.");
    }
    prm.leave_subsection();
  }

  void BoundaryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      clamped_ids  = parse_boundary_ids(prm.get("Clamped boundary ids"));
      contact_ids  = parse_boundary_ids(prm.get("Contact boundary ids"));
      symmetry_ids = parse_boundary_ids(prm.get("Symmetry boundary ids"));
      tractions.clear();
      for (const std::string &piece :
           Utilities::split_string_list(prm.get("Tractions"), '|'))
        {
          const auto colon = piece.find(':');
          AssertThrow(colon != std::string::npos && colon > 0,
                      ExcMessage("Entry 'Boundary conditions/Tractions': "
                                 "cannot read '" +
                                 piece +
                                 "'; expected 'boundary id: f_x; f_y[; f_z]'"
                                 " with pieces separated by '|'."));
          const std::string id_text = Utilities::trim(piece.substr(0, colon));
          AssertThrow(id_text.find_first_not_of("0123456789") ==
                          std::string::npos &&
                        Utilities::string_to_int(id_text) < 255,
                      ExcMessage("Entry 'Boundary conditions/Tractions': '" +
                                 id_text +
                                 "' is not a boundary id (an integer from 0 "
                                 "to 254)."));
          AssertThrow(tractions.count(Utilities::string_to_int(id_text)) == 0,
                      ExcMessage("Entry 'Boundary conditions/Tractions': "
                                 "boundary id " +
                                 id_text +
                                 " is given twice; allowed is one traction "
                                 "per boundary id."));
          tractions[Utilities::string_to_int(id_text)] =
            Utilities::trim(piece.substr(colon + 1));
        }
    }
    prm.leave_subsection();
  }


  // @sect3{Material}

  const ChoiceTable<MaterialParameters::PlaneModel> &
  MaterialParameters::plane_models()
  {
    static const ChoiceTable<PlaneModel> table(
      "Material/Plane model",
      {{"plane strain", PlaneModel::plane_strain},
       {"plane stress", PlaneModel::plane_stress}});
    return table;
  }

  void MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Density",
                        "1000",
                        Patterns::Double(0),
                        "Mass density rho [kg/m^3]; 0 gives a quasi-static "
                        "problem (no inertia).");
      prm.declare_entry("Young's modulus",
                        "2000",
                        Patterns::Double(),
                        "Young's modulus E [N/m^2] of the elasticity tensor "
                        "B, E > 0.");
      prm.declare_entry("Poisson ratio",
                        "0.3",
                        Patterns::Double(),
                        "Poisson ratio kappa of B, 0 <= kappa < 0.5.");
      prm.declare_entry("Viscosity mu1",
                        "50",
                        Patterns::Double(0),
                        "mu_1 [N s/m^2] in A tau = mu_1 tr(tau) I + mu_2 tau.");
      prm.declare_entry("Viscosity mu2",
                        "100",
                        Patterns::Double(0),
                        "mu_2 [N s/m^2] in A tau = mu_1 tr(tau) I + mu_2 tau.");
      prm.declare_entry(
        "Plane model",
        plane_models().name(PlaneModel::plane_strain),
        plane_models().pattern(),
        "2D only: the paper's formula for B (plane strain) or plane stress, "
        "lambda* = 2 lambda G / (lambda + 2 G).");
    }
    prm.leave_subsection();
  }

  void MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      density        = prm.get_double("Density");
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson ratio");
      viscosity_mu1  = prm.get_double("Viscosity mu1");
      viscosity_mu2  = prm.get_double("Viscosity mu2");
      plane_model    = plane_models().parse(prm.get("Plane model"));
    }
    prm.leave_subsection();

    check_entry(youngs_modulus > 0,
                "Material/Young's modulus",
                youngs_modulus,
                "E > 0");
    check_entry(poisson_ratio >= 0 && poisson_ratio < 0.5,
                "Material/Poisson ratio",
                poisson_ratio,
                "0 <= kappa < 0.5");
  }


  double MaterialParameters::two_G() const
  {
    return youngs_modulus / (1. + poisson_ratio);
  }

  double MaterialParameters::lambda(const unsigned int dim) const
  {
    const double kappa = poisson_ratio;
    const double lambda_3d =
      youngs_modulus * kappa / ((1. + kappa) * (1. - 2. * kappa));
    if (dim == 2 && plane_model == PlaneModel::plane_stress)
      return 2. * lambda_3d * (two_G() / 2.) / (lambda_3d + two_G());
    return lambda_3d;
  }


  // @sect3{Loads and initial values}

  void LoadParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads and initial values");
    {
      prm.declare_entry("Body force",
                        "0; -1e-5",
                        Patterns::Anything(),
                        "Body force f_0 [N/m^dim], 'f_x; f_y[; f_z]' of x, y, "
                        "z, t.");
      prm.declare_entry("Initial displacement",
                        "0; 0",
                        Patterns::Anything(),
                        "u_0 [m], 'u_x; u_y[; u_z]' of x, y, z.");
      prm.declare_entry("Initial velocity",
                        "0; 0",
                        Patterns::Anything(),
                        "u_1 [m/s], 'w_x; w_y[; w_z]' of x, y, z.");
    }
    prm.leave_subsection();
  }

  void LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads and initial values");
    {
      body_force           = prm.get("Body force");
      initial_displacement = prm.get("Initial displacement");
      initial_velocity     = prm.get("Initial velocity");
    }
    prm.leave_subsection();
  }


  // @sect3{Friction}

  void FrictionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(FrictionLaws::subsection);
    {
      // 'Friction law' (its names, default and help text) and the entries of
      // each law come from the registry of the laws
      // (source/base/friction_laws/). The laws' entries follow S, so that the
      // used parameters of a run, printed in the order of declaration, list
      // S next to the law.
      FrictionLaws::declare_law_entry(prm);
      prm.declare_entry("Friction bound S",
                        "100",
                        Patterns::Double(0),
                        "S >= 0 [N/m^(dim-1)]: the slip threshold is mu S "
                        "(3.6).");
      FrictionLaws::declare_parameters(prm);
    }
    prm.leave_subsection();
  }

  void FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(FrictionLaws::subsection);
    {
      bound_S = prm.get_double("Friction bound S");
      law     = FrictionLaws::create(prm.get("Friction law"), prm);
    }
    prm.leave_subsection();
  }


  // @sect3{Time}

  void TimeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    {
      prm.declare_entry("End time", "1.1", Patterns::Double(), "T > 0 [s].");
      prm.declare_entry(
        "Time step",
        "0.0078125",
        Patterns::Double(),
        "Time step k [s], 0 < k <= T. The run takes N = ceil(T/k) steps of the "
        "uniform size T/N, so that the last step ends at T.");
      prm.declare_entry(
        "Max steps",
        "1000000",
        Patterns::Integer(1, std::numeric_limits<int>::max()),
        "The largest N = ceil(T/k) a run accepts: a guard against a mistyped "
        "Time step that would run for days. Raise it for longer runs.");
    }
    prm.leave_subsection();
  }

  void TimeParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    {
      end_time  = prm.get_double("End time");
      time_step = prm.get_double("Time step");
      max_steps = prm.get_integer("Max steps");
    }
    prm.leave_subsection();

    check_entry(std::isfinite(end_time) && end_time > 0,
                "Time/End time",
                end_time,
                "T > 0");
    check_entry(std::isfinite(time_step) && time_step > 0 &&
                  time_step <= end_time,
                "Time/Time step",
                time_step,
                "0 < k <= Time/End time");
    // In floating point: ceil(T/k) may exceed every unsigned integer.
    const double       steps = std::ceil(end_time / time_step - 1e-9);
    std::ostringstream allowed;
    allowed << std::setprecision(6)
            << "k >= T / (Time/Max steps) = " << end_time / max_steps
            << " (here N = ceil(T/k) = " << steps
            << " steps against Time/Max steps = " << max_steps
            << "; raise Max steps if the run is meant to be that long)";
    check_entry(steps <= max_steps, "Time/Time step", time_step, allowed.str());
  }

  // N = ceil(T/k) steps of the uniform size T/N, so that the last step ends
  // at T (the paper's T = 1.1 is not a multiple of its k = 1/128).
  unsigned int TimeParameters::n_steps() const
  {
    return static_cast<unsigned int>(std::ceil(end_time / time_step - 1e-9));
  }


  // @sect3{Solver}

  const ChoiceTable<SolverParameters::LinearSolver> &
  SolverParameters::linear_solvers()
  {
    static const ChoiceTable<LinearSolver> table(
      Entry::linear_solver,
      {{"auto", LinearSolver::automatic},
       {"CHOLMOD", LinearSolver::cholmod},
       {"Amesos_Klu", LinearSolver::amesos_klu},
       {"Amesos_Mumps", LinearSolver::amesos_mumps},
       {"Amesos_Lapack", LinearSolver::amesos_lapack},
       {"CG-AMG", LinearSolver::cg_amg}});
    return table;
  }

  const ChoiceTable<SolverParameters::ContactSolver> &
  SolverParameters::contact_solvers()
  {
    static const ChoiceTable<ContactSolver> table(
      Entry::contact_solver,
      {{"auto", ContactSolver::automatic},
       {"Delassus", ContactSolver::delassus},
       {"constraints", ContactSolver::constraints}});
    return table;
  }

  const ChoiceTable<SolverParameters::FrictionMethod> &
  SolverParameters::friction_methods()
  {
    static const ChoiceTable<FrictionMethod> table(
      Entry::friction_method,
      {{"Newton", FrictionMethod::newton},
       {"convexification", FrictionMethod::convexification}});
    return table;
  }

  void SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.declare_entry(
        "Convexification tolerance",
        "1e-12",
        Patterns::Double(0),
        "The convexification stops when the slip rates on Gamma_3 change by "
        "less than this, relative to the largest tangential velocity, and the "
        "slip set does not change.");
      prm.declare_entry(
        "Friction method",
        friction_methods().name(FrictionMethod::newton),
        friction_methods().pattern(),
        "How the nonmonotone friction problem of a step is solved. Newton: "
        "a semismooth Newton method on the full law, with the derivative of "
        "the friction coefficient in its Jacobian (on the constraints path "
        "the solver gets the matrix with the weakening capped below the "
        "convexity limit, positive definite, and the true slopes enter by a "
        "low-rank correction), a line search with sufficient decrease of "
        "the step's energy from the previous step's forces, and a "
        "convexification step (a Tresca problem) where the Newton step does "
        "not lower it. An end point beyond the convexity limit must pass a "
        "test of the energy's curvature (a local minimum, not a saddle); "
        "where it does not, or where Newton does not converge within 'Max "
        "Newton iterations', the convexification solves the step. "
        "convexification: the paper's fixed point, one Tresca "
        "problem per iteration (with Anderson acceleration), solved by the "
        "primal-dual active set method; it is the fallback of Newton. Both "
        "find the same solution where the step problem has one; where it "
        "has several (S (a - b) alpha above the convexity limit printed at "
        "start-up) both start with the same Tresca step from the previous "
        "step's state and may then end on different local minima: Newton "
        "returns the one its descent on the step's energy reaches "
        "(doc/algorithm.md), and its summary line counts the steps beyond "
        "the convexity limit and the steps the convexification took over.");
      prm.declare_entry("Max Newton iterations",
                        "50",
                        Patterns::Integer(1),
                        "Iteration limit of the Newton method per step; "
                        "then the convexification takes over.");
      prm.declare_entry("Max convexification iterations",
                        "200",
                        Patterns::Integer(2),
                        "Iteration limit of the convexification per step (at "
                        "least 2: it stops when the slip set repeats).");
      prm.declare_entry("Max active set iterations",
                        "500",
                        Patterns::Integer(1),
                        "Iteration limit of the primal-dual active set "
                        "method per Tresca problem. Usually a few suffice; "
                        "a nearly incompressible material (Poisson ratio "
                        "0.4999) needed 218 in one step of the paper's "
                        "scene at h = k = 1/16 (bench/extremes.py).");
      prm.declare_entry(
        "Active set parameter",
        "0.05",
        Patterns::Double(0),
        "c_p / K_pp in z_p = eta_p + c_p w_tau,p; 0.01 to 0.1 avoids the "
        "cycling at slip onset seen with c_p = K_pp.");
      prm.declare_entry(
        "Anderson depth",
        "5",
        Patterns::Integer(0, 20),
        "Number of previous iterates that Anderson acceleration of the "
        "convexification combines; 0 gives the paper's plain iteration. An "
        "accelerated iterate that does not lower the step's energy is "
        "rejected.");
      prm.declare_entry(
        "Linear solver",
        linear_solvers().name(LinearSolver::automatic),
        linear_solvers().pattern(),
        "How systems with K = (rho/k) M + A + k B are solved. CHOLMOD "
        "(SuiteSparse's supernodal Cholesky, one process) or a Trilinos "
        "Amesos solver (Amesos_Mumps: MUMPS, distributed over the processes) "
        "factorise K once per run; CG-AMG: conjugate gradients with Trilinos "
        "ML's algebraic multigrid (built once per run), for meshes whose "
        "factor does not fit, relative residual " +
          number_text(SolverParameters::cg_relative_residual) +
          ". auto: CHOLMOD on one process, Amesos_Mumps on more.");
      prm.declare_entry(
        "Step cuts",
        "0",
        Patterns::Integer(0, 20),
        "When the convexification or the active set method of a step does "
        "not converge, take the step again as two steps of k/2 (refactorising "
        "K), each of which may be cut again, at most this many times in a "
        "row; then k is restored. 0: a step that does not converge ends the "
        "run with its diagnostic. The console reports every cut and "
        "time_series.csv counts them (column step_cuts).");
      prm.declare_entry(
        "Contact solver",
        contact_solvers().name(ContactSolver::automatic),
        contact_solvers().pattern(),
        "How the friction problem of a step is solved. Delassus: on the "
        "tangential unknowns of Gamma_3 alone, with the dense Delassus "
        "operator D = C K^{-1} C^T built once per run: from "
        "Y = L^{-1} P C^T (sparse; K = P^T L L^T P by CHOLMOD), a step then "
        "costs one forward and one backward substitution and dense work on "
        "Gamma_3; with the other linear solvers from Z = K^{-1} C^T (dense, "
        "one solve per tangential unknown of Gamma_3), a step then costs one "
        "solve and a product with Z. constraints: the straightforward path; "
        "every Newton step of the active set method solves on the whole "
        "body with the sticking nodes held fixed as constraints, and "
        "refactorises; no D. auto: Delassus while Gamma_3 has at most " +
          std::to_string(SolverParameters::max_delassus_unknowns) +
          " tangential unknowns (the dense Newton steps cost O(n^3) in their "
          "number n) and, without CHOLMOD, the linear solver is direct and Z "
          "fits in " +
          number_text(SolverParameters::max_delassus_bytes / 1e9) +
          " GB per process; constraints otherwise.");
    }
    prm.leave_subsection();
  }

  void SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      convexification_tolerance = prm.get_double("Convexification tolerance");
      max_convexification_iterations =
        prm.get_integer("Max convexification iterations");
      max_active_set_iterations = prm.get_integer("Max active set iterations");
      active_set_parameter      = prm.get_double("Active set parameter");
      anderson_depth            = prm.get_integer("Anderson depth");
      linear_solver   = linear_solvers().parse(prm.get("Linear solver"));
      contact_solver  = contact_solvers().parse(prm.get("Contact solver"));
      friction_method = friction_methods().parse(prm.get("Friction method"));
      max_newton_iterations = prm.get_integer("Max Newton iterations");
      step_cuts             = prm.get_integer("Step cuts");
    }
    prm.leave_subsection();

    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (linear_solver == LinearSolver::automatic)
      linear_solver =
        (n_processes == 1 ? LinearSolver::cholmod : LinearSolver::amesos_mumps);
    iterative_linear_solver = (linear_solver == LinearSolver::cg_amg);

    check_entry(convexification_tolerance > 0,
                "Solver/Convexification tolerance",
                convexification_tolerance,
                "a tolerance > 0");
    check_entry(active_set_parameter > 0,
                "Solver/Active set parameter",
                active_set_parameter,
                "a value > 0");
    AssertThrow(linear_solver != LinearSolver::cholmod || n_processes == 1,
                ExcMessage("'Solver/Linear solver = CHOLMOD' runs on one MPI "
                           "process; on " +
                           std::to_string(n_processes) +
                           " processes choose auto or an Amesos solver "
                           "(Amesos_Mumps distributes the factor)."));
  }


  // @sect3{Verification}

  const ChoiceTable<VerificationParameters::Solution> &
  VerificationParameters::solutions()
  {
    static const ChoiceTable<Solution> table(
      Entry::manufactured_solution,
      {{"none", Solution::none}, {"slip front", Solution::slip_front}});
    return table;
  }

  void VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    {
      prm.declare_entry(
        "Manufactured solution",
        solutions().name(Solution::none),
        solutions().pattern(),
        "slip front: solve for the exact solution of ManufacturedSolution "
        "(a stick zone x < 1/2 and a slip zone x > 1/2 on Gamma_3 = {y = 0}, "
        "Gamma_1 = {x = 0}); body force, tractions of all sides but Gamma_1 "
        "and Gamma_3, a tangential load on Gamma_3 and the initial values are "
        "then computed from it (the entries for them are ignored), and the "
        "errors are reported.");
      prm.declare_entry("Amplitude",
                        "0.1",
                        Patterns::Double(0),
                        "A in u = A (t + t^2/2) U(x) [m/s]; the slip rate on "
                        "Gamma_3 reaches A (1 + t)/8.");
    }
    prm.leave_subsection();
  }

  void VerificationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    {
      manufactured_solution =
        solutions().parse(prm.get("Manufactured solution"));
      amplitude = prm.get_double("Amplitude");
    }
    prm.leave_subsection();
  }


  // @sect3{Convergence study}

  const ChoiceTable<ConvergenceStudyParameters::Refine> &
  ConvergenceStudyParameters::refinements()
  {
    static const ChoiceTable<Refine> table("Convergence study/Refine",
                                           {{"space and time",
                                             Refine::space_and_time},
                                            {"space", Refine::space},
                                            {"time", Refine::time}});
    return table;
  }

  void ConvergenceStudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    {
      prm.declare_entry(
        "Levels",
        "0",
        Patterns::Integer(0, 12),
        "0: one run. n > 0: n + 1 runs, starting from Geometry/Cell size and "
        "Time/Time step and halving what 'Refine' says from one run to the "
        "next (a mesh read from a Mesh file gets one more global refinement "
        "per level instead, and h is its largest cell diameter); a table of "
        "the errors (against a manufactured solution, or else against the "
        "finest level) and their rates is printed at the end.");
      prm.declare_entry("Refine",
                        refinements().name(Refine::space_and_time),
                        refinements().pattern(),
                        "What is halved from one level to the next.");
      prm.declare_entry(
        "Reference degree",
        "0",
        Patterns::Integer(0, 4),
        "Without a manufactured solution the finest level is the reference; "
        "this is its element degree (0: the degree of the levels). A richer "
        "reference lets studies with different degrees share one reference "
        "(work-precision).");
    }
    prm.leave_subsection();
  }

  void ConvergenceStudyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    {
      levels           = prm.get_integer("Levels");
      reference_degree = prm.get_integer("Reference degree");
      refine           = refinements().parse(prm.get("Refine"));
    }
    prm.leave_subsection();
  }


  // @sect3{Mesh adaptation}

  const std::array<std::string, 3> &MeshAdaptationParameters::indicator_names()
  {
    static const std::array<std::string, 3> names = {
      {"displacement", "velocity", "slip rate"}};
    return names;
  }

  void MeshAdaptationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      prm.declare_entry(
        "Cycles",
        "0",
        Patterns::Integer(0, 20),
        "0: the mesh of the Geometry. n > 0: n pilot runs of the whole scene "
        "(each in its own directory adaptation-cycle-c), each on the mesh its "
        "predecessor refined and coarsened from the 'Indicators', taken at "
        "at most 20 steps spread over the run and kept as their largest; "
        "then the scene runs on the adapted mesh. The pilots write "
        "indicators_0.pvtu; adapted_mesh.txt holds the mesh's cycles (every "
        "checkpoint stores them too: --resume runs on them without the "
        "pilots).");
      prm.declare_entry(
        "Interval",
        "0",
        Patterns::Integer(0),
        "0: the mesh does not change during the run. n > 0: after every n-th "
        "step the mesh is refined and coarsened from the 'Indicators' of that "
        "step, u and w are carried over to the new mesh, K is assembled and "
        "factorised again, and the change of the kinetic and elastic energy "
        "that the transfer makes enters the energy balance. adaptation.csv "
        "lists the adaptations (with the energy before and after each), "
        "adapted_mesh.txt the mesh's cycles, and with 'Output/VTU interval' "
        "> 0 indicators_<step>.pvtu the indicators and the cells chosen; a "
        "checkpoint stores the mesh.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the largest "
                        "indicators, refined per cycle (or per adaptation "
                        "during the run).");
      prm.declare_entry("Coarsen fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the smallest "
                        "indicators, coarsened per cycle (never coarser than "
                        "the Geometry's coarsest cells).");
      prm.declare_entry(
        "Target unknowns",
        "0",
        Patterns::Integer(0),
        "0: refine by 'Refine fraction'. n > 0: refine as many cells per "
        "cycle as multiply the unknowns by equal factors to about n at the "
        "last cycle. During the run ('Interval' > 0, which then needs "
        "'Coarsen fraction' > 0): refine by 'Refine fraction' up to about n "
        "unknowns, and from there only as many cells as the coarsening frees, "
        "so that the mesh keeps about n unknowns and still follows the "
        "solution. Without a target, each adaptation during the run refines "
        "'Refine fraction' of the cells, up to 'Max levels'.");
      prm.declare_entry(
        "Indicators",
        "displacement",
        Patterns::MultipleSelection("displacement|velocity|slip rate"),
        "What chooses the cells: Kelly's indicator of the displacement, of "
        "the velocity, and the variation of the slip rate over the faces of "
        "Gamma_3 (each as a share of its worst cell; a cell's indicator is "
        "the largest of its shares). The default gave the smallest V-error "
        "at T per unknown on the paper's scene (bench/adapted_mesh.md).");
      prm.declare_entry("Max levels",
                        "4",
                        Patterns::Integer(0, 12),
                        "Cells are refined at most this many times beyond "
                        "the Geometry's coarsest cells.");
    }
    prm.leave_subsection();
  }

  void MeshAdaptationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      cycles           = prm.get_integer("Cycles");
      interval         = prm.get_integer("Interval");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      target_unknowns  = prm.get_integer("Target unknowns");
      max_levels       = prm.get_integer("Max levels");
      const std::vector<std::string> chosen =
        Utilities::split_string_list(prm.get("Indicators"));
      for (unsigned int i = 0; i < indicators.size(); ++i)
        indicators[i] =
          std::find(chosen.begin(), chosen.end(), indicator_names()[i]) !=
          chosen.end();
    }
    prm.leave_subsection();
    AssertThrow((cycles == 0 && interval == 0) || indicators[0] ||
                  indicators[1] || indicators[2],
                ExcMessage("Entry '" + Entry::indicators +
                           "' is empty: allowed is one or more of "
                           "displacement, velocity, slip rate."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1,
                ExcMessage("Entries '" + Entry::refine_fraction +
                           "' = " + number_text(refine_fraction) + " and '" +
                           Entry::coarsen_fraction +
                           "' = " + number_text(coarsen_fraction) +
                           ": allowed is a sum of at most 1."));
  }


  // @sect3{Accuracy}

  const ChoiceTable<AccuracyParameters::TargetErrorType> &
  AccuracyParameters::target_error_types()
  {
    static const ChoiceTable<TargetErrorType> table(
      Entry::target_error_type,
      {{"relative", TargetErrorType::relative},
       {"absolute", TargetErrorType::absolute}});
    return table;
  }

  const ChoiceTable<AccuracyParameters::CostModel> &
  AccuracyParameters::cost_models()
  {
    static const ChoiceTable<CostModel> table(
      Entry::cost_model,
      {{"measured", CostModel::measured},
       {"unknowns times steps", CostModel::unknowns_times_steps}});
    return table;
  }

  void AccuracyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Accuracy");
    {
      prm.declare_entry(
        "Estimate error",
        "false",
        Patterns::Bool(),
        "Also run the scene with h and k doubled, quadrupled and (where "
        "the mesh allows) multiplied by 8 (into <Output directory>/coarse-1, "
        "coarse-2 and coarse-3; in 2D they cost about 1/8, 1/64 and 1/512 "
        "of the run) and report the estimated error of this run at T: in "
        "the V-norm, in the probe displacements, the friction dissipation, "
        "the slipping share of Gamma_3, where its slip zone starts and the "
        "time of the first slip, each by Richardson extrapolation with the "
        "orders measured between consecutive runs. A row without "
        "consistent orders gets no estimate and says why. The table goes to "
        "the console and to <Output directory>/error_estimate.txt. On a mesh "
        "adapted by pilots the coarse runs are that mesh coarsened cell by "
        "cell; a run adapted during itself runs again from the coarser "
        "meshes of the Geometry, adapting at about the same times (the "
        "interval scaled with k and rounded) towards 1/2^dim (1/4^dim, ...) "
        "of its 'Target unknowns', and is compared at T only.");
      prm.declare_entry(
        "Separate space and time",
        "false",
        Patterns::Bool(),
        "With 'Estimate error': also run with 2h and 4h at k and with 2k "
        "and 4k at h (coarse-space-1, -2, coarse-time-1, -2; in 2D about "
        "1/4, 1/16, 1/2 and 1/4 of the run) and split every estimate into "
        "the part that halving h removes and the part that halving k does, "
        "each extrapolated with its own order; a row's estimate is their "
        "sum where that is larger. Needed where the orders in h and k "
        "differ (degree 2).");
      prm.declare_entry(
        "Target error",
        "0",
        Patterns::Double(0),
        "0: off. Otherwise the error in 'Target quantity' (by default the "
        "largest V-error over time) that the program picks the element "
        "degree (1 or 2), h and k for: pilot runs "
        "on the scene's h and k and on 2h, 4h, 2k, 4k (<Output "
        "directory>/pilot-*) measure how the error falls with h and with k "
        "and what a run costs; the cheapest run predicted within half the "
        "target then runs, with its error estimate (as 'Estimate error'). "
        "A scene that adapts its mesh during the run ('Mesh "
        "adaptation/Interval' > 0) adds pilots adapted during the run from "
        "H, 2H, 4H, and chooses between uniform and adapted meshes (for "
        "every 'Target quantity' but the largest V-error over time). "
        "The choice and the predicted and estimated errors are printed and "
        "written to <Output directory>/target.txt.");
      prm.declare_entry("Target error type",
                        target_error_types().name(TargetErrorType::relative),
                        target_error_types().pattern(),
                        "relative: 'Target error' times the size of the "
                        "quantity on the first pilot (for the V-norm "
                        "||eps(u_h)||, at T or its largest over time); "
                        "absolute: in the quantity's units.");
      prm.declare_entry(
        "Target quantity",
        worst_V_error,
        Patterns::Anything(),
        "The quantity whose error 'Target error' bounds: '" + worst_V_error +
          "' (the largest V-error ||eps(u - u_h)|| over the times t = 4Kj), "
          "or at T: 'V-norm of u', 'friction dissipation', 'probe <i> u_x' "
          "(u_y, u_z) of the i-th 'Output/Probe points' entry, 'slipping "
          "share of Gamma_3' or 'slip zone starts at x'; or the 'time of the "
          "first slip'.");
      prm.declare_entry("Cost model",
                        cost_models().name(CostModel::measured),
                        cost_models().pattern(),
                        "How the target predicts what a run costs: from "
                        "the pilots' measured wall times (a + b unknowns "
                        "steps, per degree), or unknowns times steps "
                        "(the same choice on every machine).");
      prm.declare_entry("Maximum predicted time",
                        "0",
                        Patterns::Double(0),
                        "0: no limit. Otherwise the longest predicted wall "
                        "time [s] of the run that 'Target error' chooses "
                        "(with its estimate's coarse runs, from the "
                        "pilots' measured wall times: needs 'Cost model' = "
                        "measured). Beyond it the program stops before "
                        "that run and says what it would have chosen.");
    }
    prm.leave_subsection();
  }

  void AccuracyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Accuracy");
    {
      estimate_error          = prm.get_bool("Estimate error");
      separate_space_and_time = prm.get_bool("Separate space and time");
      target_error            = prm.get_double("Target error");
      target_error_type =
        target_error_types().parse(prm.get("Target error type"));
      target_quantity    = Quantity::parse(prm.get("Target quantity"));
      cost_model         = cost_models().parse(prm.get("Cost model"));
      max_predicted_time = prm.get_double("Maximum predicted time");
    }
    prm.leave_subsection();
  }


  // @sect3{Output}

  std::vector<OutputParameters::OwnEntry> &
  OutputParameters::registered_entries()
  {
    static std::vector<OwnEntry> entries;
    return entries;
  }

  bool OutputParameters::register_entry(const OwnEntry &entry)
  {
    registered_entries().push_back(entry);
    return true;
  }

  void OutputParameters::parse_own_entries(ParameterHandler &prm,
                                           const Parameters &parameters)
  {
    prm.enter_subsection("Output");
    for (const OwnEntry &own : registered_entries())
      own_values[own.entry] = own.parse(prm, parameters);
    prm.leave_subsection();
  }

  // An entry of a postprocessor may follow another one's.
  void OutputParameters::declare_entries_after(ParameterHandler  &prm,
                                               const std::string &name)
  {
    for (const OwnEntry &own : registered_entries())
      if (own.after == name)
        {
          own.declare(prm);
          declare_entries_after(prm, own.entry);
        }
  }

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    // After each entry, those of the postprocessors that follow it.
    const auto declare_entry = [&prm](const std::string           &name,
                                      const std::string           &value,
                                      const Patterns::PatternBase &pattern,
                                      const std::string           &help) {
      prm.declare_entry(name, value, pattern, help);
      declare_entries_after(prm, name);
    };
    prm.enter_subsection("Output");
    {
      declare_entry("Output directory",
                    "results-barboteu2015",
                    Patterns::Anything(),
                    "Directory for VTU/PVD, time_series.csv and "
                    "parameters.prm, relative to where the program runs. "
                    "A run that is not resumed replaces the results of "
                    "an earlier run there (its VTU/PVD, time series, "
                    "Gamma_3 history, parameters, checkpoints, error "
                    "estimate with its coarse-* runs and a study's table "
                    "with its level-N); one run at a time "
                    "may use it (the lock file .lock names the run).");
      // Read by parse_report_times(): deal.II's Patterns::List splits its
      // text in a time quadratic in its length (400 000 times: 65 s).
      declare_entry("Report times",
                    "0.3, 1.1",
                    Patterns::Anything(),
                    "Times [s] > 0, separated by ',', at which the stick/slip "
                    "state of Gamma_3 is printed (at the nearest step), at "
                    "most " +
                      std::to_string(max_report_times) + ".");
      declare_entry("Probe points",
                    "",
                    Patterns::Anything(),
                    "Points 'x, y[, z]' separated by ';' whose "
                    "displacement is written to time_series.csv "
                    "(columns probe<i>_u_x, ...). On a shell a point "
                    "between its radii that the cells miss by the "
                    "geometry error of their curved boundary is taken "
                    "at the nearest point of the cell around it.");
      declare_entry("Print timings",
                    "true",
                    Patterns::Bool(),
                    "Print the wall time summary at the end (switch off "
                    "for tests).");
      declare_entry("Checkpoint interval",
                    "0",
                    Patterns::Integer(0),
                    "Write a checkpoint (output directory/checkpoint) "
                    "every this many steps, and at the end; 0: by steps "
                    "never.");
      declare_entry("Checkpoint minutes",
                    "0",
                    Patterns::Double(0),
                    "Write a checkpoint when this many minutes of wall "
                    "time have passed since the last one, and at the "
                    "end; 0: by time never.");
      declare_entry(
        "Resume",
        "false",
        Patterns::Bool(),
        "Continue the run from the checkpoint in the output directory "
        "(the command line option --resume sets this). The scene must be the "
        "same; a later 'Time/End time' with the same time step extends a "
        "finished run. time_series.csv and solution.pvd are cut back to the "
        "checkpoint's step.");
    }
    prm.leave_subsection();
  }

  void OutputParameters::parse_parameters(ParameterHandler  &prm,
                                          const unsigned int dim)
  {
    prm.enter_subsection("Output");
    {
      directory    = Utilities::trim(prm.get("Output directory"));
      report_times = parse_report_times(prm.get("Report times"));
      probe_points =
        parse_points(prm.get("Probe points"), dim, "Output/Probe points");
      print_timings       = prm.get_bool("Print timings");
      checkpoint_interval = prm.get_integer("Checkpoint interval");
      checkpoint_minutes  = prm.get_double("Checkpoint minutes");
      resume              = prm.get_bool("Resume");
    }
    prm.leave_subsection();

    AssertThrow(!directory.empty(),
                ExcMessage("The entry 'Output/Output directory' is empty: "
                           "allowed is a directory name."));
    // The used parameters are written to <directory>/parameters.prm, where
    // '#' would start a comment and a newline end the entry.
    AssertThrow(directory.find_first_of("#\n\\") == std::string::npos,
                ExcMessage("The entry 'Output/Output directory' = '" +
                           directory +
                           "' contains '#', '\\' or a line break, which "
                           "parameters.prm cannot hold; allowed is a "
                           "directory name without them."));
    for (const double t : report_times)
      check_entry(t > 0,
                  "Output/Report times",
                  t,
                  "times t > 0 (t = 0 is the initial state; times after "
                  "'Time/End time' are reported at the last step)");
  }


  // @sect3{All parameters}

  void Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the problem, 2 or 3.");
    GeometryParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    FrictionParameters::declare_parameters(prm);
    TimeParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
    ConvergenceStudyParameters::declare_parameters(prm);
    AccuracyParameters::declare_parameters(prm);
    MeshAdaptationParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
  }

  // A mesh adaptation refines the cells of p4est's forest by their ids,
  // and runs the scene as it is several times: not as a level of a study
  // (yet), nor as a target's pilot (those adapt during the run). An error
  // estimate runs a mesh adapted by pilots coarsened, and a run adapted during
  // itself again from coarser meshes (scene_variant.cc).
  void Parameters::check_mesh_adaptation() const
  {
    if (mesh_adaptation.cycles == 0 && mesh_adaptation.interval == 0)
      {
        AssertThrow(mesh_adaptation.target_unknowns == 0,
                    ExcMessage("Entry '" + Entry::target_unknowns + "' = " +
                               std::to_string(mesh_adaptation.target_unknowns) +
                               " is the size of an adapted mesh, but nothing "
                               "adapts the mesh: allowed with it is '" +
                               Entry::adaptation_cycles + "' > 0 or '" +
                               Entry::adaptation_interval + "' > 0 (or " +
                               Entry::target_unknowns + " = 0)."));
        return;
      }
    const std::string adapting =
      mesh_adaptation.cycles > 0 ?
        "Entry '" + Entry::adaptation_cycles +
          "' = " + std::to_string(mesh_adaptation.cycles) +
          " adapts the mesh: " :
        "Entry '" + Entry::adaptation_interval +
          "' = " + std::to_string(mesh_adaptation.interval) +
          " adapts the mesh during the run: ";
    AssertThrow(mesh_adaptation.cycles == 0 || mesh_adaptation.interval == 0,
                ExcMessage(adapting + "it cannot be combined with '" +
                           Entry::adaptation_interval +
                           "' = " + std::to_string(mesh_adaptation.interval) +
                           " yet; allowed is one of the two, the other 0."));
    // Settings under which the mesh cannot change at all.
    check_entry(mesh_adaptation.max_levels > 0,
                Entry::max_levels,
                mesh_adaptation.max_levels,
                "at least 1 where the mesh adapts (with 0 no cell may be "
                "refined, and none coarser than the Geometry's)");
    if (mesh_adaptation.interval > 0)
      check_entry(mesh_adaptation.interval < time.n_steps(),
                  Entry::adaptation_interval,
                  mesh_adaptation.interval,
                  "0 or below the run's " + std::to_string(time.n_steps()) +
                    " steps (the mesh adapts after every n-th step but "
                    "the last)");
    AssertThrow(geometry.cell_shape != GeometryParameters::CellShape::simplex,
                ExcMessage(adapting +
                           "it refines quadrilaterals and "
                           "hexahedra only; allowed with it is '" +
                           Entry::cell_shape + "' = hypercube."));
    // An error estimate runs a mesh adapted by pilots coarsened, cell by
    // cell (MeshPlan::coarser()), which gives nested meshes for plans that
    // refine only.
    AssertThrow(!accuracy.estimate_error || mesh_adaptation.cycles == 0 ||
                  mesh_adaptation.coarsen_fraction == 0,
                ExcMessage(adapting + "with '" + Entry::estimate_error +
                           "' its coarse runs are the adapted mesh coarsened, "
                           "which is only defined for meshes that the pilots "
                           "refined; allowed with it is '" +
                           Entry::coarsen_fraction + "' = 0."));
    // During the run, a mesh that keeps its size at the target must give
    // cells back to refine others.
    AssertThrow(mesh_adaptation.interval == 0 ||
                  mesh_adaptation.target_unknowns == 0 ||
                  mesh_adaptation.coarsen_fraction > 0,
                ExcMessage(
                  adapting + "with '" + Entry::target_unknowns +
                  "' = " + std::to_string(mesh_adaptation.target_unknowns) +
                  " the mesh keeps about that size once it has "
                  "reached it, and can then follow the solution only "
                  "by coarsening where it refines; allowed with it is "
                  "'" +
                  Entry::coarsen_fraction + "' > 0."));
    AssertThrow(convergence_study.levels == 0,
                ExcMessage(adapting + "it cannot be combined with '" +
                           Entry::levels + "' yet; allowed are '" +
                           Entry::adaptation_cycles + "' = 0 and '" +
                           Entry::adaptation_interval + "' = 0 there."));
    // A target's 'Target unknowns' is the size of the scene's degree's
    // adapted mesh, scaled for the other of the degrees 1 and 2 that it
    // compares.
    check_entry(accuracy.target_error == 0 ||
                  mesh_adaptation.target_unknowns == 0 ||
                  geometry.fe_degree <= 2,
                Entry::finite_element_degree,
                geometry.fe_degree,
                "1 or 2 with '" + Entry::target_error + "' > 0 and '" +
                  Entry::target_unknowns +
                  "' > 0 (the target compares degrees 1 and 2, and scales "
                  "'" +
                  Entry::target_unknowns +
                  "' from the scene's degree to the other)");
    // A target compares uniform meshes with meshes adapted during the run
    // (target_error.cc); the pilots' adaptation would need its own cycles
    // at each candidate h.
    AssertThrow(accuracy.target_error == 0 || mesh_adaptation.cycles == 0,
                ExcMessage(adapting + "it cannot be combined with '" +
                           Entry::target_error +
                           "' yet, which chooses between uniform meshes and "
                           "meshes adapted during the run; allowed are '" +
                           Entry::adaptation_cycles + "' = 0 (with '" +
                           Entry::adaptation_interval +
                           "' > 0 for the adapted ones) or '" +
                           Entry::target_error + "' = 0."));
  }


  // An error estimate runs the scene twice more, with h and k doubled and
  // quadrupled, and a target's pilots do so in h and in k separately: the
  // coarse meshes must exist, and the runs are separate (not a study, not
  // a resumed run).
  void Parameters::check_error_estimate() const
  {
    const bool target = accuracy.target_error > 0;
    AssertThrow(accuracy.estimate_error || target ||
                  !accuracy.separate_space_and_time,
                ExcMessage("Entry '" + Entry::separate_space_and_time +
                           "' = true splits an error estimate: allowed with "
                           "it is '" +
                           Entry::estimate_error + "' = true or '" +
                           Entry::target_error + "' > 0."));
    AssertThrow(accuracy.max_predicted_time == 0 ||
                  (target && accuracy.cost_model ==
                               AccuracyParameters::CostModel::measured),
                ExcMessage("Entry '" + Entry::max_predicted_time +
                           "' = " + number_text(accuracy.max_predicted_time) +
                           " limits the run that a target chooses by its "
                           "predicted wall time: allowed with it are '" +
                           Entry::target_error + "' > 0 and '" +
                           Entry::cost_model + "' = " +
                           AccuracyParameters::cost_models().name(
                             AccuracyParameters::CostModel::measured) +
                           " (or 0 for no limit)."));
    if (target)
      {
        check_target_quantity();
        // The nearest valid steps: T / N for the multiples N of 4 around
        // the N = ceil(T / k) that the entry gives.
        const unsigned int n     = time.n_steps();
        const unsigned int below = std::max(4u, n / 4 * 4);
        check_entry(
          n % 4 == 0,
          Entry::time_step,
          time.time_step,
          "a step that divides '" + Entry::end_time +
            "' into a multiple of 4 steps with '" + Entry::target_error +
            "' > 0 (the pilots run with 2k and 4k on the same "
            "time grid); this one gives " +
            std::to_string(n) + " steps, the nearest valid ones are T/" +
            std::to_string(below) + " = " + number_text(time.end_time / below) +
            " and T/" + std::to_string(below + 4) + " = " +
            number_text(time.end_time / (below + 4)));
      }
    if (!accuracy.estimate_error && !target)
      return;
    const std::string mode = target ? "'" + Entry::target_error + "' > 0" :
                                      "'" + Entry::estimate_error + "' = true";
    AssertThrow(convergence_study.levels == 0 && !output.resume,
                ExcMessage("Entry " + mode +
                           " runs one scene with its error estimate; "
                           "allowed with it are '" +
                           Entry::levels + "' = 0 and no --resume ('" +
                           Entry::resume + "' = false)" +
                           (target ? std::string(".") :
                                     "; a run killed before its estimate "
                                     "resumes with '" +
                                       Entry::estimate_error +
                                       "' = false, and continues without "
                                       "it.")));
    // The geometry knows how its h is set, and so which meshes of 2h and
    // 4h exist.
    create_geometry(*this)->check_coarse_runs(mode);
  }

  // A probe's quantity needs the probe: the target must be one of this
  // scene's quantities.
  void Parameters::check_target_quantity() const
  {
    const std::string target = accuracy.target_quantity.name();
    bool              found  = false;
    std::string       list;
    for (const Quantity &quantity :
         Quantity::of_scene(output.probe_points.size(), dimension))
      {
        found = found || quantity.name() == target;
        list += (list.empty() ? "'" : ", '") + quantity.name() + "'";
      }
    AssertThrow(found,
                ExcMessage(
                  "Entry '" + Entry::target_quantity + "' = '" + target +
                  "' is not a quantity of this scene; allowed: " + list + "."));
    // Found out before the pilots run: a closed Gamma_3 has no start of
    // its slip zone, and its x has no scale of its own.
    if (accuracy.target_quantity.kind != Quantity::Kind::slip_zone_start)
      return;
    AssertThrow(!create_geometry(*this)->gamma3_is_closed(),
                ExcMessage("Entry '" + Entry::target_quantity + "' = '" +
                           target +
                           "' is not defined on a shell (its Gamma_3 is a "
                           "closed circle); allowed there are the others of " +
                           list + "."));
    AssertThrow(accuracy.target_error_type ==
                  AccuracyParameters::TargetErrorType::absolute,
                ExcMessage("Entry '" + Entry::target_error_type +
                           "': a relative target on '" + target +
                           "' would depend on where x = 0 is; allowed for "
                           "it is absolute (a length in m)."));
  }

  void Parameters::parse_parameters(ParameterHandler &prm)
  {
    dimension = prm.get_integer("Dimension");
    // A build for one dimension (the CMake option CONTACT_DIMENSIONS) has
    // no ContactProblem of the other.
    AssertThrow(is_compiled_dimension(dimension),
                ExcMessage("Entry 'Dimension' = " + std::to_string(dimension) +
                           ": this build of the program is compiled for "
                           "the dimensions '" +
                           compiled_dimensions() +
                           "' only (CMake option CONTACT_DIMENSIONS); "
                           "allowed here is " +
                           compiled_dimensions() +
                           ", or a build configured with "
                           "-DCONTACT_DIMENSIONS=\"2;3\" (the default)."));
    geometry.parse_parameters(prm, dimension);
    boundary.parse_parameters(prm);
    material.parse_parameters(prm);
    loads.parse_parameters(prm);
    friction.parse_parameters(prm);
    time.parse_parameters(prm);
    solver.parse_parameters(prm);
    verification.parse_parameters(prm);
    convergence_study.parse_parameters(prm);
    accuracy.parse_parameters(prm);
    mesh_adaptation.parse_parameters(prm);
    output.parse_parameters(prm, dimension);

    // On a P2 triangle the integral of a vertex basis function is zero:
    // the nodal friction weights m_p of Gamma_3 would vanish at the vertices.
    AssertThrow(!(dimension == 3 &&
                  geometry.cell_shape ==
                    GeometryParameters::CellShape::simplex &&
                  geometry.fe_degree > 1 && !friction.law->is_frictionless()),
                ExcMessage("Entry 'Geometry/Finite element degree': P" +
                           std::to_string(geometry.fe_degree) +
                           " on tetrahedra gives zero nodal friction weights "
                           "at the vertices of Gamma_3 (positive lumped "
                           "weights were tried and give only first order in "
                           "the V-norm); allowed with friction in 3D are "
                           "degree 1 on simplices or any degree on "
                           "hexahedra."));

    AssertThrow(material.density > 0 || !boundary.clamped_ids.empty(),
                ExcMessage("Entry 'Boundary conditions/Clamped boundary ids' "
                           "is empty while 'Material/Density' = 0: the "
                           "quasi-static problem has no inertia and nothing "
                           "that holds the body against rigid motions. "
                           "Allowed: at least one clamped boundary id, or a "
                           "density > 0."));
    output.parse_own_entries(prm, *this);
    AssertThrow(!(output.resume && convergence_study.levels > 0),
                ExcMessage("Entry 'Output/Resume' (--resume): a convergence "
                           "study ('Convergence study/Levels' > 0) cannot be "
                           "resumed; allowed is Resume = false there."));
    check_error_estimate();
    check_mesh_adaptation();

    // The parameters a run writes run it again from its start: a resumed
    // run computes what the run without the break computes
    // (verification/kill_and_resume), and its checkpoint may be gone.
    const auto set_resume = [&](const bool resume) {
      prm.enter_subsection("Output");
      prm.set("Resume", resume);
      prm.leave_subsection();
    };
    set_resume(false);
    std::ostringstream text;
    prm.print_parameters(text,
                         ParameterHandler::ShortPRM |
                           ParameterHandler::KeepDeclarationOrder);
    used_parameters = text.str();
    set_resume(output.resume);
  }


  // @sect3{Expressions}

  bool expression_uses_variable(const std::string &expression,
                                const std::string &variable)
  {
    const auto is_name_character = [](const char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (std::size_t i = 0; i < expression.size();)
      {
        if (!is_name_character(expression[i]))
          {
            ++i;
            continue;
          }
        std::size_t end = i;
        while (end < expression.size() && is_name_character(expression[end]))
          ++end;
        if (expression.compare(i, end - i, variable) == 0 &&
            end - i == variable.size())
          return true;
        i = end;
      }
    return false;
  }


  // deal.II's FunctionParser reports a muparser error as an exception whose
  // text says nothing about where the expression came from; evaluating the
  // function once here turns every such error into one that names the
  // entry. Components are counted first, since a missing ';' would
  // otherwise surface as a dimension mismatch deep inside deal.II.
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_vector_function(const std::string &entry,
                        const std::string &expression,
                        const bool         time_dependent)
  {
    const std::string variables =
      std::string(dim == 2 ? "x,y" : "x,y,z") + (time_dependent ? ",t" : "");
    const std::string allowed = "'" + std::to_string(dim) +
                                " expressions separated by ';' in the "
                                "variables " +
                                variables + "'";
    const unsigned int n_components =
      Utilities::split_string_list(expression, ';').size();
    AssertThrow(n_components == dim,
                ExcMessage("The entry '" + entry + "' = '" + expression +
                           "' has " + std::to_string(n_components) +
                           " components; allowed is " + allowed + "."));

    // deal.II also writes muparser's diagnosis to std::cerr; it is
    // swallowed here, since the exception below says the same with the
    // entry's name.
    auto               function = std::make_unique<FunctionParser<dim>>(dim);
    std::ostringstream muparser_diagnosis;
    std::streambuf *cerr_buffer = std::cerr.rdbuf(muparser_diagnosis.rdbuf());
    try
      {
        function->initialize(variables, expression, {}, time_dependent);
        Vector<double> value(dim);
        function->vector_value(Point<dim>(), value);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (ExceptionBase &exc)
      {
        std::cerr.rdbuf(cerr_buffer);
        std::ostringstream reason;
        exc.print_info(reason);
        AssertThrow(false,
                    ExcMessage(
                      "The entry '" + entry + "' = '" + expression +
                      "' cannot be evaluated; allowed is " + allowed +
                      ". muparser says: " + Utilities::trim(reason.str())));
      }
    return function;
  }

#define INSTANTIATE(dim)                                                    \
  template std::unique_ptr<FunctionParser<dim>> parse_vector_function<dim>( \
    const std::string &, const std::string &, const bool);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
