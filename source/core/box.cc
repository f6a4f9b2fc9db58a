/* The box: its entries and its mesh. */

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>

#include <base/dimensions.h>
#include <core/box.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

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
    std::any parse_entries(ParameterHandler &prm, const Parameters &parameters)
    {
      BoxParameters box;
      box.lower_corner = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Lower corner")));
      box.upper_corner = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Upper corner")));
      box.cell_size             = prm.get_double("Cell size");
      const unsigned int dim    = parameters.dimension;
      const auto        &shared = parameters.geometry;
      if (!shared.mesh_file.empty() || shared.domain != "box")
        return box;
      const auto &lower = box.lower_corner, &upper = box.upper_corner;
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
      check_entry(box.cell_size > 0, Entry::cell_size, box.cell_size, "h > 0");
      check_entry(box.cell_size <= shortest_edge,
                  Entry::cell_size,
                  box.cell_size,
                  "h at most the shortest edge of the box, " +
                    Utilities::to_string(shortest_edge));
      return box;
    }

    // The core's geometry, first in 'Domain'. Its entries are declared
    // after 'Mapping degree': their place in doc/parameters.prm.
    const GeometryRegistration<Box>
      registration("box",
                   10,
                   "Lower and Upper corner, divided by the Cell size",
                   {"Geometry",
                    "Mapping degree",
                    "Cell size",
                    declare_entries,
                    parse_entries});
  } // namespace


  template <int dim>
  Box<dim>::Box(const Parameters &run_parameters,
                const MPI_Comm    mpi_communicator)
    : Geometry<dim>(run_parameters, mpi_communicator)
    , box(run_parameters.part<BoxParameters>("box"))
  {}


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
        parts[d] =
          std::max(1.,
                   std::round((box.upper_corner[d] - box.lower_corner[d]) /
                              box.cell_size));
        cells *= parts[d];
        unknowns *= parts[d] * geometry.fe_degree + 1;
      }
    this->check_memory(cells, unknowns, Entry::cell_size);
    Point<dim>                lower, upper;
    std::vector<unsigned int> subdivisions(parts.begin(), parts.end());
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = box.lower_corner[d];
        upper[d] = box.upper_corner[d];
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


  // @sect4{The cell size h of the box}

  // Every edge has round(edge / h) cells (Box::create_coarse_mesh()); h is
  // the entry that a variant scales, written with 17 digits so that it
  // reads back as the same double.
  template <int dim>
  long Box<dim>::n_cells(const unsigned int d, const double size) const
  {
    const double edge = box.upper_corner[d] - box.lower_corner[d];
    return static_cast<long>(std::max(1., std::round(edge / size)));
  }


  template <int dim>
  std::map<std::string, std::string>
  Box<dim>::entries_with_h_halved(const int h_halvings) const
  {
    std::ostringstream text;
    text << std::setprecision(17) << std::ldexp(box.cell_size, -h_halvings);
    return {{Entry::cell_size, text.str()}};
  }


  template <int dim>
  std::string Box<dim>::mesh_size_text() const
  {
    std::ostringstream text;
    text << std::setprecision(17) << "h = " << box.cell_size;
    return text.str();
  }


  // The largest of the edges' cell sizes is the h the box has.
  template <int dim>
  double Box<dim>::cell_size(const Triangulation<dim> &,
                             const Mapping<dim> &) const
  {
    double h = 0;
    for (unsigned int d = 0; d < dim; ++d)
      h = std::max(h,
                   (box.upper_corner[d] - box.lower_corner[d]) /
                     n_cells(d, box.cell_size));
    return h;
  }


  // The mesh of 2^doublings h is nested around this one where every edge
  // has a multiple of 2^doublings cells that stays the same count divided.
  template <int dim>
  std::string Box<dim>::coarsening_obstacle(const unsigned int doublings) const
  {
    const double h      = box.cell_size;
    const long   factor = 1L << doublings;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const long n = n_cells(d, h);
        if (n % factor != 0 || n_cells(d, factor * h) != n / factor)
          return "every edge of the box needs a multiple of " +
                 std::to_string(factor) + " cells";
      }
    return "";
  }


  // @sect4{Box::check_coarse_runs}

  // The coarse runs have cells of exactly 2h and 4h only where each edge's
  // number of cells is a multiple of 4 and stays the same count halved.
  template <int dim>
  void Box<dim>::check_coarse_runs(const std::string &mode) const
  {
    const auto edge = [&](const unsigned int d) {
      return box.upper_corner[d] - box.lower_corner[d];
    };
    const auto fits = [&](const unsigned int d, const double size) {
      const long n = n_cells(d, size);
      return n % 4 == 0 && n_cells(d, 2 * size) == n / 2 &&
             n_cells(d, 4 * size) == n / 4;
    };
    // The largest size at most the given one that fits every edge (a
    // quarter of the shortest edge divided by m fits it; the others are
    // tried), as the message's suggestion.
    const auto suggestion = [&]() {
      double shortest = edge(0);
      for (unsigned int d = 1; d < dim; ++d)
        shortest = std::min(shortest, edge(d));
      for (long m = 1; m <= 4096; ++m)
        {
          const double size = shortest / (4 * m);
          bool         all  = size <= box.cell_size * (1 + 1e-12);
          for (unsigned int d = 0; all && d < dim; ++d)
            all = fits(d, size);
          if (all)
            return "; e.g. " + number_text(size) + " fits every edge";
        }
      return std::string();
    };
    for (unsigned int d = 0; d < dim; ++d)
      if (!fits(d, box.cell_size))
        check_entry(false,
                    Entry::cell_size,
                    box.cell_size,
                    "a size that divides every edge of the box into a "
                    "multiple of 4 cells with " +
                      mode + " (the coarse runs have cells of 2h and 4h)" +
                      suggestion() + "; here the edge " +
                      std::string(1, "xyz"[d]) + " of length " +
                      number_text(edge(d)) + " gets " +
                      std::to_string(n_cells(d, box.cell_size)) + " cells");
  }


  // @sect4{Box::check_manufactured_scene}

  // The manufactured solution vanishes on x = 0, has u.n = 0 on y = 0 and
  // its stick/slip front at x = 1/2: the box must start at the origin,
  // clamp its face x = 0 (id 0), put the contact on its face y = 0 (id 2)
  // and have a mesh line at x = 1/2, or the "exact" solution would not
  // solve the discrete problem's continuous counterpart, or not be
  // resolved.
  template <int dim>
  void Box<dim>::check_manufactured_scene() const
  {
    const auto &boundary = this->parameters.boundary;
    AssertThrow(box.lower_corner[0] == 0. && box.lower_corner[1] == 0.,
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs "
                           "'" +
                           Entry::lower_corner +
                           "' to start at x = 0, y = 0."));
    AssertThrow(boundary.clamped_ids == std::vector<types::boundary_id>{0} &&
                  boundary.contact_ids == std::vector<types::boundary_id>{2},
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs "
                           "'" +
                           Entry::clamped_boundary_ids +
                           " = 0' "
                           "(x = 0) and 'Contact boundary ids = 2' (y = 0)."));
    const double length         = box.upper_corner[0] - box.lower_corner[0];
    const double cells_to_front = 0.5 / (length / n_cells(0, box.cell_size));
    AssertThrow(std::abs(cells_to_front - std::round(cells_to_front)) < 1e-8,
                ExcMessage("'" + Entry::manufactured_solution +
                           "': the "
                           "stick/slip front x = 1/2 must be a mesh line; "
                           "choose '" +
                           Entry::cell_size +
                           "' so that 1/(2h) cells "
                           "fit in [0, 1/2]."));
  }


#define INSTANTIATE(dim) template class Box<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
