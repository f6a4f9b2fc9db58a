/**
 * The nodes of Gamma_3 (contact_nodes.cc): what the friction solver and
 * the postprocessors know of the contact boundary.
 */
#ifndef contact_contact_nodes_h
#define contact_contact_nodes_h

#include <core/discrete_space.h>
#include <core/friction_solver.h>

#include <vector>

namespace Contact
{
  /**
   * The nodes of the faces with one of `contact_ids`, with their dofs, the
   * weight m_p = int_Gamma3 psi_p ds of the nodal ("node-to-rigid")
   * friction (psi_p the basis function of V_h, which holds the hanging
   * nodes that follow p), the outward normal averaged over the faces
   * around the node and the tangents orthogonal to its constraints,
   * ordered along Gamma_3. A node all of whose dofs are constrained (where
   * Gamma_3 meets the clamp, or a hanging node) has no friction unknown
   * and is left out. Every process gets every node (collective).
   */
  template <int dim>
  std::vector<ContactNode<dim>>
  make_contact_nodes(const DiscreteSpace<dim>              &space,
                     const std::vector<types::boundary_id> &contact_ids);

  /** The directions in which the constraints of V_h fix a node with these
   *  dofs (a clamp, the normal of Gamma_3, of a symmetry plane, or the
   *  normal deal.II averaged over both), orthonormal. The constraints
   *  define V_h: the friction solver's tangents and the self-checks' map
   *  of Gamma_3 both start from them. */
  template <int dim>
  std::vector<Tensor<1, dim>>
  fixed_directions(const std::array<types::global_dof_index, dim> &dofs,
                   const AffineConstraints<double>                &constraints);
} // namespace Contact

#endif
