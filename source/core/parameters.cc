/* The .prm's entries as a whole: every subsection declared and parsed in
   order, the checks that involve entries of several subsections, and the
   muparser expressions. Each subsection's own entries are in
   scene_parameters.cc (the scene), solver_parameters.cc (the solvers and
   the verification) and output_parameters.cc (the output); the parts
   (base/parts.h) declare, parse and check theirs, whole subsections among
   them. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <base/dimensions.h>
#include <core/parameters.h>

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
    Parts::declare_entries_after(prm, "", "Verification");
    OutputParameters::declare_parameters(prm);
    Parts::declare_unbuilt_entries(prm);
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
    Parts::refuse_unbuilt_entries(prm);
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
    prm.enter_subsection("Solver");
    part_values.merge(Parts::parse_entries(prm, "Solver", *this));
    prm.leave_subsection();
    verification.parse_parameters(prm);
    part_values.merge(Parts::parse_entries(prm, "", *this));
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
    Parts::check_entries(*this);

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
