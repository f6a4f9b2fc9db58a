/* The .prm's entries as a whole: every subsection declared and parsed in
   order, the checks that involve entries of several subsections, and the
   muparser expressions. Each subsection's own entries are in
   scene_parameters.cc (the scene), solver_parameters.cc (the solvers and
   the verification), study_parameters.cc (the studies) and
   output_parameters.cc (the output). */

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


  namespace
  {
    // Where the mesh adapts (`adapting` names the entry that makes it do
    // so): what the other entries, the drivers' among them, must allow.
    void check_adaptation_combinations(const Parameters  &parameters,
                                       const std::string &adapting)
    {
      // An error estimate runs a mesh adapted by pilots coarsened, cell by
      // cell (MeshPlan::coarser()), which gives nested meshes for plans that
      // refine only.
      AssertThrow(!parameters.accuracy.estimate_error ||
                    parameters.mesh_adaptation.cycles == 0 ||
                    parameters.mesh_adaptation.coarsen_fraction == 0,
                  ExcMessage(
                    adapting + "with '" + Entry::estimate_error +
                    "' its coarse runs are the adapted mesh coarsened, "
                    "which is only defined for meshes that the pilots "
                    "refined; allowed with it is '" +
                    Entry::coarsen_fraction + "' = 0."));
      // During the run, a mesh that keeps its size at the target must give
      // cells back to refine others.
      AssertThrow(parameters.mesh_adaptation.interval == 0 ||
                    parameters.mesh_adaptation.target_unknowns == 0 ||
                    parameters.mesh_adaptation.coarsen_fraction > 0,
                  ExcMessage(
                    adapting + "with '" + Entry::target_unknowns + "' = " +
                    std::to_string(parameters.mesh_adaptation.target_unknowns) +
                    " the mesh keeps about that size once it has "
                    "reached it, and can then follow the solution only "
                    "by coarsening where it refines; allowed with it is "
                    "'" +
                    Entry::coarsen_fraction + "' > 0."));
      AssertThrow(parameters.convergence_study.levels == 0,
                  ExcMessage(adapting + "it cannot be combined with '" +
                             Entry::levels + "' yet; allowed are '" +
                             Entry::adaptation_cycles + "' = 0 and '" +
                             Entry::adaptation_interval + "' = 0 there."));
      // A target's 'Target unknowns' is the size of the scene's degree's
      // adapted mesh, scaled for the other of the degrees 1 and 2 that it
      // compares.
      check_entry(parameters.accuracy.target_error == 0 ||
                    parameters.mesh_adaptation.target_unknowns == 0 ||
                    parameters.geometry.fe_degree <= 2,
                  Entry::finite_element_degree,
                  parameters.geometry.fe_degree,
                  "1 or 2 with '" + Entry::target_error + "' > 0 and '" +
                    Entry::target_unknowns +
                    "' > 0 (the target compares degrees 1 and 2, and scales "
                    "'" +
                    Entry::target_unknowns +
                    "' from the scene's degree to the other)");
      // A target compares uniform meshes with meshes adapted during the run
      // (target_error.cc); the pilots' adaptation would need its own cycles
      // at each candidate h.
      AssertThrow(parameters.accuracy.target_error == 0 ||
                    parameters.mesh_adaptation.cycles == 0,
                  ExcMessage(adapting + "it cannot be combined with '" +
                             Entry::target_error +
                             "' yet, which chooses between uniform meshes and "
                             "meshes adapted during the run; allowed are '" +
                             Entry::adaptation_cycles + "' = 0 (with '" +
                             Entry::adaptation_interval +
                             "' > 0 for the adapted ones) or '" +
                             Entry::target_error + "' = 0."));
    }
  } // namespace


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
    check_adaptation_combinations(*this, adapting);
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
    prm.enter_subsection("Geometry");
    part_values.merge(Parts::parse_entries(prm, "Geometry", *this));
    prm.leave_subsection();
    geometry.check_simplices();
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
    prm.enter_subsection("Output");
    part_values.merge(Parts::parse_entries(prm, "Output", *this));
    prm.leave_subsection();
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
