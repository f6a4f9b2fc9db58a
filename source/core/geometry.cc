/* What every geometry shares: the rotation, refinement and grading of its
   coarse mesh, the checks of the memory and of the boundary ids, and the
   choice of the geometry among the registered ones. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>


#include <base/dimensions.h>
#include <core/geometry.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace Contact
{
  namespace
  {
    // @sect4{grade_towards_points}

    // Refines, until none is left, every cell that is larger than
    // h (r/R)^gamma, r the distance of its center to the nearest of the
    // 'Refinement points' (cells farther than R keep the global size h): the
    // grading that a corner singularity u ~ r^lambda needs (gamma =
    // 1 - lambda) for the rate of a smooth solution (doc/verification.md).
    // The smallest cells, at the point, have the size of about
    // (h R^-gamma)^(1/(1-gamma)), h^(3/2) for gamma = 1/3. The target size is
    // proportional to h, so the meshes of a convergence study stay nested.
    // Cells at Gamma_3 may be refined: hanging nodes there share their
    // friction weight with the nodes they follow (contact_nodes.cc).
    template <int dim>
    void grade_towards_points(const GeometryParameters &geometry,
                              const MPI_Comm            communicator,
                              Triangulation<dim>       &mesh)
    {
      std::vector<Point<dim>> points;
      for (const auto &coordinates : geometry.refinement_points)
        {
          Point<dim> point;
          for (unsigned int d = 0; d < dim; ++d)
            point[d] = coordinates[d];
          points.push_back(point);
        }
      // Each cell's size relative to its ancestor before grading, 2^-(level
      // - base level), against the target factor: the same as cell sizes on
      // a box, whose cells are all alike, and right on a shell, whose cells
      // grow with the radius. (The first active cell of this process may be
      // an artificial, coarser one: the base level is the smallest level of
      // the locally owned cells of all processes.)
      unsigned int base_level = numbers::invalid_unsigned_int;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          base_level = std::min<unsigned int>(base_level, cell->level());
      base_level = Utilities::MPI::min(base_level, communicator);
      for (bool flagged = true; flagged;)
        {
          flagged = false;
          for (const auto &cell : mesh.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                double r = std::numeric_limits<double>::max();
                for (const Point<dim> &point : points)
                  r = std::min(r, cell->center().distance(point));
                const double target =
                  std::pow(std::min(r / geometry.refinement_radius, 1.),
                           geometry.refinement_grading);
                if (std::pow(0.5, cell->level() - base_level) >
                    target * (1. + 1e-10))
                  {
                    cell->set_refine_flag();
                    flagged = true;
                  }
              }
          flagged = Utilities::MPI::logical_or(flagged, communicator);
          if (flagged)
            mesh.execute_coarsening_and_refinement();
        }
    }


    // @sect4{check_points_in_body}

    // A refinement point outside the body grades nothing near it, or cells
    // far from where the user meant: each must lie in the body, as the
    // geometry decides (Geometry::contains()).
    template <int dim>
    void check_points_in_body(const Geometry<dim>      &geometry,
                              const GeometryParameters &entries,
                              const Triangulation<dim> &mesh)
    {
      for (const auto &coordinates : entries.refinement_points)
        {
          Point<dim> point;
          for (unsigned int d = 0; d < dim; ++d)
            point[d] = coordinates[d];
          std::ostringstream text;
          text << point;
          AssertThrow(geometry.contains(point, mesh),
                      ExcMessage("Entry '" + Entry::refinement_points +
                                 "': the point " + text.str() +
                                 " is not in the body; allowed are points "
                                 "of the body (its corners and boundary "
                                 "included)."));
        }
    }


    // @sect4{check_boundary_ids}

    // A boundary id in the .prm that the mesh does not have would silently
    // leave a part of the boundary free; a boundary part in two roles is a
    // contradiction. Both are user errors that name the entry.
    template <int dim>
    void check_boundary_ids(const BoundaryParameters &boundary,
                            const Triangulation<dim> &mesh)
    {
      const std::vector<types::boundary_id> mesh_ids = mesh.get_boundary_ids();
      std::string                           available;
      for (const auto id : mesh_ids)
        available += (available.empty() ? "" : ", ") + std::to_string(id);

      std::map<types::boundary_id, std::string> role;
      const auto claim = [&](const types::boundary_id id,
                             const std::string       &entry) {
        AssertThrow(std::find(mesh_ids.begin(), mesh_ids.end(), id) !=
                      mesh_ids.end(),
                    ExcMessage("The entry 'Boundary conditions/" + entry +
                               "' names the boundary id " + std::to_string(id) +
                               ", which the mesh does not have; allowed are " +
                               available + "."));
        AssertThrow(role.count(id) == 0 || role[id] == entry,
                    ExcMessage("The boundary id " + std::to_string(id) +
                               " appears in both 'Boundary conditions/" +
                               role[id] + "' and 'Boundary conditions/" +
                               entry + "'; a boundary part has one role."));
        role[id] = entry;
      };
      for (const auto id : boundary.clamped_ids)
        claim(id, "Clamped boundary ids");
      for (const auto id : boundary.contact_ids)
        claim(id, "Contact boundary ids");
      for (const auto id : boundary.symmetry_ids)
        claim(id, "Symmetry boundary ids");
      for (const auto &traction : boundary.tractions)
        claim(traction.first, "Tractions");
    }
  } // namespace


  template <int dim>
  Geometry<dim>::Geometry(const Parameters &run_parameters,
                          const MPI_Comm    mpi_communicator)
    : GeometryBase(run_parameters)
    , communicator(mpi_communicator)
  {}


  // @sect4{Geometry::contains}

  // The cells of a box or a mesh file have straight sides, so the mesh
  // decides (each process searches its own cells).
  template <int dim>
  bool Geometry<dim>::contains(const Point<dim>         &point,
                               const Triangulation<dim> &mesh) const
  {
    bool inside = false;
    try
      {
        inside = !GridTools::find_all_active_cells_around_point(
                    MappingQ1<dim>(), mesh, point, 1e-10)
                    .empty();
      }
    catch (const ExceptionBase &)
      {}
    return Utilities::MPI::logical_or(inside, communicator);
  }


  template <int dim>
  double Geometry<dim>::cell_size(const Triangulation<dim> &mesh,
                                  const Mapping<dim>       &mapping) const
  {
    return GridTools::maximal_cell_diameter(mesh, mapping);
  }


  // @sect4{Geometry::create_mesh}

  template <int dim>
  void Geometry<dim>::create_mesh(Triangulation<dim> &mesh) const
  {
    const auto        &geometry      = parameters.geometry;
    const unsigned int n_refinements = create_coarse_mesh(mesh);
    const double       angle = geometry.rotation_angle * numbers::PI / 180.;
    if (angle != 0.)
      {
        if constexpr (dim == 2)
          GridTools::rotate(angle, mesh);
        else
          GridTools::rotate(Tensor<1, 3>({geometry.rotation_axis[0],
                                          geometry.rotation_axis[1],
                                          geometry.rotation_axis[2]}),
                            angle,
                            mesh);
      }
    mesh.refine_global(n_refinements);
    if (!geometry.refinement_points.empty() && geometry.refinement_radius != 0.)
      {
        check_points_in_body(*this, geometry, mesh);
        grade_towards_points(geometry, communicator, mesh);
      }
    check_boundary_ids(parameters.boundary, mesh);
  }


  // @sect4{Geometry::check_memory}

  // A mesh far too fine for the machine would end in std::bad_alloc (or
  // the swap) somewhere in the setup, so its unknowns are counted (or, for
  // a refined mesh file, estimated from below) before it is built. A run
  // needs about 3 kB per unknown in 2D and 6 kB in 3D on its leanest path
  // (measured: 439 MB at 66 000 unknowns in 2D, bench/results.md; 3.7 GB
  // per process at 1.1 million unknowns on two processes in 3D,
  // bench/scaling.md); a mesh that needs more than the machine's memory
  // per process is refused, naming the entry that made it.
  template <int dim>
  void Geometry<dim>::check_memory(const double       cells,
                                   const double       unknowns,
                                   const std::string &entry) const
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   name;
    double        total_kB = 0;
    while (meminfo >> name >> total_kB && name != "MemTotal:")
      meminfo.ignore(256, '\n');
    const double needed = (dim == 3 ? 6e3 : 3e3) * unknowns /
                          Utilities::MPI::n_mpi_processes(communicator);
    std::ostringstream text;
    text << std::setprecision(3) << "Entry '" << entry
         << "': the mesh would have " << cells << " cells and " << unknowns
         << " unknowns, which need about " << needed / 1e9
         << " GB per process (" << (dim == 3 ? 6 : 3)
         << " kB per unknown, measured), more than this machine's memory. "
         << "Allowed is a coarser mesh, or more processes on more machines.";
    AssertThrow(total_kB == 0 || needed <= 1e3 * total_kB,
                ExcMessage(text.str()));
  }


  // @sect4{create_geometry}

  // A geometry that an entry of its own asks for (a mesh file) replaces
  // the Domain; else the registered geometry of that name.
  template <int dim>
  std::unique_ptr<const Geometry<dim>>
  create_geometry(const Parameters &parameters, const MPI_Comm communicator)
  {
    for (const auto &part : ReplacingGeometryRegistry<dim>::parts())
      if (auto geometry = part.create(parameters, communicator))
        return geometry;
    return GeometryRegistry<dim>::create(Entry::domain,
                                         parameters.geometry.domain,
                                         parameters,
                                         communicator);
  }


  // For base/'s create_geometry(parameters), whatever the name it was
  // registered under: the geometry of the parameters' dimension on one
  // process.
  std::unique_ptr<const GeometryBase>
  create_geometry_on_one_process(const Parameters &parameters)
  {
#ifdef CONTACT_WITH_2D
    if (parameters.dimension == 2)
      return create_geometry<2>(parameters, MPI_COMM_SELF);
#endif
#ifdef CONTACT_WITH_3D
    if (parameters.dimension == 3)
      return create_geometry<3>(parameters, MPI_COMM_SELF);
#endif
    AssertThrow(false, ExcInternalError("A dimension without a geometry."));
    return nullptr;
  }


#define INSTANTIATE(dim)                                              \
  template class Geometry<dim>;                                       \
  template std::unique_ptr<const Geometry<dim>> create_geometry<dim>( \
    const Parameters &, const MPI_Comm);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
