/* Mesh, finite element space, constraints of V_h and the nodes of Gamma_3. */

#include <deal.II/base/exceptions.h>

#include <deal.II/distributed/fully_distributed_tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
#include <core/contact_nodes.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>

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
  // @sect4{ContactProblem::make_grid}

  // Hypercubes go to p4est's distributed triangulation, which refines its
  // own part. p4est does not take simplices: on several processes the
  // whole simplex mesh is built on every process, partitioned by METIS, and
  // each process keeps its part in a fully distributed triangulation.
  template <int dim>
  void ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(computing_timer, "Grid");
    auto              *fully_distributed =
      dynamic_cast<parallel::fullydistributed::Triangulation<dim> *>(
        space.triangulation.get());
    if (fully_distributed == nullptr)
      {
        build_mesh(*space.triangulation);
        return;
      }
    Triangulation<dim> whole;
    build_mesh(whole);
    GridTools::partition_triangulation(
      Utilities::MPI::n_mpi_processes(mpi_communicator), whole);
    fully_distributed->create_triangulation(
      TriangulationDescription::Utilities::
        create_description_from_triangulation(whole, mpi_communicator));
  }


  // @sect4{ContactProblem::build_mesh}

  // The coarse mesh (the box, or a gmsh file), turned by the 'Rotation
  // angle', refined globally, then graded towards the 'Refinement points'.
  template <int dim>
  void ContactProblem<dim>::build_mesh(Triangulation<dim> &mesh)
  {
    const auto        &geometry      = parameters.geometry;
    const unsigned int n_refinements = !geometry.mesh_file.empty() ?
                                         read_mesh_file(mesh) :
                                       geometry.shell ? make_shell(mesh) :
                                                        make_box(mesh);
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
    grade_towards_points(mesh);
    check_boundary_ids(mesh);
  }


  // @sect4{ContactProblem::make_box}

  // The box of the .prm, colorized so that its faces carry the boundary
  // ids 0 (x = x0), 1 (x = x1), 2 (y = y0), 3 (y = y1), 4, 5 (z). Every edge
  // is divided into round(length / h) parts, as the paper divides its
  // boundary "into 1/h equal parts". The coarse mesh is the coarsest box
  // that refines globally into this one (the number of refinements is
  // returned): the same cells, but the meshes of a convergence study are
  // then nested (a level's solution is carried onto the reference's nodes
  // exactly) and p4est gets few trees. Tetrahedra are the exception:
  // deal.II 9.4's refinement of tetrahedra degrades them (P1 V-rates 0.79, 0.81
  // on refined meshes against 0.99, 1.00 on generated ones, measured), so a
  // tetrahedral box is generated at the requested cell size.
  template <int dim>
  unsigned int ContactProblem<dim>::make_box(Triangulation<dim> &mesh)
  {
    const auto &geometry = parameters.geometry;
    {
      double cells = 1, unknowns = dim;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double parts = std::max(1.,
                                        std::round((geometry.upper_corner[d] -
                                                    geometry.lower_corner[d]) /
                                                   geometry.cell_size));
          cells *= parts;
          unknowns *= parts * geometry.fe_degree + 1;
        }
      check_memory(cells, unknowns, Entry::cell_size);
    }
    Point<dim>                lower, upper;
    std::vector<unsigned int> subdivisions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = geometry.lower_corner[d];
        upper[d] = geometry.upper_corner[d];
        subdivisions[d] =
          std::max(1., std::round((upper[d] - lower[d]) / geometry.cell_size));
      }
    unsigned int n_refinements = 0;
    while (!(geometry.simplex_cells && dim == 3) &&
           std::all_of(subdivisions.begin(),
                       subdivisions.end(),
                       [](const unsigned int n) { return n % 2 == 0; }))
      {
        for (unsigned int &n : subdivisions)
          n /= 2;
        ++n_refinements;
      }
    if (geometry.simplex_cells)
      {
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
      }
    else
      GridGenerator::subdivided_hyper_rectangle(
        mesh, subdivisions, lower, upper, /*colorize=*/true);
    return n_refinements;
  }


  // @sect4{ContactProblem::make_shell}

  // The annulus or the tube of the bushing scene: deal.II's shell with its
  // spherical (2D) or cylindrical (3D) manifold, so that refinement puts
  // new vertices on the circles and a mapping of degree 2 or more curves
  // the cells' edges along them. Returns the number of refinements.
  template <int dim>
  unsigned int ContactProblem<dim>::make_shell(Triangulation<dim> &mesh)
  {
    const auto  &geometry = parameters.geometry;
    const double inner = geometry.inner_radius, outer = geometry.outer_radius;
    // In 3D as many cells along z as keep them about as long as wide.
    const unsigned int n_axial =
      dim == 2 ? 1 :
                 std::max(1u,
                          static_cast<unsigned int>(std::round(
                            geometry.shell_length / (2 * numbers::PI * inner /
                                                     geometry.cells_around))));
    {
      const double cells = std::pow(2., dim * geometry.mesh_refinements) *
                           geometry.cells_around * n_axial;
      check_memory(cells,
                   dim * cells * std::pow(geometry.fe_degree, dim),
                   Entry::mesh_refinements);
    }
    if constexpr (dim == 2)
      GridGenerator::hyper_shell(
        mesh, Point<dim>(), inner, outer, geometry.cells_around, true);
    else
      {
        GridGenerator::cylinder_shell(mesh,
                                      geometry.shell_length,
                                      inner,
                                      outer,
                                      geometry.cells_around,
                                      n_axial);
        // By the faces' vertices, which lie on the circles (a face's center
        // lies inside its circle, for few cells around below the middle
        // radius even on the outer one).
        const double length = geometry.shell_length;
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


  // @sect4{ContactProblem::check_memory}

  // A mesh far too fine for the machine would end in std::bad_alloc (or
  // the swap) somewhere in the setup, so its unknowns are counted (or, for
  // a refined mesh file, estimated from below) before it is built. A run
  // needs about 3 kB per unknown in 2D and 6 kB in 3D on its leanest path
  // (measured: 439 MB at 66 000 unknowns in 2D, bench/results.md; 3.7 GB
  // per process at 1.1 million unknowns on two processes in 3D,
  // bench/scaling.md); a mesh that needs more than the machine's memory
  // per process is refused, naming the entry that made it.
  template <int dim>
  void ContactProblem<dim>::check_memory(const double       cells,
                                         const double       unknowns,
                                         const std::string &entry) const
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   name;
    double        total_kB = 0;
    while (meminfo >> name >> total_kB && name != "MemTotal:")
      meminfo.ignore(256, '\n');
    const double needed = (dim == 3 ? 6e3 : 3e3) * unknowns /
                          Utilities::MPI::n_mpi_processes(mpi_communicator);
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


  // @sect4{ContactProblem::read_mesh_file}

  // A gmsh mesh: its physical ids become boundary ids. It is read once
  // into a serial triangulation to check that its cells have the declared
  // 'Cell shape' (p4est would fail on simplices with a less clear message),
  // then into the triangulation of the run.
  template <int dim>
  unsigned int ContactProblem<dim>::read_mesh_file(Triangulation<dim> &mesh)
  {
    const std::string &file = parameters.geometry.mesh_file;
    const auto         read = [&](Triangulation<dim> &target) {
      std::ifstream in(file);
      AssertThrow(in,
                  ExcMessage("Entry '" + Entry::mesh_file + "': cannot open '" +
                             file +
                             "'; allowed is a readable gmsh .msh file."));
      GridIn<dim> grid_in(target);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const ExceptionBase &exc)
        {
          std::ostringstream reason;
          exc.print_info(reason);
          AssertThrow(false,
                      ExcMessage("Entry '" + Entry::mesh_file +
                                 "': cannot read '" + file +
                                 "' as a gmsh mesh of dimension " +
                                 std::to_string(dim) + ": " +
                                 Utilities::trim(reason.str())));
        }
    };
    Triangulation<dim> serial;
    read(serial);
    // From below: a refined cell has 2^dim children, and at least
    // p^dim / 6 (tetrahedra) of its own nodes.
    const auto  &geometry = parameters.geometry;
    const double cells =
      serial.n_active_cells() * std::pow(2., dim * geometry.mesh_refinements);
    check_memory(cells,
                 dim * cells * std::pow(geometry.fe_degree, dim) /
                   (geometry.simplex_cells ? 6. : 1.),
                 Entry::mesh_refinements);
    const bool simplices = serial.all_reference_cells_are_simplex();
    AssertThrow(simplices == parameters.geometry.simplex_cells &&
                  (simplices || serial.all_reference_cells_are_hyper_cube()),
                ExcMessage("Entry '" + Entry::cell_shape + "': the mesh '" +
                           file + "' has " +
                           (simplices ? "simplices" : "not only simplices") +
                           "; allowed is 'Cell shape = " +
                           (simplices ? "simplex" : "hypercube") +
                           "' for it (meshes of one cell shape only)."));
    read(mesh);
    return parameters.geometry.mesh_refinements;
  }


  // @sect4{ContactProblem::grade_towards_points}

  // Refines, until none is left, every cell that is larger than
  // h (r/R)^gamma, r the distance of its center to the nearest of the
  // 'Refinement points' (cells farther than R keep the global size h): the
  // grading that a corner singularity u ~ r^lambda needs (gamma =
  // 1 - lambda) for the rate of a smooth solution (doc/verification.md).
  // The smallest cells, at the point, have the size of about
  // (h R^-gamma)^(1/(1-gamma)), h^(3/2) for gamma = 1/3. The target size is
  // proportional to h, so the meshes of a convergence study stay nested.
  // Hanging nodes on Gamma_3 would need the nodal friction weights of the
  // constrained basis; they are excluded for now.
  template <int dim>
  void ContactProblem<dim>::grade_towards_points(Triangulation<dim> &mesh)
  {
    const auto &geometry = parameters.geometry;
    if (geometry.refinement_points.empty() || geometry.refinement_radius == 0.)
      return;
    std::vector<Point<dim>> points;
    for (const auto &coordinates : geometry.refinement_points)
      {
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = coordinates[d];
        points.push_back(point);
      }
    // Each cell's size relative to its ancestor before grading, 2^-(level
    // - base level), against the target factor: the same as cell sizes on a
    // box, whose cells are all alike, and right on a shell, whose cells
    // grow with the radius. (The first active cell of this process may be
    // an artificial, coarser one: the base level is the smallest level of
    // the locally owned cells of all processes.)
    unsigned int base_level = numbers::invalid_unsigned_int;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        base_level = std::min<unsigned int>(base_level, cell->level());
    base_level = Utilities::MPI::min(base_level, mpi_communicator);
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
        flagged = Utilities::MPI::logical_or(flagged, mpi_communicator);
        if (flagged)
          mesh.execute_coarsening_and_refinement();
      }

    const std::set<types::boundary_id> contact_ids(
      parameters.boundary.contact_ids.begin(),
      parameters.boundary.contact_ids.end());
    unsigned int finest = 0, coarsest = numbers::invalid_unsigned_int;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              contact_ids.count(face->boundary_id()) != 0)
            {
              finest   = std::max<unsigned int>(finest, cell->level());
              coarsest = std::min<unsigned int>(coarsest, cell->level());
            }
    finest   = Utilities::MPI::max(finest, mpi_communicator);
    coarsest = Utilities::MPI::min(coarsest, mpi_communicator);
    AssertThrow(finest <= coarsest,
                ExcMessage("The local refinement of "
                           "'" +
                           Entry::refinement_points +
                           "' reaches Gamma_3, "
                           "which is not supported yet: choose points away "
                           "from '" +
                           Entry::contact_boundary_ids +
                           "' "
                           "or a smaller '" +
                           Entry::refinement_radius + "'."));
  }


  // @sect4{ContactProblem::check_boundary_ids}

  // A boundary id in the .prm that the mesh does not have would silently
  // leave a part of the boundary free; a boundary part in two roles is a
  // contradiction. Both are user errors that name the entry.
  template <int dim>
  void
  ContactProblem<dim>::check_boundary_ids(const Triangulation<dim> &mesh) const
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
                             role[id] + "' and 'Boundary conditions/" + entry +
                             "'; a boundary part has one role."));
      role[id] = entry;
    };
    for (const auto id : parameters.boundary.clamped_ids)
      claim(id, "Clamped boundary ids");
    for (const auto id : parameters.boundary.contact_ids)
      claim(id, "Contact boundary ids");
    for (const auto id : parameters.boundary.symmetry_ids)
      claim(id, "Symmetry boundary ids");
    for (const auto &traction : parameters.boundary.tractions)
      claim(traction.first, "Tractions");
  }


  // @sect4{ContactProblem::setup_system}

  // V_h with its constraints, the sparsity of the matrices, the vectors of
  // the state, the nodes of Gamma_3 and the friction solver on them, and
  // the set-up of the postprocessors.
  template <int dim>
  void ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    space.setup(parameters.boundary);
    const IndexSet &owned    = space.locally_owned_dofs;
    const IndexSet &relevant = space.locally_relevant_dofs;

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(space.dof_handler,
                                    dsp,
                                    space.constraints,
                                    false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned,
                                               mpi_communicator,
                                               relevant);
    for (MatrixType *matrix : {&matrices.mass,
                               &matrices.viscosity,
                               &matrices.elasticity,
                               &matrices.system})
      matrix->reinit(owned, owned, dsp, mpi_communicator);
    for (VectorType &vector : matrices.momentum_density)
      vector.reinit(owned, mpi_communicator);
    matrices.angular_momentum_density.reinit(owned, mpi_communicator);
    for (VectorType *vector : {&state.displacement,
                               &state.velocity,
                               &state.old_displacement,
                               &state.old_velocity,
                               &state.load})
      vector->reinit(owned, mpi_communicator);

    friction_solver = std::make_unique<FrictionSolver<dim>>(
      parameters,
      friction_law,
      make_contact_nodes(space, parameters.boundary.contact_ids),
      space.constraints,
      owned,
      mpi_communicator,
      pcout,
      computing_timer);
    friction_solver->set_sabotage(sabotage);
    loads->setup(friction_solver->boundary());
    // The postprocessors' set-up may refuse an entry of theirs (a probe
    // outside the body): before anything is reported of the mesh.
    for (const auto &postprocessor : postprocessors)
      postprocessor->initialize();

    pcout << "Mesh: " << space.triangulation->n_global_active_cells()
          << " cells, " << (parameters.geometry.simplex_cells ? 'P' : 'Q')
          << space.fe.degree << ", " << space.dof_handler.n_dofs()
          << " unknowns, " << friction_solver->boundary().nodes.size()
          << " free nodes on Gamma_3" << std::endl;
    // Measured on the bushing (doc/verification.md, "A curved Gamma_3"):
    // Q2 nodes on the chords of a circle make the slip onset converge at
    // first order in h only, Q2 on the curved cells at second order.
    const auto &geometry = parameters.geometry;
    if (geometry.shell && geometry.mapping_degree < space.fe.degree)
      pcout << "Warning: '" << Entry::mapping_degree
            << "' = " << geometry.mapping_degree << " is below '"
            << Entry::finite_element_degree << "' = " << space.fe.degree
            << ": the element's nodes on the circles lie on their chords, "
               "which costs the tractions on Gamma_3 an order of accuracy "
               "(doc/verification.md); set both equal."
            << std::endl;
  }


#define INSTANTIATE(dim)                                                              \
  template void         ContactProblem<dim>::make_grid();                             \
  template void         ContactProblem<dim>::build_mesh(Triangulation<dim> &);        \
  template unsigned int ContactProblem<dim>::make_box(Triangulation<dim> &);          \
  template void         ContactProblem<dim>::check_memory(const double,               \
                                                  const double,               \
                                                  const std::string &) const; \
  template unsigned int ContactProblem<dim>::make_shell(Triangulation<dim> &);        \
  template unsigned int ContactProblem<dim>::read_mesh_file(                          \
    Triangulation<dim> &);                                                            \
  template void ContactProblem<dim>::grade_towards_points(                            \
    Triangulation<dim> &);                                                            \
  template void ContactProblem<dim>::check_boundary_ids(                              \
    const Triangulation<dim> &) const;                                                \
  template void ContactProblem<dim>::setup_system();

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
