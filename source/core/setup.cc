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

#include <core/contact_problem.h>

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
        triangulation.get());
    if (fully_distributed == nullptr)
      {
        build_mesh(*triangulation);
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

  template <int dim>
  void ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(computing_timer, "Setup");

    dof_handler.distribute_dofs(fe);
    scalar_dof_handler.distribute_dofs(*scalar_fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    make_constraints();

    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    for (MatrixType *matrix :
         {&mass_matrix, &viscosity_matrix, &elasticity_matrix, &system_matrix})
      matrix->reinit(locally_owned_dofs,
                     locally_owned_dofs,
                     dsp,
                     mpi_communicator);
    for (VectorType &vector : momentum_density)
      vector.reinit(locally_owned_dofs, mpi_communicator);
    angular_momentum_density.reinit(locally_owned_dofs, mpi_communicator);
    for (VectorType *vector :
         {&displacement, &velocity, &old_displacement, &old_velocity, &load})
      vector->reinit(locally_owned_dofs, mpi_communicator);

    friction_solver = std::make_unique<FrictionSolver<dim>>(parameters,
                                                            friction_law,
                                                            contact_nodes(),
                                                            constraints,
                                                            locally_owned_dofs,
                                                            mpi_communicator,
                                                            pcout,
                                                            computing_timer);
    friction_solver->set_sabotage(sabotage);
    setup_moment_balance();
    setup_probes();

    pcout << "Mesh: " << triangulation->n_global_active_cells() << " cells, "
          << (parameters.geometry.simplex_cells ? 'P' : 'Q') << fe.degree
          << ", " << dof_handler.n_dofs() << " unknowns, "
          << friction_solver->boundary().nodes.size()
          << " free nodes on Gamma_3" << std::endl;
    // Measured on the bushing (doc/verification.md, "A curved Gamma_3"):
    // Q2 nodes on the chords of a circle make the slip onset converge at
    // first order in h only, Q2 on the curved cells at second order.
    const auto &geometry = parameters.geometry;
    if (geometry.shell && geometry.mapping_degree < fe.degree)
      pcout << "Warning: '" << Entry::mapping_degree
            << "' = " << geometry.mapping_degree << " is below '"
            << Entry::finite_element_degree << "' = " << fe.degree
            << ": the element's nodes on the circles lie on their chords, "
               "which costs the tractions on Gamma_3 an order of accuracy "
               "(doc/verification.md); set both equal."
            << std::endl;
  }


  // @sect4{ContactProblem::make_constraints}

  // V_h of the paper: hanging nodes of a locally refined mesh, then w = 0
  // on Gamma_1 and w.n = 0 on Gamma_3. The normal
  // constraints come from compute_no_normal_flux_constraints, so that a
  // Gamma_3 that is not axis-aligned works too. Where Gamma_3 meets the
  // clamp the clamp wins (left_object_wins).
  template <int dim>
  void ContactProblem<dim>::make_constraints()
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto id : parameters.boundary.clamped_ids)
      VectorTools::interpolate_boundary_values(*mapping,
                                               dof_handler,
                                               id,
                                               Functions::ZeroFunction<dim>(
                                                 dim),
                                               constraints);

    // Gamma_3 and the symmetry planes in one call, so that where they meet
    // (an edge in 3D) both normal directions are constrained.
    AffineConstraints<double>    normal_constraints(locally_relevant_dofs);
    std::set<types::boundary_id> normal_ids(
      parameters.boundary.contact_ids.begin(),
      parameters.boundary.contact_ids.end());
    normal_ids.insert(parameters.boundary.symmetry_ids.begin(),
                      parameters.boundary.symmetry_ids.end());
    VectorTools::compute_no_normal_flux_constraints(
      dof_handler, 0, normal_ids, normal_constraints, *mapping);
    normal_constraints.close();

    constraints.merge(normal_constraints,
                      AffineConstraints<double>::left_object_wins);
    constraints.close();
  }


  // @sect4{The tangent basis of a node of Gamma_3}

  // The directions in which a node of Gamma_3 may not move are the rows of
  // its constraints: the normal that compute_no_normal_flux_constraints
  // used, the normal of a symmetry plane it also lies on, a clamped
  // component. The friction acts in the orthogonal complement, spanned by
  // the node's tangents. With one constraint (the usual case) the tangents
  // are, in 2D, the normal turned by +90 degrees, (-n_y, n_x), so that on the
  // paper's Gamma_3 (n = (0, -1)) t = e_x; in 3D the coordinate axis least
  // aligned with n, made orthogonal to n, and n x t_1. Where Gamma_3 meets a
  // symmetry plane in 3D one direction is left; the second tangent is then
  // zero, which the Tresca solver reads as a component without force. The
  // Tresca ball is isotropic, so the solution does not depend on the choice
  // of basis, only the components that represent it do.
  namespace
  {
    std::array<Tensor<1, 2>, 1> tangent_basis(const Tensor<1, 2> &normal,
                                              const unsigned int = 0)
    {
      return {{Tensor<1, 2>({-normal[1], normal[0]})}};
    }

    // `preferred`: the axis least aligned with all of Gamma_3's normals,
    // so that t_1 is the same direction along a curved Gamma_3 (the axis
    // of a tube), where it is not too close to this node's normal.
    std::array<Tensor<1, 3>, 2> tangent_basis(const Tensor<1, 3> &normal,
                                              const unsigned int  preferred = 3)
    {
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(normal[d]) < std::abs(normal[axis]))
          axis = d;
      if (preferred < 3 && std::abs(normal[preferred]) < 0.5)
        axis = preferred;
      Tensor<1, 3> first;
      first[axis] = 1;
      first -= (first * normal) * normal;
      first /= first.norm();
      return {{first, cross_product_3d(normal, first)}};
    }

    // Orthonormal rows of the constraints of one node's dofs (Gram-Schmidt).
    template <int dim>
    std::vector<Tensor<1, dim>>
    constrained_directions(const std::array<types::global_dof_index, dim> &dofs,
                           const AffineConstraints<double> &constraints)
    {
      std::vector<Tensor<1, dim>> directions;
      for (unsigned int d = 0; d < dim; ++d)
        if (constraints.is_constrained(dofs[d]))
          {
            Tensor<1, dim> row;
            row[d] = 1;
            for (const auto &[dof, weight] :
                 *constraints.get_constraint_entries(dofs[d]))
              for (unsigned int e = 0; e < dim; ++e)
                if (dofs[e] == dof)
                  row[e] -= weight;
            for (const Tensor<1, dim> &direction : directions)
              row -= (row * direction) * direction;
            if (row.norm() > 1e-10)
              directions.push_back(row / row.norm());
          }
      return directions;
    }

    // The tangents of a node whose constraint rows are `constrained`
    // (1 <= size < dim); `normal` orients them.
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    free_tangents(const std::vector<Tensor<1, dim>> &constrained,
                  const Tensor<1, dim>              &normal,
                  const unsigned int                 preferred)
    {
      if (constrained.size() == 1)
        return tangent_basis(constrained[0] * normal > 0 ? constrained[0] :
                                                           -constrained[0],
                             preferred);
      std::array<Tensor<1, dim>, dim - 1> tangents;
      if constexpr (dim == 3)
        {
          // Oriented like the reference tangent it is closest to (on a
          // tube's end t_1 is orthogonal to the axis, the first reference).
          const auto reference = tangent_basis(normal, preferred);
          tangents[0] = cross_product_3d(constrained[0], constrained[1]);
          tangents[0] /= tangents[0].norm();
          const double along_first  = tangents[0] * reference[0],
                       along_second = tangents[0] * reference[1];
          if ((std::abs(along_first) >= std::abs(along_second) ?
                 along_first :
                 along_second) < 0)
            tangents[0] *= -1;
        }
      return tangents;
    }
  } // namespace


  // @sect4{ContactProblem::contact_nodes}

  // Collects the nodes of Gamma_3 with their dofs, the weight
  // m_p = int_Gamma3 phi_p ds of the nodal ("node-to-rigid") friction and
  // the outward normal averaged over the faces around the node. A node all
  // of whose dofs are constrained (where Gamma_3 meets the clamp) has no
  // friction unknown and is left out.
  //
  // Every process keeps every node: the friction problem on Gamma_3 is
  // small and solved redundantly, so that all processes take the same
  // branches. Each process integrates over the faces of its own cells; the
  // parts are exchanged (all_gather) and summed, and the constraint rows of
  // a node (known where its dofs are locally relevant) travel with them.
  template <int dim>
  std::vector<ContactNode<dim>> ContactProblem<dim>::contact_nodes() const
  {
    // One record per (process, node) as doubles (dof indices are exact):
    // dofs, scalar dof, location, weight, normal, number of constraint
    // rows, the rows.
    constexpr unsigned int record_size =
      dim + 1 + dim + 1 + dim + 1 + dim * dim;
    std::vector<double> records;
    for (const auto &[key, node] : integrate_contact_faces())
      {
        const auto constrained =
          constrained_directions<dim>(node.dofs, constraints);
        records.insert(records.end(), node.dofs.begin(), node.dofs.end());
        records.push_back(node.scalar_dof);
        for (unsigned int d = 0; d < dim; ++d)
          records.push_back(node.location[d]);
        records.push_back(node.weight);
        for (unsigned int d = 0; d < dim; ++d)
          records.push_back(node.normal[d]);
        records.push_back(constrained.size());
        for (unsigned int r = 0; r < dim; ++r)
          for (unsigned int d = 0; d < dim; ++d)
            records.push_back(r < constrained.size() ? constrained[r][d] : 0.);
      }

    std::map<types::global_dof_index, ContactNode<dim>>            nodes;
    std::map<types::global_dof_index, std::vector<Tensor<1, dim>>> rows;
    for (const auto &part :
         Utilities::MPI::all_gather(mpi_communicator, records))
      for (auto r = part.begin(); r != part.end(); r += record_size)
        {
          const auto        key  = static_cast<types::global_dof_index>(r[0]);
          ContactNode<dim> &node = nodes[key];
          for (unsigned int d = 0; d < dim; ++d)
            {
              node.dofs[d]     = static_cast<types::global_dof_index>(r[d]);
              node.location[d] = r[dim + 1 + d];
              node.normal[d] += r[2 * dim + 2 + d];
            }
          node.scalar_dof = static_cast<types::global_dof_index>(r[dim]);
          node.weight += r[2 * dim + 1];
          std::vector<Tensor<1, dim>> &directions = rows[key];
          directions.resize(static_cast<unsigned int>(r[3 * dim + 2]));
          for (unsigned int i = 0; i < directions.size(); ++i)
            for (unsigned int d = 0; d < dim; ++d)
              directions[i][d] = r[3 * dim + 3 + i * dim + d];
        }

    // The axis least aligned with all normals (the first on ties).
    std::array<double, dim> largest{};
    for (const auto &[key, node] : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        largest[d] =
          std::max(largest[d], std::abs(node.normal[d]) / node.normal.norm());
    const unsigned int preferred = static_cast<unsigned int>(
      std::min_element(largest.begin(), largest.end()) - largest.begin());

    std::vector<ContactNode<dim>> contact_nodes;
    for (auto &[key, node] : nodes)
      {
        const std::vector<Tensor<1, dim>> &constrained = rows[key];
        AssertThrow(!constrained.empty(),
                    ExcInternalError("A node of Gamma_3 without its normal "
                                     "constraint."));
        if (constrained.size() == dim)
          continue;
        node.normal /= node.normal.norm();
        node.tangents      = free_tangents(constrained, node.normal, preferred);
        node.locally_owned = locally_owned_dofs.is_element(node.dofs[0]);
        contact_nodes.push_back(node);
      }
    // Order along Gamma_3, so that output and reports read left to right.
    std::sort(contact_nodes.begin(),
              contact_nodes.end(),
              [](const ContactNode<dim> &a, const ContactNode<dim> &b) {
                for (unsigned int d = 0; d < dim; ++d)
                  if (a.location[d] != b.location[d])
                    return a.location[d] < b.location[d];
                return false;
              });
    return contact_nodes;
  }


  // @sect4{ContactProblem::integrate_contact_faces}

  // This process's part of the nodes of Gamma_3: the faces of its own
  // cells, keyed by the node's first dof.
  template <int dim>
  std::map<types::global_dof_index, ContactNode<dim>>
  ContactProblem<dim>::integrate_contact_faces() const
  {
    const std::set<types::boundary_id> contact_ids(
      parameters.boundary.contact_ids.begin(),
      parameters.boundary.contact_ids.end());
    FEFaceValues<dim>                    fe_face_values(*mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_normal_vectors |
                                       update_JxW_values);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> scalar_dofs(
      scalar_fe->n_dofs_per_cell());
    std::map<types::global_dof_index, ContactNode<dim>> nodes;

    auto scalar_cell = scalar_dof_handler.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const auto this_scalar_cell = scalar_cell++;
        if (!cell->is_locally_owned())
          continue;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_ids.count(cell->face(f)->boundary_id()) != 0)
            {
              fe_face_values.reinit(cell, f);
              cell->get_dof_indices(cell_dofs);
              this_scalar_cell->get_dof_indices(scalar_dofs);
              // The dofs of the face (has_support_on_face is not exact
              // for simplex elements).
              for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
                {
                  const unsigned int i = fe.face_to_cell_index(j, f);
                  const auto [component, base_index] =
                    fe.system_to_component_index(i);
                  if (component != 0)
                    continue;
                  ContactNode<dim> &node = nodes[cell_dofs[i]];
                  for (unsigned int d = 0; d < dim; ++d)
                    node.dofs[d] =
                      cell_dofs[fe.component_to_system_index(d, base_index)];
                  node.scalar_dof = scalar_dofs[base_index];
                  node.location   = mapping->transform_unit_to_real_cell(
                    cell, fe.base_element(0).unit_support_point(base_index));
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    {
                      const double phi_JxW =
                        fe_face_values.shape_value_component(i, q, 0) *
                        fe_face_values.JxW(q);
                      node.weight += phi_JxW;
                      node.normal +=
                        fe_face_values.normal_vector(q) * std::abs(phi_JxW);
                    }
                }
            }
      }
    return nodes;
  }


  // @sect4{ContactProblem::setup_probes}

  template <int dim>
  void ContactProblem<dim>::setup_probes()
  {
    const unsigned int this_process =
                         Utilities::MPI::this_mpi_process(mpi_communicator),
                       n_processes =
                         Utilities::MPI::n_mpi_processes(mpi_communicator);
    probes.clear();
    for (const auto &coordinates : parameters.output.probe_points)
      {
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = coordinates[d];
        // The cells of this process around the point (a point outside the
        // mesh gives none, or an exception, depending on the triangulation).
        std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
          probe;
        try
          {
            for (const auto &candidate :
                 GridTools::find_all_active_cells_around_point(*mapping,
                                                               dof_handler,
                                                               point))
              if (candidate.first->is_locally_owned())
                {
                  probe = candidate;
                  break;
                }
          }
        catch (const ExceptionBase &)
          {}
        unsigned int evaluating_process =
          Utilities::MPI::min(probe.first.state() == IteratorState::valid ?
                                this_process :
                                n_processes,
                              mpi_communicator);
        std::ostringstream text;
        text << point;
        if (evaluating_process == n_processes && parameters.geometry.shell)
          evaluating_process = probe_near_curved_boundary(point, probe);
        AssertThrow(evaluating_process < n_processes,
                    ExcMessage("Entry '" + Entry::probe_points +
                               "': the point " + text.str() +
                               " is not in the mesh; allowed are points of "
                               "the body."));
        if (evaluating_process != this_process)
          probe.first = typename DoFHandler<dim>::active_cell_iterator();
        probes.push_back(probe);
      }
  }


  // @sect4{ContactProblem::probe_near_curved_boundary}

  // A point of the shell (between its radii, and in 3D its end faces, to
  // 1e-6 of the outer radius, as a point typed with a few digits is) that
  // no cell contains, because the cells' boundary is a polygon or a
  // polynomial through points of the circle, not the circle itself: the
  // nearest point of the cell around it (its reference coordinates, up to
  // half a cell outside, moved onto the reference cell). Of all processes
  // the one with the nearest cell evaluates it (the lowest rank on ties);
  // the return value is that process, or the number of processes if the
  // point is not of the shell.
  template <int dim>
  unsigned int ContactProblem<dim>::probe_near_curved_boundary(
    const Point<dim> &point,
    std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
      &probe) const
  {
    const auto  &geometry = parameters.geometry;
    const double radius   = std::hypot(point[0], point[1]),
                 slack    = 1e-6 * geometry.outer_radius;
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    if (radius < geometry.inner_radius - slack ||
        radius > geometry.outer_radius + slack ||
        (dim == 3 && (point[dim - 1] < -slack ||
                      point[dim - 1] > geometry.shell_length + slack)))
      return n_processes;
    double outside = std::numeric_limits<double>::max();
    try
      {
        for (const auto &candidate :
             GridTools::find_all_active_cells_around_point(
               *mapping, dof_handler, point, 0.5))
          {
            const Point<dim> inside =
              GeometryInfo<dim>::project_to_unit_cell(candidate.second);
            if (candidate.first->is_locally_owned() &&
                inside.distance(candidate.second) < outside)
              {
                outside = inside.distance(candidate.second);
                probe   = {candidate.first, inside};
              }
          }
      }
    catch (const ExceptionBase &)
      {}
    const double       nearest = Utilities::MPI::min(outside, mpi_communicator);
    const unsigned int this_process =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    return Utilities::MPI::min(nearest < std::numeric_limits<double>::max() &&
                                   outside == nearest ?
                                 this_process :
                                 n_processes,
                               mpi_communicator);
  }


  // @sect4{ContactProblem::ghosted}

  template <int dim>
  VectorType ContactProblem<dim>::ghosted(const VectorType &v) const
  {
    VectorType result(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
    result = v;
    return result;
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
  template void ContactProblem<dim>::setup_system();                                  \
  template void ContactProblem<dim>::make_constraints();                              \
  template std::vector<ContactNode<dim>> ContactProblem<dim>::contact_nodes()         \
    const;                                                                            \
  template std::map<types::global_dof_index, ContactNode<dim>>                        \
                        ContactProblem<dim>::integrate_contact_faces() const;         \
  template void         ContactProblem<dim>::setup_probes();                          \
  template unsigned int ContactProblem<dim>::probe_near_curved_boundary(              \
    const Point<dim> &,                                                               \
    std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>> &)          \
    const;                                                                            \
  template VectorType ContactProblem<dim>::ghosted(const VectorType &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
