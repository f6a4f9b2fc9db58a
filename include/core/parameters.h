/**
 * Parameters of a run, one struct per subsection of the .prm file (the
 * step-44 / Lethe habit). Every entry carries a Pattern with its allowed
 * range and a documentation string with units; each struct's
 * parse_parameters() checks its entries (check_entry() names the entry
 * and the allowed range), Parameters::parse_parameters() the checks that
 * involve entries of several subsections, and Geometry::create_mesh()
 * those that need the mesh. A Selection entry is an enum class with its
 * ChoiceTable. The entries of one geometry alone are declared and parsed
 * by that geometry (source/core/box.cc, source/parts/<geometry>/), those of a
 * part by the part: a part declares, parses and checks its own entries
 * (PartEntries, base/parts.h).
 */
#ifndef contact_parameters_h
#define contact_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <base/choice_table.h>
#include <core/friction_laws.h>
#include <base/parts.h>

#include <any>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /** A number as the messages and help texts print it (6 significant
   *  digits: 1e-12, 0.05, 2000). */
  std::string number_text(const double value);

  /** Unless `condition`: the error "Invalid value <value> for the entry
   *  '<entry>': allowed is <allowed>." (entry as "Subsection/Entry"). */
  void check_entry(const bool         condition,
                   const std::string &entry,
                   const double       value,
                   const std::string &allowed);

  /** Points 'x, y[, z]' separated by ';', each of exactly dim numbers;
   *  otherwise an error that names the entry and the point. */
  std::vector<std::vector<double>> parse_points(const std::string &text,
                                                const unsigned int dim,
                                                const std::string &entry);

  /**
   * The entries that code outside parameters.cc names, as
   * "Subsection/Entry": in error messages, in the overrides of a
   * convergence study's levels and in the checkpoint's list of entries that
   * must not change. One definition each, so that renaming an entry is
   * this line and its declaration; unit/entry_paths checks that every one
   * of them is declared. A part's own entries are constants of this
   * namespace in the part's header.
   */
  namespace Entry
  {
    inline const std::string lower_corner = "Geometry/Lower corner";
    inline const std::string upper_corner = "Geometry/Upper corner";
    inline const std::string cell_size    = "Geometry/Cell size";
    inline const std::string cell_shape   = "Geometry/Cell shape";
    inline const std::string finite_element_degree =
      "Geometry/Finite element degree";
    inline const std::string mesh_file         = "Geometry/Mesh file";
    inline const std::string mesh_refinements  = "Geometry/Mesh refinements";
    inline const std::string domain            = "Geometry/Domain";
    inline const std::string mapping_degree    = "Geometry/Mapping degree";
    inline const std::string refinement_points = "Geometry/Refinement points";
    inline const std::string refinement_radius = "Geometry/Refinement radius";
    inline const std::string rotation_angle    = "Geometry/Rotation angle";
    inline const std::string clamped_boundary_ids =
      "Boundary conditions/Clamped boundary ids";
    inline const std::string contact_boundary_ids =
      "Boundary conditions/Contact boundary ids";
    inline const std::string tractions      = "Boundary conditions/Tractions";
    inline const std::string density        = "Material/Density";
    inline const std::string youngs_modulus = "Material/Young's modulus";
    inline const std::string poisson_ratio  = "Material/Poisson ratio";
    inline const std::string body_force = "Loads and initial values/Body force";
    inline const std::string initial_displacement =
      "Loads and initial values/Initial displacement";
    inline const std::string initial_velocity =
      "Loads and initial values/Initial velocity";
    inline const std::string friction_bound_S = "Friction/Friction bound S";
    inline const std::string end_time         = "Time/End time";
    inline const std::string time_step        = "Time/Time step";
    inline const std::string max_steps        = "Time/Max steps";
    inline const std::string convexification_tolerance =
      "Solver/Convexification tolerance";
    inline const std::string max_convexification_iterations =
      "Solver/Max convexification iterations";
    inline const std::string max_active_set_iterations =
      "Solver/Max active set iterations";
    inline const std::string active_set_parameter =
      "Solver/Active set parameter";
    inline const std::string anderson_depth      = "Solver/Anderson depth";
    inline const std::string linear_solver       = "Solver/Linear solver";
    inline const std::string step_cuts           = "Solver/Step cuts";
    inline const std::string contact_solver      = "Solver/Contact solver";
    inline const std::string friction_method     = "Solver/Friction method";
    inline const std::string output_directory    = "Output/Output directory";
    inline const std::string time_series         = "Output/Time series";
    inline const std::string vtu_interval        = "Output/VTU interval";
    inline const std::string gamma3_history      = "Output/Gamma3 history";
    inline const std::string report_times        = "Output/Report times";
    inline const std::string probe_points        = "Output/Probe points";
    inline const std::string checkpoint_interval = "Output/Checkpoint interval";
    inline const std::string checkpoint_minutes  = "Output/Checkpoint minutes";
    inline const std::string resume              = "Output/Resume";
    inline const std::string manufactured_solution =
      "Verification/Manufactured solution";
  } // namespace Entry

  struct Parameters;

  /**
   * The subsection Geometry: the entries that every geometry shares. The
   * entries of one geometry alone are its own (PartEntries, base/parts.h):
   * it declares, parses and checks them in its file (source/core/box.cc,
   * source/parts/<geometry>/).
   */
  struct GeometryParameters
  {
    /** A gmsh .msh file; empty: the geometry of `domain`. */
    std::string  mesh_file;
    unsigned int mesh_refinements;
    /** 'Geometry/Domain': the name of a registered geometry
     *  (GeometryBaseRegistry, core/geometry_base.h), e.g. "box". */
    std::string domain;
    /** Degree of the polynomial mapping of the cells: 2 and more follow a
     *  curved boundary (the shell's circles) between the nodes. */
    unsigned int mapping_degree;
    /** Quadrilaterals/hexahedra with Q_p, or triangles/tetrahedra with
     *  P_p. */
    enum class CellShape
    {
      hypercube,
      simplex
    };
    CellShape    cell_shape;
    unsigned int fe_degree;
    /** Gauss quadrature, or Gauss-Lobatto at the nodes: a diagonal M. */
    enum class MassMatrix
    {
      consistent,
      lumped
    };
    MassMatrix mass_matrix;
    /** Points towards which the mesh is refined, each of dim coordinates. */
    std::vector<std::vector<double>> refinement_points;
    double                           refinement_radius;
    double                           refinement_grading;
    /** Rotation of the whole mesh about the origin [degrees], about the
     *  z axis in 2D and about `rotation_axis` in 3D. */
    double              rotation_angle;
    std::vector<double> rotation_axis;

    /** The names of the choices of 'Cell shape' and 'Mass matrix'. */
    static const ChoiceTable<CellShape>  &cell_shapes();
    static const ChoiceTable<MassMatrix> &mass_matrices();

    /** Declares the shared entries, and after each of them the entries of
     *  the geometries that follow it. */
    static void declare_parameters(ParameterHandler &prm);
    /** Reads the shared entries; the geometries' own entries are parsed
     *  after them (Parameters::parse_parameters()). */
    void parse_parameters(ParameterHandler &prm, const unsigned int dim);
    /** The checks of the shared entries that come after the geometries'
     *  own: what simplices do not allow. */
    void check_simplices() const;
  };

  struct BoundaryParameters
  {
    std::vector<types::boundary_id> clamped_ids;
    std::vector<types::boundary_id> contact_ids;
    std::vector<types::boundary_id> symmetry_ids;
    /** Boundary id -> traction expression "f_x; f_y[; f_z]" of x,y,z,t. */
    std::map<types::boundary_id, std::string> tractions;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  struct MaterialParameters
  {
    double density;
    double youngs_modulus;
    double poisson_ratio;
    double viscosity_mu1;
    double viscosity_mu2;
    /** 2D only: the paper's B (plane strain), or plane stress. */
    enum class PlaneModel
    {
      plane_strain,
      plane_stress
    };
    PlaneModel plane_model;

    /** The names of the choices of 'Plane model'. */
    static const ChoiceTable<PlaneModel> &plane_models();

    /** 2G = E/(1 + kappa) of the elasticity tensor B. */
    double two_G() const;
    /**
     * lambda = E kappa/((1 + kappa)(1 - 2 kappa)) of B (the paper's formula,
     * plane strain in 2D), or 2 lambda G/(lambda + 2G) for plane stress.
     */
    double lambda(const unsigned int dim) const;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  struct LoadParameters
  {
    std::string body_force;
    std::string initial_displacement;
    std::string initial_velocity;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  struct FrictionParameters
  {
    /** The law of 'Friction law' with its own entries read and checked
     *  (FrictionLaws::LawRegistry); copies of the parameters share it. */
    std::shared_ptr<const FrictionLaws::Interface> law;
    double                                         bound_S;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  struct TimeParameters
  {
    double       end_time;
    double       time_step;
    unsigned int max_steps;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
    /** N = ceil(T/k), checked against max_steps when parsed. */
    unsigned int n_steps() const;
  };

  struct SolverParameters
  {
    double       convexification_tolerance;
    unsigned int max_convexification_iterations;
    unsigned int max_active_set_iterations;
    double       active_set_parameter;
    unsigned int anderson_depth;
    /** How systems with K are solved: the name of a registered linear
     *  solver (Factorization::create()), 'auto' resolved. */
    std::string linear_solver;
    /** Halvings of k allowed for a step that does not converge. */
    unsigned int step_cuts;
    /** The path between the body and Gamma_3: 'auto' or the name of a
     *  registered path (FrictionSolver::choose_path()). */
    std::string contact_solver = "auto";
    /** The name of a registered friction method (friction_method.h). */
    std::string friction_method;

    /** 'Contact solver = auto' takes the Delassus path up to this many
     *  tangential unknowns n of Gamma_3 (D and W = D^{-1} are dense: 16 n^2
     *  bytes, 1 GB here, on every process, and about as much again while D
     *  is built), and without CHOLMOD only while Z = K^{-1} C^T
     *  takes at most this many bytes per process. The help texts state
     *  both. */
    static constexpr unsigned int max_delassus_unknowns = 7900;
    static constexpr double       max_delassus_bytes    = 1e9;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  struct VerificationParameters
  {
    /** Replace loads and initial values by those of ManufacturedSolution
     *  (slip_front), or not (none). */
    enum class Solution
    {
      none,
      slip_front
    };
    Solution manufactured_solution;
    double   amplitude;

    bool manufactured() const
    {
      return manufactured_solution != Solution::none;
    }

    /** The names of the choices of 'Manufactured solution'. */
    static const ChoiceTable<Solution> &solutions();

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  /**
   * The subsection Output: the entries that several parts of the program
   * read. Those that one postprocessor alone reads are its own
   * (PartEntries, base/parts.h).
   */
  struct OutputParameters
  {
    std::string         directory;
    std::vector<double> report_times;
    /** Points whose displacement goes into time_series.csv. */
    std::vector<std::vector<double>> probe_points;
    bool                             print_timings;
    /** Write a checkpoint every this many steps / minutes; 0: never. */
    unsigned int checkpoint_interval;
    double       checkpoint_minutes;
    /** Continue from the checkpoint in the output directory. */
    bool resume;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  struct Parameters
  {
    unsigned int           dimension;
    GeometryParameters     geometry;
    BoundaryParameters     boundary;
    MaterialParameters     material;
    LoadParameters         loads;
    FrictionParameters     friction;
    TimeParameters         time;
    SolverParameters       solver;
    VerificationParameters verification;
    OutputParameters       output;

    /** The values of the parts' own entries (PartEntries, base/parts.h),
     *  as each part's parse() returned them, by the part's name. */
    std::map<std::string, std::any> part_values;

    /** The value of the entries of the part `name`. */
    template <class Value>
    const Value &part(const std::string &name) const
    {
      return std::any_cast<const Value &>(part_values.at(name));
    }

    /** The .prm text of all entries as they were used, for the results. */
    std::string used_parameters;
    /** Not an entry: set for the run that a target chose
     *  (parameters_of()), which keeps the pilots in its directory; its
     *  parameters.prm, run again, is a plain run. */
    bool keeps_pilots = false;

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
  };

  /**
   * A dim-component muparser function of x, y[, z] (and t if
   * time_dependent) from an expression 'f_x; f_y[; f_z]' of the .prm entry
   * named `entry`. Syntax errors, unknown variables and a wrong number of
   * components are reported with the entry and the expression.
   */
  /** Whether the muparser expression uses the variable (as a whole name). */
  bool expression_uses_variable(const std::string &expression,
                                const std::string &variable);

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_vector_function(const std::string &entry,
                        const std::string &expression,
                        const bool         time_dependent);
} // namespace Contact

#endif
