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

#include <contact_problem.h>

#include <array>
#include <vector>

namespace Contact
{
  template <int dim>
  class ReferenceInterpolation
  {
  public:
    /** The nodes of the reference that this process owns. */
    explicit ReferenceInterpolation(const ContactProblem<dim> &reference);

    /**
     * The interpolant of `field`, a field of `level`. Collective. The nodes
     * are located in the level's mesh at the first call, so one object
     * serves one level (whose mesh exists once its run has started).
     */
    VectorType operator()(const ContactProblem<dim> &level,
                          const VectorType          &field);

  private:
    void locate_nodes(const ContactProblem<dim> &level);

    const IndexSet owned_dofs;
    // This process's nodes of the reference, with their unknowns (one per
    // component), and where they start among the nodes of all processes.
    std::vector<Point<dim>>                               node_points;
    std::vector<std::array<types::global_dof_index, dim>> node_dofs;
    unsigned int                                          first_node = 0;

    // The nodes of all processes that lie in this process's cells of the
    // level's mesh: their number among all nodes, the cell and the point
    // in the cell's unit coordinates.
    struct NodeInCell
    {
      unsigned int                                   node;
      typename DoFHandler<dim>::active_cell_iterator cell;
      Point<dim>                                     unit_point;
    };
    std::vector<NodeInCell> nodes_in_own_cells;
    unsigned int            n_all_nodes = 0;
    bool                    located     = false;
  };
} // namespace Contact

#endif
