/* The entries of the scene (.prm subsections Geometry, Boundary
   conditions, Material, Loads, Friction and Time): declaration, parsing
   and the checks of each subsection alone. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <core/geometry_base.h>
#include <core/parameters.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Contact
{
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
  } // namespace


  // @sect3{Geometry}

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

  namespace
  {
    // Declares an entry of Geometry, and after it the entries of the
    // geometries that follow it.
    using EntryDeclarer =
      std::function<void(const std::string           &name,
                         const std::string           &value,
                         const Patterns::PatternBase &pattern,
                         const std::string           &help)>;

    // The mesh: its source, its cells and its finite element.
    void declare_mesh_entries(const EntryDeclarer &declare_entry)
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
      // The registered geometries (source/core/box.cc,
      // source/parts/<geometry>/), the box first.
      const unsigned int n_geometries = GeometryBaseRegistry::parts().size();
      declare_entry(
        "Domain",
        "box",
        Patterns::Selection(GeometryBaseRegistry::selection(Entry::domain)),
        GeometryBaseRegistry::help_text() + ". A Mesh file " +
          (n_geometries == 2 ? "replaces both." : "replaces each of them."));
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
        GeometryParameters::cell_shapes().name(
          GeometryParameters::CellShape::hypercube),
        GeometryParameters::cell_shapes().pattern(),
        "hypercube: quadrilaterals/hexahedra with Q_p elements; simplex: "
        "every box cell split into triangles (2) or tetrahedra (5), with "
        "P_p elements (FE_SimplexP).");
      declare_entry("Finite element degree",
                    "1",
                    Patterns::Integer(1, 4),
                    "Polynomial degree of the Lagrange elements Q_p.");
      declare_entry("Mass matrix",
                    GeometryParameters::mass_matrices().name(
                      GeometryParameters::MassMatrix::consistent),
                    GeometryParameters::mass_matrices().pattern(),
                    "consistent: Gauss quadrature; lumped: Gauss-Lobatto "
                    "quadrature at the nodes, a diagonal M.");
    }

    // What changes the mesh: the grading towards points and the rotation.
    void declare_refinement_entries(const EntryDeclarer &declare_entry)
    {
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
  } // namespace


  // The entries that every geometry shares; after each, those of the
  // geometries that follow it (source/core/box.cc, source/parts/<geometry>/).
  void GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    const EntryDeclarer declare_entry =
      [&prm](const std::string           &name,
             const std::string           &value,
             const Patterns::PatternBase &pattern,
             const std::string           &help) {
        prm.declare_entry(name, value, pattern, help);
        Parts::declare_entries_after(prm, "Geometry", name);
      };
    prm.enter_subsection("Geometry");
    {
      declare_mesh_entries(declare_entry);
      declare_refinement_entries(declare_entry);
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
      domain             = prm.get("Domain");
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
    }
    prm.leave_subsection();
  }

  void GeometryParameters::check_simplices() const
  {
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
    using FrictionLaws::LawRegistry;
    prm.enter_subsection(FrictionLaws::subsection);
    {
      // 'Friction law' (its names and help text) and the entries of each
      // law come from the registered laws (source/core/slip_rate_weakening.cc,
      // source/parts/friction_laws/). The laws' entries follow S, so that the
      // used parameters of a run, printed in the order of declaration, list S
      // next to the law.
      prm.declare_entry(FrictionLaws::law_entry,
                        "slip rate weakening",
                        Patterns::Selection(LawRegistry::selection(
                          FrictionLaws::entry_path(FrictionLaws::law_entry))),
                        LawRegistry::help_text() + ".");
      prm.declare_entry("Friction bound S",
                        "100",
                        Patterns::Double(0),
                        "S >= 0 [N/m^(dim-1)]: the slip threshold is mu S "
                        "(3.6).");
      Parts::declare_entries_after(prm,
                                   FrictionLaws::subsection,
                                   "Friction bound S");
    }
    prm.leave_subsection();
  }

  void FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(FrictionLaws::subsection);
    {
      bound_S = prm.get_double("Friction bound S");
      law     = FrictionLaws::LawRegistry::create(FrictionLaws::entry_path(
                                                FrictionLaws::law_entry),
                                              prm.get(FrictionLaws::law_entry),
                                              prm);
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
} // namespace Contact
