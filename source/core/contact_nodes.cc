/* The nodes of Gamma_3: their dofs, weights, normals and tangents, from
   the faces of the space's mesh. */

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>

#include <base/dimensions.h>
#include <core/parameters.h>
#include <core/contact_nodes.h>

#include <algorithm>
#include <map>
#include <set>

namespace Contact
{
  // @sect4{fixed_directions}

  // The rows of the constraints of one node's dofs, orthonormal
  // (Gram-Schmidt): u_d - sum_e c_de u_e for each constrained dof d.
  template <int dim>
  std::vector<Tensor<1, dim>>
  fixed_directions(const std::array<types::global_dof_index, dim> &dofs,
                   const AffineConstraints<double>                &constraints)
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
    // Both overloads are [[maybe_unused]]: a build of one dimension
    // (CONTACT_DIMENSIONS) calls one of them.
    [[maybe_unused]] std::array<Tensor<1, 2>, 1>
    tangent_basis(const Tensor<1, 2> &normal, const unsigned int = 0)
    {
      return {{Tensor<1, 2>({-normal[1], normal[0]})}};
    }

    // `preferred`: the axis least aligned with all of Gamma_3's normals,
    // so that t_1 is the same direction along a curved Gamma_3 (the axis
    // of a tube), where it is not too close to this node's normal.
    [[maybe_unused]] std::array<Tensor<1, 3>, 2>
    tangent_basis(const Tensor<1, 3> &normal, const unsigned int preferred = 3)
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

    // @sect4{integrate_contact_faces}

    // What a hanging node of Gamma_3 gives to the nodes its value follows:
    // its weight and normal, times the constraint's coefficients.
    template <int dim>
    struct HangingShare
    {
      double         weight = 0;
      Tensor<1, dim> normal;
    };

    // This process's part of the nodes of Gamma_3: the faces of its own
    // cells, keyed by the node's first dof, and the shares of the hanging
    // nodes among them (a refined part of Gamma_3 in 3D; doc/algorithm.md):
    // the friction term takes the nodes of V_h, whose basis functions on
    // Gamma_3 are psi_q = phi_q + sum_h c_hq phi_h over the hanging nodes h
    // with u_h = sum_q c_hq u_q, so m_q = int phi_q ds + sum_h c_hq m_h.
    template <int dim>
    std::pair<std::map<types::global_dof_index, ContactNode<dim>>,
              std::map<types::global_dof_index, HangingShare<dim>>>
    integrate_contact_faces(const DiscreteSpace<dim>              &space,
                            const std::vector<types::boundary_id> &ids)
    {
      const std::set<types::boundary_id>   contact_ids(ids.begin(), ids.end());
      const FiniteElement<dim>            &fe      = space.fe;
      const Mapping<dim>                  &mapping = *space.mapping;
      FEFaceValues<dim>                    fe_face_values(mapping,
                                       fe,
                                       space.face_quadrature,
                                       update_values | update_normal_vectors |
                                         update_JxW_values);
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> scalar_dofs(
        space.scalar_fe->n_dofs_per_cell());
      std::map<types::global_dof_index, ContactNode<dim>>  nodes;
      std::map<types::global_dof_index, HangingShare<dim>> shares;
      const AffineConstraints<double> &hanging = space.hanging_node_constraints;

      auto scalar_cell = space.scalar_dof_handler.begin_active();
      for (const auto &cell : space.dof_handler.active_cell_iterators())
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
                    HangingShare<dim> part;
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      {
                        const double phi_JxW =
                          fe_face_values.shape_value_component(i, q, 0) *
                          fe_face_values.JxW(q);
                        part.weight += phi_JxW;
                        part.normal +=
                          fe_face_values.normal_vector(q) * std::abs(phi_JxW);
                      }
                    if (hanging.is_constrained(cell_dofs[i]))
                      {
                        for (const auto &[master, c] :
                             *hanging.get_constraint_entries(cell_dofs[i]))
                          {
                            shares[master].weight += c * part.weight;
                            shares[master].normal += std::abs(c) * part.normal;
                          }
                        continue;
                      }
                    ContactNode<dim> &node = nodes[cell_dofs[i]];
                    for (unsigned int d = 0; d < dim; ++d)
                      node.dofs[d] =
                        cell_dofs[fe.component_to_system_index(d, base_index)];
                    node.scalar_dof = scalar_dofs[base_index];
                    node.location   = mapping.transform_unit_to_real_cell(
                      cell, fe.base_element(0).unit_support_point(base_index));
                    node.weight += part.weight;
                    node.normal += part.normal;
                  }
              }
        }
      return {nodes, shares};
    }


    // @sect4{add_hanging_shares}

    // The hanging nodes' shares, to the nodes they follow (each of which
    // is a node of a face of Gamma_3 on some process).
    template <int dim>
    void add_hanging_shares(
      const std::map<types::global_dof_index, HangingShare<dim>> &own_shares,
      const MPI_Comm                                              communicator,
      std::map<types::global_dof_index, ContactNode<dim>>        &nodes)
    {
      std::vector<double> share_records;
      for (const auto &[key, share] : own_shares)
        {
          share_records.push_back(key);
          share_records.push_back(share.weight);
          for (unsigned int d = 0; d < dim; ++d)
            share_records.push_back(share.normal[d]);
        }
      for (const auto &part :
           Utilities::MPI::all_gather(communicator, share_records))
        for (auto r = part.begin(); r != part.end(); r += dim + 2)
          {
            const auto key = static_cast<types::global_dof_index>(r[0]);
            // With Q2 in 3D a hanging node on the border of Gamma_3 can follow
            // the node in the middle of a coarse edge that no face of
            // Gamma_3 has (Gamma_3 meets another boundary part along a
            // refined edge).
            AssertThrow(
              nodes.count(key) == 1,
              ExcMessage("A refined cell of Gamma_3 meets a coarser cell of "
                         "another boundary part on the border of Gamma_3, and "
                         "its hanging node there follows a node that is not "
                         "on Gamma_3: this is not supported with "
                         "'" +
                         Entry::finite_element_degree +
                         "' > 1; allowed are degree 1, or a refinement ("
                         "'" +
                         Entry::refinement_points +
                         "', 'Mesh adaptation/Cycles') that does not reach the "
                         "border of Gamma_3."));
            nodes[key].weight += r[1];
            for (unsigned int d = 0; d < dim; ++d)
              nodes[key].normal[d] += r[2 + d];
          }
    }


    // The axis least aligned with all normals (the first on ties).
    template <int dim>
    unsigned int least_aligned_axis(
      const std::map<types::global_dof_index, ContactNode<dim>> &nodes)
    {
      std::array<double, dim> largest{};
      for (const auto &[key, node] : nodes)
        for (unsigned int d = 0; d < dim; ++d)
          largest[d] =
            std::max(largest[d], std::abs(node.normal[d]) / node.normal.norm());
      return static_cast<unsigned int>(
        std::min_element(largest.begin(), largest.end()) - largest.begin());
    }
  } // namespace


  // @sect4{make_contact_nodes}

  // Collects the nodes of Gamma_3 with their dofs, the weight
  // m_p = int_Gamma3 psi_p ds of the nodal ("node-to-rigid") friction (psi_p
  // the basis function of V_h: phi_p and the shares of the hanging nodes
  // that follow p) and the outward normal averaged over the faces around
  // the node. A node all of whose dofs are constrained (where Gamma_3 meets
  // the clamp, or a hanging node) has no friction unknown and is left out.
  //
  // Every process keeps every node: the friction problem on Gamma_3 is
  // small and solved redundantly, so that all processes take the same
  // branches. Each process integrates over the faces of its own cells; the
  // parts are exchanged (all_gather) and summed, and the constraint rows of
  // a node (known where its dofs are locally relevant) travel with them.
  template <int dim>
  std::vector<ContactNode<dim>>
  make_contact_nodes(const DiscreteSpace<dim>              &space,
                     const std::vector<types::boundary_id> &contact_ids)
  {
    const MPI_Comm communicator = space.mpi_communicator;
    // One record per (process, node) as doubles (dof indices are exact):
    // dofs, scalar dof, location, weight, normal, number of constraint
    // rows, the rows.
    constexpr unsigned int record_size =
      dim + 1 + dim + 1 + dim + 1 + dim * dim;
    const auto [own_nodes, own_shares] =
      integrate_contact_faces(space, contact_ids);
    std::vector<double> records;
    for (const auto &[key, node] : own_nodes)
      {
        const auto constrained =
          fixed_directions<dim>(node.dofs, space.constraints);
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
    for (const auto &part : Utilities::MPI::all_gather(communicator, records))
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

    add_hanging_shares(own_shares, communicator, nodes);

    const unsigned int preferred = least_aligned_axis(nodes);

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
        node.locally_owned = space.locally_owned_dofs.is_element(node.dofs[0]);
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



#define INSTANTIATE(dim)                                                  \
  template std::vector<ContactNode<dim>> make_contact_nodes(              \
    const DiscreteSpace<dim> &, const std::vector<types::boundary_id> &); \
  template std::vector<Tensor<1, dim>> fixed_directions<dim>(             \
    const std::array<types::global_dof_index, dim> &,                     \
    const AffineConstraints<double> &);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
