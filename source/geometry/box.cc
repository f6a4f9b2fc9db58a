/* The box: its entries and its mesh. */

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>

#include <base/dimensions.h>
#include <geometry/box.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Contact
{
  namespace
  {
    // @sect4{The entries of the box}

    void declare_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Lower corner of the box Omega [m], dim numbers.");
      prm.declare_entry("Upper corner",
                        "1, 0.5",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the box Omega [m], dim numbers.");
      prm.declare_entry(
        "Cell size",
        "0.0078125",
        Patterns::Double(0),
        "Edge length h of the cells [m]; every edge of the box is divided "
        "into round(length/h) equal parts (the paper's h).");
    }

    // The corners and the cell size are checked where they describe the
    // domain, the box.
    void parse_entries(ParameterHandler   &prm,
                       GeometryParameters &geometry,
                       const unsigned int  dim)
    {
      geometry.lower_corner = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Lower corner")));
      geometry.upper_corner = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Upper corner")));
      geometry.cell_size = prm.get_double("Cell size");
      if (!geometry.is_box())
        return;
      const auto &lower = geometry.lower_corner, &upper = geometry.upper_corner;
      check_entry(lower.size() == dim,
                  Entry::lower_corner,
                  lower.size(),
                  "exactly Dimension numbers");
      check_entry(upper.size() == dim,
                  Entry::upper_corner,
                  upper.size(),
                  "exactly Dimension numbers");
      double shortest_edge = std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        {
          check_entry(upper[d] > lower[d],
                      Entry::upper_corner,
                      upper[d],
                      "a value above the matching " + Entry::lower_corner +
                        " in every coordinate");
          shortest_edge = std::min(shortest_edge, upper[d] - lower[d]);
        }
      check_entry(geometry.cell_size > 0,
                  Entry::cell_size,
                  geometry.cell_size,
                  "h > 0");
      check_entry(geometry.cell_size <= shortest_edge,
                  Entry::cell_size,
                  geometry.cell_size,
                  "h at most the shortest edge of the box, " +
                    Utilities::to_string(shortest_edge));
    }

    // Declared after 'Mapping degree': their place in doc/parameters.prm.
    [[maybe_unused]] const bool registered =
      GeometryParameters::register_entries("box",
                                           {"Mapping degree",
                                            declare_entries,
                                            parse_entries});
  } // namespace


  // @sect4{Box::create_coarse_mesh}

  // Every edge is divided into round(length / h) parts, as the paper
  // divides its boundary "into 1/h equal parts". The coarse mesh is the
  // coarsest box that refines globally into this one: the same cells, but
  // the meshes of a convergence study are then nested (a level's solution
  // is carried onto the reference's nodes exactly) and p4est gets few
  // trees. Tetrahedra are the exception: deal.II 9.4's refinement of
  // tetrahedra degrades them (P1 V-rates 0.79, 0.81 on refined meshes
  // against 0.99, 1.00 on generated ones, measured), so a tetrahedral box
  // is generated at the requested cell size.
  template <int dim>
  unsigned int Box<dim>::create_coarse_mesh(Triangulation<dim> &mesh) const
  {
    const auto &geometry = this->parameters.geometry;
    const bool  simplices =
      (geometry.cell_shape == GeometryParameters::CellShape::simplex);
    // Counted in floating point: a mistyped cell size may give more cells
    // than an unsigned integer holds.
    std::vector<double> parts(dim);
    double              cells = 1, unknowns = dim;
    for (unsigned int d = 0; d < dim; ++d)
      {
        parts[d] = std::max(1.,
                            std::round((geometry.upper_corner[d] -
                                        geometry.lower_corner[d]) /
                                       geometry.cell_size));
        cells *= parts[d];
        unknowns *= parts[d] * geometry.fe_degree + 1;
      }
    this->check_memory(cells, unknowns, Entry::cell_size);
    Point<dim>                lower, upper;
    std::vector<unsigned int> subdivisions(parts.begin(), parts.end());
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = geometry.lower_corner[d];
        upper[d] = geometry.upper_corner[d];
      }
    unsigned int n_refinements = 0;
    while (!(simplices && dim == 3) &&
           std::all_of(subdivisions.begin(),
                       subdivisions.end(),
                       [](const unsigned int n) { return n % 2 == 0; }))
      {
        for (unsigned int &n : subdivisions)
          n /= 2;
        ++n_refinements;
      }
    if (!simplices)
      {
        GridGenerator::subdivided_hyper_rectangle(
          mesh, subdivisions, lower, upper, /*colorize=*/true);
        return n_refinements;
      }
    // deal.II 9.4 cannot colorize the simplex box itself.
    GridGenerator::subdivided_hyper_rectangle_with_simplices(mesh,
                                                             subdivisions,
                                                             lower,
                                                             upper);
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        for (unsigned int d = 0; d < dim; ++d)
          for (const unsigned int side : {0u, 1u})
            if (std::abs(face->center()[d] - (side ? upper : lower)[d]) <
                1e-10 * (upper[d] - lower[d]))
              face->set_boundary_id(2 * d + side);
    return n_refinements;
  }


#define INSTANTIATE(dim) template class Box<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
