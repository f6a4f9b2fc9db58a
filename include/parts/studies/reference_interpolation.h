/**
 * The fields of one level of a convergence study, interpolated into the
 * finite element space of the study's reference (its finest level): the
 * level's field is evaluated at the nodes of the reference, wherever (on
 * whichever process) they lie in the level's mesh. This is the nodal
 * interpolant, exact when the reference space contains the level's (nested
 * meshes, a reference degree at least the level's); it needs neither a
 * common coarse mesh nor the same partition of the levels on several
 * processes.
 */
#ifndef contact_reference_interpolation_h
#define contact_reference_interpolation_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <core/contact_problem.h>

#include <array>
#include <vector>

namespace Contact
{
  template <int dim>
  class ReferenceInterpolation
  {
  public:
    /**
     * The nodes of the reference: this process's, with their unknowns, and
     * the coordinates of every process's. Collective; once per study.
     */
    explicit ReferenceInterpolation(const ContactProblem<dim> &reference);

    /** A node of the reference in one of this process's cells of a level's
     *  mesh: its number among all nodes, the cell and the point in the
     *  cell's unit coordinates. */
    struct NodeInCell
    {
      unsigned int                                   node;
      typename DoFHandler<dim>::active_cell_iterator cell;
      Point<dim>                                     unit_point;
    };

    /** The reference's nodes in this process's cells of `level`'s mesh;
     *  once per level (the mesh exists once the level's run has started). */
    std::vector<NodeInCell> locate(const ContactProblem<dim> &level) const;

    /** The interpolant of `field`, a field of `level` whose nodes
     *  `locate()` found. Collective. */
    VectorType operator()(const std::vector<NodeInCell> &located,
                          const ContactProblem<dim>     &level,
                          const VectorType              &field) const;

  private:
    const IndexSet owned_dofs;
    // This process's nodes (their unknowns, one per component), where they
    // start among the nodes of all processes, and all nodes' coordinates.
    std::vector<std::array<types::global_dof_index, dim>> node_dofs;
    unsigned int                                          first_node = 0;
    std::vector<Point<dim>>                               all_nodes;
  };


  /** ||eps(a - b)||, the V-norm of the difference of two fields in the
   *  finite element space of `problem` (its own fields, or fields of other
   *  runs interpolated onto it): the distance by which the drivers compare
   *  runs. */
  template <int dim>
  double strain_distance(const ContactProblem<dim> &problem,
                         const VectorType          &a,
                         const VectorType          &b)
  {
    VectorType difference(a);
    difference -= b;
    return problem.strain_norm(difference);
  }
} // namespace Contact

#endif
