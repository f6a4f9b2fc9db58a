/**
 * DiscreteSpace<dim>: the mesh, the finite element space V_h of the paper
 * with its constraints, the mapping and the quadrature rules: everything
 * the assembly, the friction on Gamma_3 and the postprocessors integrate
 * with (discrete_space.cc). ContactProblem owns one; it is fixed after the
 * set-up.
 */
#ifndef contact_discrete_space_h
#define contact_discrete_space_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <core/parameters.h>

#include <memory>

namespace Contact
{
  using namespace dealii;

  using VectorType = TrilinosWrappers::MPI::Vector;
  /** deal.II's own distributed vector, for the cell loops that read a
   *  field's entries (a lookup in the vector's map for each entry of an
   *  Epetra vector is much slower). */
  using FastVector = LinearAlgebra::distributed::Vector<double>;

  template <int dim>
  class DiscreteSpace
  {
  public:
    DiscreteSpace(const GeometryParameters &geometry,
                  const MPI_Comm            mpi_communicator);

    /** Distributes the dofs on the mesh (made by then) and builds the
     *  constraints of V_h. */
    void setup(const BoundaryParameters &boundary);

    /** Gauss rules of n points per direction on the cells and faces of the
     *  mesh's shape. */
    Quadrature<dim>     gauss_rule(const unsigned int n_points) const;
    Quadrature<dim - 1> face_gauss_rule(const unsigned int n_points) const;

    /** A copy of a distributed vector with this process's ghost entries,
     *  for FEValues, DataOut and point evaluation. */
    VectorType ghosted(const VectorType &v) const;
    FastVector fast_ghosted(const VectorType &v) const;

    const bool     simplex_cells;
    const MPI_Comm mpi_communicator;

    // p4est's distributed triangulation and Q_p for hypercubes, a plain
    // triangulation with P_p (FE_SimplexP and its MappingFE) for
    // simplices, which p4est does not handle. The scalar space of the same
    // degree carries the Gamma_3 quantities (slip rate, status) for output.
    const std::unique_ptr<Triangulation<dim>>       triangulation;
    const std::unique_ptr<const FiniteElement<dim>> scalar_fe;
    const FESystem<dim>                             fe;
    const std::unique_ptr<const Mapping<dim>>       mapping;
    // The rules of the assembly: Gauss with degree + 1 points, and for the
    // mass the Gauss-Lobatto rule when it is lumped.
    const Quadrature<dim>     quadrature;
    const Quadrature<dim>     mass_quadrature;
    const Quadrature<dim - 1> face_quadrature;
    DoFHandler<dim>           dof_handler;
    DoFHandler<dim>           scalar_dof_handler;
    IndexSet                  locally_owned_dofs;
    IndexSet                  locally_relevant_dofs;

    // Clamped Gamma_1 (u = 0, hence w = 0) and the bilateral Gamma_3
    // (w.n = 0) as homogeneous constraints: V_h of the paper.
    AffineConstraints<double> constraints;
    // The hanging nodes' constraints alone (part of the above): the
    // friction weights of Gamma_3, its fields in the output and the
    // self-checks need them without the normal constraints, which mix a
    // node's components.
    AffineConstraints<double> hanging_node_constraints;

  private:
    void make_constraints(const BoundaryParameters &boundary);
  };
} // namespace Contact

#endif
