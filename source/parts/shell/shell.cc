/* The shell: its entries and its mesh. */

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>

#include <base/dimensions.h>
#include <parts/shell/shell.h>

#include <algorithm>
#include <any>
#include <cmath>

namespace Contact
{
  namespace
  {
    // @sect4{The entries of the shell}

    void declare_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Inner radius",
                        "0.5",
                        Patterns::Double(0),
                        "Inner radius of the shell [m].");
      prm.declare_entry("Outer radius",
                        "1",
                        Patterns::Double(0),
                        "Outer radius of the shell [m].");
      prm.declare_entry("Shell length",
                        "0.25",
                        Patterns::Double(0),
                        "Length of the tube along z in 3D [m].");
      prm.declare_entry("Cells around",
                        "8",
                        Patterns::Integer(3, 1000),
                        "Cells of the shell's coarse mesh around the circle "
                        "(one layer across the wall; in 3D as many along z "
                        "as keep the cells about as long as wide).");
    }

    // Cells far thinner than wide make K singular to working precision:
    // on prm/bushing_3d.prm a width 4000 times the length along z passes
    // the self-checks, 39 000 times fails them.
    void check_aspect_ratio(const ShellParameters &shell,
                            const unsigned int     dim)
    {
      const double max_aspect_ratio = 1e4;
      const double cell_width =
        2 * numbers::PI * shell.inner_radius / shell.cells_around;
      const std::string thinnest = number_text(cell_width / max_aspect_ratio);
      const std::string why =
        " (1e-4 of a coarse cell's width 2 pi r / 'Cells around' = " +
        number_text(cell_width) +
        "; thinner cells make the stiffness matrix singular to working "
        "precision)";
      check_entry(shell.outer_radius - shell.inner_radius >=
                    cell_width / max_aspect_ratio,
                  Entry::outer_radius,
                  shell.outer_radius,
                  "a radius at least " + thinnest +
                    " above the Inner radius (here " +
                    number_text(shell.outer_radius - shell.inner_radius) +
                    " above)" + why);
      check_entry(dim == 2 ||
                    shell.shell_length >= cell_width / max_aspect_ratio,
                  Entry::shell_length,
                  shell.shell_length,
                  "a length of at least " + thinnest + why);
    }

    // Checked where the shell is the domain. Its circles are a manifold
    // about the origin (about the z axis in 3D): a rotated mesh would
    // leave it.
    std::any parse_entries(ParameterHandler &prm, const Parameters &parameters)
    {
      ShellParameters shell;
      shell.inner_radius   = prm.get_double("Inner radius");
      shell.outer_radius   = prm.get_double("Outer radius");
      shell.shell_length   = prm.get_double("Shell length");
      shell.cells_around   = prm.get_integer("Cells around");
      const auto &geometry = parameters.geometry;
      if (geometry.domain != "shell")
        return shell;
      const unsigned int dim        = parameters.dimension;
      const std::string  with_shell = " with '" + Entry::domain + " = shell'";
      AssertThrow(geometry.mesh_file.empty(),
                  ExcMessage("Entry '" + Entry::domain +
                             "': shell does not go with a '" +
                             Entry::mesh_file +
                             "' (the file is the domain); allowed with a "
                             "mesh file is box."));
      check_entry(shell.outer_radius > shell.inner_radius,
                  Entry::outer_radius,
                  shell.outer_radius,
                  "a radius above the Inner radius, " +
                    Utilities::to_string(shell.inner_radius));
      check_entry(shell.inner_radius > 0,
                  Entry::inner_radius,
                  shell.inner_radius,
                  "r > 0" + with_shell);
      check_entry(dim == 2 || shell.shell_length > 0,
                  Entry::shell_length,
                  shell.shell_length,
                  "a length > 0" + with_shell + " in 3D");
      check_aspect_ratio(shell, dim);
      check_entry(geometry.rotation_angle == 0,
                  Entry::rotation_angle,
                  geometry.rotation_angle,
                  "0" + with_shell);
      AssertThrow(geometry.cell_shape ==
                    GeometryParameters::CellShape::hypercube,
                  ExcMessage("Entry '" + Entry::domain +
                             "': shell is built of quadrilaterals/hexahedra; "
                             "allowed with 'Cell shape = simplex' is box."));
      return shell;
    }

    // Second in 'Domain'. Its entries are declared after 'Domain': their
    // place in doc/parameters.prm.
    const GeometryRegistration<Shell> registration(
      "shell",
      20,
      "the annulus (2D) or the tube along z from z = 0 to the Shell length "
      "(3D) between the Inner and the Outer radius around the origin, Cells "
      "around the circle, refined Mesh refinements times along the circles "
      "(boundary ids 0 inner, 1 outer, 2 z = 0, 3 z = length)",
      {"Geometry", "Domain", "Cells around", declare_entries, parse_entries});
  } // namespace


  template <int dim>
  Shell<dim>::Shell(const Parameters &run_parameters,
                    const MPI_Comm    mpi_communicator)
    : Geometry<dim>(run_parameters, mpi_communicator)
    , shell(run_parameters.part<ShellParameters>("shell"))
  {}


  // @sect4{Shell::create_coarse_mesh}

  // deal.II's shell with its spherical (2D) or cylindrical (3D) manifold,
  // so that refinement puts new vertices on the circles and a mapping of
  // degree 2 or more curves the cells' edges along them.
  template <int dim>
  unsigned int Shell<dim>::create_coarse_mesh(Triangulation<dim> &mesh) const
  {
    const auto  &geometry = this->parameters.geometry;
    const double inner = shell.inner_radius, outer = shell.outer_radius;
    // In 3D as many cells along z as keep them about as long as wide, at
    // most max_axial_cells (the count is formed as a double first: a cast
    // of a huge length to unsigned would be undefined).
    const double cell_width = 2 * numbers::PI * inner / shell.cells_around;
    const double axial      = std::round(shell.shell_length / cell_width);
    const unsigned int max_axial_cells = 10000;
    check_entry(dim == 2 || axial <= max_axial_cells,
                Entry::shell_length,
                shell.shell_length,
                "a length of at most " +
                  number_text(max_axial_cells * cell_width) + " (" +
                  std::to_string(max_axial_cells) +
                  " cells along the axis, each about as long as wide at "
                  "this 'Inner radius' and 'Cells around')");
    const unsigned int n_axial =
      dim == 2 ? 1 : std::max(1u, static_cast<unsigned int>(axial));
    const double cells = std::pow(2., dim * geometry.mesh_refinements) *
                         shell.cells_around * n_axial;
    this->check_memory(cells,
                       dim * cells * std::pow(geometry.fe_degree, dim),
                       Entry::mesh_refinements);
    if constexpr (dim == 2)
      GridGenerator::hyper_shell(
        mesh, Point<dim>(), inner, outer, shell.cells_around, true);
    else
      {
        GridGenerator::cylinder_shell(
          mesh, shell.shell_length, inner, outer, shell.cells_around, n_axial);
        // By the faces' vertices, which lie on the circles (a face's center
        // lies inside its circle, for few cells around below the middle
        // radius even on the outer one).
        const double length = shell.shell_length;
        for (const auto &face : mesh.active_face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> center = face->center();
              double           radius = 0;
              for (const unsigned int v : face->vertex_indices())
                radius =
                  std::max(radius,
                           std::hypot(face->vertex(v)[0], face->vertex(v)[1]));
              face->set_boundary_id(
                std::abs(center[2]) < 1e-10 * length          ? 2 :
                std::abs(center[2] - length) < 1e-10 * length ? 3 :
                radius < (inner + outer) / 2                  ? 0 :
                                                                1);
            }
      }
    return geometry.mesh_refinements;
  }


  // @sect4{Shell::contains}

  // The shell's cells only approximate its circles (a polygon, or
  // polynomials through points of them), so its radii decide, to 1e-6 of
  // the outer radius (a shell is not rotated).
  template <int dim>
  bool Shell<dim>::contains(const Point<dim> &point,
                            const Triangulation<dim> &) const
  {
    const double slack = 1e-6 * shell.outer_radius;
    const double r     = std::hypot(point[0], point[1]);
    return r >= shell.inner_radius - slack && r <= shell.outer_radius + slack &&
           (dim == 2 || (point[dim - 1] >= -slack &&
                         point[dim - 1] <= shell.shell_length + slack));
  }


#define INSTANTIATE(dim) template class Shell<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
