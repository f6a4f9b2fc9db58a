/**
 * Gamma3Map<dim>: the contact boundary as the self-checks see it
 * (gamma3_map.cc), built from the mesh, the finite element, the mapping and
 * the constraints of V_h alone, not from the friction solver's node list:
 * each node's dofs, its weight m_p = int_Gamma3 psi_p ds (psi_p the basis
 * function of V_h; hanging nodes are left out) and the directions in
 * which V_h fixes it (its tangent plane is what is left).
 * Through it the checks read the body's velocity at the nodes and apply
 * the solver's nodal forces to the body, so that a wrong weight, tangent or
 * dof in the solver's map of Gamma_3 is seen instead of shared.
 */
#ifndef contact_gamma3_map_h
#define contact_gamma3_map_h

#include <core/discrete_space.h>

#include <array>
#include <vector>

namespace Contact
{
  template <int dim>
  class Gamma3Map
  {
  public:
    struct Node
    {
      Point<dim>                               location;
      std::array<types::global_dof_index, dim> dofs;
      double                                   weight = 0;
      // Orthonormal: the normal of Gamma_3 (averaged with a symmetry
      // plane's where deal.II's constraints do), a symmetry plane's, a
      // clamp's.
      std::vector<Tensor<1, dim>> fixed_directions;
      bool                        locally_owned = false;

      /** The part of a vector at the node in which V_h lets it move (the
       *  tangent plane of Gamma_3, less any direction a symmetry plane or
       *  a clamp fixes). */
      Tensor<1, dim> tangential(const Tensor<1, dim> &vector) const
      {
        Tensor<1, dim> free = vector;
        for (const Tensor<1, dim> &direction : fixed_directions)
          free -= (vector * direction) * direction;
        return free;
      }
    };

    /** Every process gets every node (collective). */
    Gamma3Map(const DiscreteSpace<dim>              &space,
              const std::vector<types::boundary_id> &contact_ids);

    /** For each of `locations`, the index of the node there; throws where
     *  there is none within round-off of the coordinates' size, or where
     *  two locations have one node. */
    std::vector<unsigned int>
    nodes_at(const std::vector<Point<dim>> &locations) const;

    /** The value of a field at every node, on every process
     *  (collective). */
    std::vector<Tensor<1, dim>> values_at_nodes(const FastVector &field) const;

    /** Adds a force at each node to a load vector, condensed with the
     *  constraints of V_h; compress(add) follows (collective). */
    void add_nodal_forces(const std::vector<Tensor<1, dim>> &forces,
                          VectorType                        &load) const;

    std::vector<Node> nodes;

  private:
    const DiscreteSpace<dim> &space;
  };
} // namespace Contact

#endif
