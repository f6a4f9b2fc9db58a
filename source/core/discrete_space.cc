/* The mesh, the finite element space V_h with its constraints, the mapping
   and the quadrature rules. */

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
#include <core/discrete_space.h>

#include <algorithm>
#include <set>

namespace Contact
{
  namespace
  {
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    make_triangulation(const GeometryParameters &geometry,
                       const MPI_Comm            communicator)
    {
      if ((geometry.cell_shape == GeometryParameters::CellShape::simplex) &&
          Utilities::MPI::n_mpi_processes(communicator) > 1)
        return std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
          communicator);
      if ((geometry.cell_shape == GeometryParameters::CellShape::simplex))
        return std::make_unique<Triangulation<dim>>();
      return std::make_unique<parallel::distributed::Triangulation<dim>>(
        communicator);
    }

    template <int dim>
    std::unique_ptr<const FiniteElement<dim>>
    make_scalar_element(const GeometryParameters &geometry)
    {
      if ((geometry.cell_shape == GeometryParameters::CellShape::simplex))
        return std::make_unique<FE_SimplexP<dim>>(geometry.fe_degree);
      return std::make_unique<FE_Q<dim>>(geometry.fe_degree);
    }

    // The map of the reference cell: linear (straight edges), or of the
    // 'Mapping degree', whose points between the vertices lie on the
    // manifold of a curved boundary. Assembly, the normals of Gamma_3 and
    // its nodal weights all use this one.
    template <int dim>
    std::unique_ptr<const Mapping<dim>>
    make_mapping(const GeometryParameters &geometry)
    {
      if ((geometry.cell_shape == GeometryParameters::CellShape::simplex))
        return std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      return std::make_unique<MappingQ<dim>>(geometry.mapping_degree);
    }

    // QGaussSimplex has rules of up to 4 points per direction in this
    // deal.II (exact for degree 7); more are not needed for the degrees
    // offered.
    template <int dim>
    Quadrature<dim> gauss_rule(const bool         simplex_cells,
                               const unsigned int n_points)
    {
      if (simplex_cells)
        return QGaussSimplex<dim>(std::min(n_points, 4u));
      return QGauss<dim>(n_points);
    }
  } // namespace


  // @sect4{DiscreteSpace::DiscreteSpace}

  template <int dim>
  DiscreteSpace<dim>::DiscreteSpace(const GeometryParameters &geometry,
                                    const MPI_Comm            communicator)
    : simplex_cells(
        (geometry.cell_shape == GeometryParameters::CellShape::simplex))
    , mpi_communicator(communicator)
    , triangulation(make_triangulation<dim>(geometry, communicator))
    , scalar_fe(make_scalar_element<dim>(geometry))
    , fe(*scalar_fe, dim)
    , mapping(make_mapping<dim>(geometry))
    , quadrature(gauss_rule(geometry.fe_degree + 1))
    , mass_quadrature(
        (geometry.mass_matrix == GeometryParameters::MassMatrix::lumped) ?
          Quadrature<dim>(QGaussLobatto<dim>(geometry.fe_degree + 1)) :
          quadrature)
    , face_quadrature(face_gauss_rule(geometry.fe_degree + 1))
    , dof_handler(*triangulation)
    , scalar_dof_handler(*triangulation)
  {}


  template <int dim>
  Quadrature<dim>
  DiscreteSpace<dim>::gauss_rule(const unsigned int n_points) const
  {
    return Contact::gauss_rule<dim>(simplex_cells, n_points);
  }

  template <int dim>
  Quadrature<dim - 1>
  DiscreteSpace<dim>::face_gauss_rule(const unsigned int n_points) const
  {
    return Contact::gauss_rule<dim - 1>(simplex_cells, n_points);
  }


  // @sect4{DiscreteSpace::setup}

  template <int dim>
  void DiscreteSpace<dim>::setup(const BoundaryParameters &boundary)
  {
    dof_handler.distribute_dofs(fe);
    scalar_dof_handler.distribute_dofs(*scalar_fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    make_constraints(boundary);
  }


  // @sect4{DiscreteSpace::make_constraints}

  // V_h of the paper: hanging nodes of a locally refined mesh, then w = 0
  // on Gamma_1 and w.n = 0 on Gamma_3. The normal
  // constraints come from compute_no_normal_flux_constraints, so that a
  // Gamma_3 that is not axis-aligned works too. Where Gamma_3 meets the
  // clamp the clamp wins (left_object_wins).
  template <int dim>
  void DiscreteSpace<dim>::make_constraints(const BoundaryParameters &boundary)
  {
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto id : boundary.clamped_ids)
      VectorTools::interpolate_boundary_values(*mapping,
                                               dof_handler,
                                               id,
                                               Functions::ZeroFunction<dim>(
                                                 dim),
                                               constraints);

    // Gamma_3 and the symmetry planes in one call, so that where they meet
    // (an edge in 3D) both normal directions are constrained.
    AffineConstraints<double>    normal_constraints(locally_relevant_dofs);
    std::set<types::boundary_id> normal_ids(boundary.contact_ids.begin(),
                                            boundary.contact_ids.end());
    normal_ids.insert(boundary.symmetry_ids.begin(),
                      boundary.symmetry_ids.end());
    VectorTools::compute_no_normal_flux_constraints(
      dof_handler, 0, normal_ids, normal_constraints, *mapping);
    normal_constraints.close();

    constraints.merge(normal_constraints,
                      AffineConstraints<double>::left_object_wins);
    constraints.close();
  }


  // @sect4{DiscreteSpace::ghosted}

  template <int dim>
  VectorType DiscreteSpace<dim>::ghosted(const VectorType &v) const
  {
    VectorType result(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
    result = v;
    return result;
  }


  // @sect4{DiscreteSpace::fast_ghosted}

  // A ghosted copy of a field in deal.II's own vector, whose entries the
  // cell loops read much faster than those of an Epetra vector (a lookup in
  // the vector's map for each).
  template <int dim>
  FastVector DiscreteSpace<dim>::fast_ghosted(const VectorType &v) const
  {
    FastVector result(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
    if (locally_owned_dofs.is_contiguous())
      std::copy(v.begin(), v.end(), result.begin());
    else
      for (const types::global_dof_index i : locally_owned_dofs)
        result[i] = v[i];
    result.update_ghost_values();
    return result;
  }


#define INSTANTIATE(dim) template class DiscreteSpace<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
