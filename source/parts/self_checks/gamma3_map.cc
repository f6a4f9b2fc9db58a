/* Gamma_3 as the self-checks see it: its nodes' dofs, weights and tangent
   planes from the mesh, the element and the constraints of V_h,
   independently of the friction solver's node list (contact_nodes.cc). */

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/rtree.h>

#include <base/dimensions.h>
#include <core/contact_nodes.h>
#include <parts/self_checks/gamma3_map.h>

#include <map>
#include <set>
#include <sstream>

namespace Contact
{
  namespace
  {
    // Calls `visit(cell, face)` for each Gamma_3 face of this process's
    // cells.
    template <int dim, typename Visit>
    void for_each_contact_face(const DiscreteSpace<dim>           &space,
                               const std::set<types::boundary_id> &ids,
                               const Visit                        &visit)
    {
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                ids.count(cell->face(f)->boundary_id()) != 0)
              visit(cell, f);
    }


    // @sect4{contact_weights}

    // The weights int psi_p ds of the basis functions psi_p of V_h on
    // Gamma_3, with the space's face rule, assembled as a load and condensed
    // by the hanging nodes' constraints (a hanging node's integral goes to
    // the nodes it follows; the friction solver adds these shares node by
    // node instead). Ghosted: read at every node of this process's faces.
    template <int dim>
    VectorType contact_weights(const DiscreteSpace<dim>           &space,
                               const std::set<types::boundary_id> &ids)
    {
      const FiniteElement<dim>            &fe = space.fe;
      FEFaceValues<dim>                    integrals(*space.mapping,
                                  fe,
                                  space.face_quadrature,
                                  update_values | update_JxW_values);
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      VectorType assembled(space.locally_owned_dofs, space.mpi_communicator);
      Vector<double> cell_weights(fe.n_dofs_per_cell());
      for_each_contact_face(space, ids, [&](const auto &cell, const auto f) {
        integrals.reinit(cell, f);
        cell->get_dof_indices(cell_dofs);
        cell_weights = 0;
        for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
          {
            const unsigned int i = fe.face_to_cell_index(j, f);
            if (fe.system_to_component_index(i).first == 0)
              for (const unsigned int q : integrals.quadrature_point_indices())
                cell_weights[i] +=
                  integrals.shape_value_component(i, q, 0) * integrals.JxW(q);
          }
        space.hanging_node_constraints.distribute_local_to_global(cell_weights,
                                                                  cell_dofs,
                                                                  assembled);
      });
      assembled.compress(VectorOperation::add);
      return space.ghosted(assembled);
    }


    // @sect4{contact_node_records}

    // Per node of this process's Gamma_3 faces, one record of
    // `record_size<dim>` numbers: dofs, location, weight, the number of
    // fixed directions and the directions (a node on several faces or
    // processes has several records).
    template <int dim>
    constexpr unsigned int record_size = (dim + 2) * dim + 2;

    template <int dim>
    std::vector<double>
    contact_node_records(const DiscreteSpace<dim>           &space,
                         const std::set<types::boundary_id> &ids,
                         const VectorType                   &weights)
    {
      const FiniteElement<dim>            &fe = space.fe;
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      std::vector<double>                  records;
      for_each_contact_face(space, ids, [&](const auto &cell, const auto f) {
        cell->get_dof_indices(cell_dofs);
        for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
          {
            const unsigned int i = fe.face_to_cell_index(j, f);
            const auto [component, base_index] =
              fe.system_to_component_index(i);
            // A hanging node is no node of V_h (with Q2 it may lie where
            // the coarse edge's own node is).
            if (component != 0 ||
                space.hanging_node_constraints.is_constrained(cell_dofs[i]))
              continue;
            std::array<types::global_dof_index, dim> dofs;
            for (unsigned int d = 0; d < dim; ++d)
              dofs[d] = cell_dofs[fe.component_to_system_index(d, base_index)];
            records.insert(records.end(), dofs.begin(), dofs.end());
            const Point<dim> x = space.mapping->transform_unit_to_real_cell(
              cell, fe.base_element(0).unit_support_point(base_index));
            for (unsigned int d = 0; d < dim; ++d)
              records.push_back(x[d]);
            records.push_back(weights(dofs[0]));
            const auto fixed = fixed_directions<dim>(dofs, space.constraints);
            records.push_back(fixed.size());
            for (unsigned int r = 0; r < dim; ++r)
              for (unsigned int d = 0; d < dim; ++d)
                records.push_back(r < fixed.size() ? fixed[r][d] : 0.);
          }
      });
      return records;
    }
  } // namespace


  // @sect4{Gamma3Map::Gamma3Map}

  // Each process integrates the weights over the Gamma_3 faces of its own
  // cells and reads the constraints of the nodes there; the records of all
  // processes are gathered on every process, one node per first dof.
  template <int dim>
  Gamma3Map<dim>::Gamma3Map(const DiscreteSpace<dim> &discrete_space,
                            const std::vector<types::boundary_id> &contact_ids)
    : space(discrete_space)
  {
    const std::set<types::boundary_id> ids(contact_ids.begin(),
                                           contact_ids.end());
    const std::vector<double>          records =
      contact_node_records(space, ids, contact_weights(space, ids));

    std::map<types::global_dof_index, Node> by_dof;
    for (const auto &part :
         Utilities::MPI::all_gather(space.mpi_communicator, records))
      for (auto r = part.begin(); r != part.end(); r += record_size<dim>)
        {
          const auto key = static_cast<types::global_dof_index>(r[0]);
          if (by_dof.count(key) != 0)
            continue;
          Node &node  = by_dof[key];
          node.weight = r[2 * dim];
          for (unsigned int d = 0; d < dim; ++d)
            {
              node.dofs[d]     = static_cast<types::global_dof_index>(r[d]);
              node.location[d] = r[dim + d];
            }
          node.fixed_directions.resize(
            static_cast<unsigned int>(r[2 * dim + 1]));
          for (unsigned int i = 0; i < node.fixed_directions.size(); ++i)
            for (unsigned int d = 0; d < dim; ++d)
              node.fixed_directions[i][d] = r[2 * dim + 2 + i * dim + d];
        }
    for (auto &[dof, node] : by_dof)
      {
        node.locally_owned = space.locally_owned_dofs.is_element(dof);
        nodes.push_back(node);
      }
  }


  // @sect4{Gamma3Map::nodes_at}

  // A location's node: the nearest, if it is there to round-off of the
  // coordinates' size; no two locations may share one.
  template <int dim>
  std::vector<unsigned int>
  Gamma3Map<dim>::nodes_at(const std::vector<Point<dim>> &locations) const
  {
    std::vector<Point<dim>> points;
    double                  size = 0;
    for (const Node &node : nodes)
      {
        points.push_back(node.location);
        size = std::max(
          {size, node.location.norm(), node.location.distance(points.front())});
      }
    const auto                tree = pack_rtree_of_indices(points);
    std::vector<unsigned int> indices;
    std::vector<bool>         taken(points.size(), false);
    for (const Point<dim> &x : locations)
      {
        std::vector<unsigned int> nearest;
        tree.query(boost::geometry::index::nearest(x, 1),
                   std::back_inserter(nearest));
        std::ostringstream where;
        where << x;
        AssertThrow(!nearest.empty() &&
                      points[nearest[0]].distance(x) <= 1e-10 * size &&
                      !taken[nearest[0]],
                    ExcMessage("Self-check failed: the friction solver has a "
                               "node of Gamma_3 at (" +
                               where.str() +
                               ") where the mesh has no node of Gamma_3 that "
                               "no other node of the solver has taken."));
        taken[nearest[0]] = true;
        indices.push_back(nearest[0]);
      }
    return indices;
  }


  // @sect4{Gamma3Map::values_at_nodes}

  template <int dim>
  std::vector<Tensor<1, dim>>
  Gamma3Map<dim>::values_at_nodes(const FastVector &field) const
  {
    std::vector<double> values(nodes.size() * dim);
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (nodes[p].locally_owned)
        for (unsigned int d = 0; d < dim; ++d)
          values[p * dim + d] = field(nodes[p].dofs[d]);
    Utilities::MPI::sum(values, space.mpi_communicator, values);
    std::vector<Tensor<1, dim>> result(nodes.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      for (unsigned int d = 0; d < dim; ++d)
        result[p][d] = values[p * dim + d];
    return result;
  }


  // @sect4{Gamma3Map::add_nodal_forces}

  template <int dim>
  void
  Gamma3Map<dim>::add_nodal_forces(const std::vector<Tensor<1, dim>> &forces,
                                   VectorType &load) const
  {
    AssertDimension(forces.size(), nodes.size());
    Vector<double>                       force(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (nodes[p].locally_owned)
        {
          for (unsigned int d = 0; d < dim; ++d)
            {
              force[d] = forces[p][d];
              dofs[d]  = nodes[p].dofs[d];
            }
          space.constraints.distribute_local_to_global(force, dofs, load);
        }
    load.compress(VectorOperation::add);
  }


#define INSTANTIATE(dim) template class Gamma3Map<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
