/* The interpolation of a convergence study's levels into the reference's
 * finite element space (include/parts/studies/reference_interpolation.h). */

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/array_view.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/numerics/rtree.h>

#include <base/dimensions.h>
#include <parts/studies/reference_interpolation.h>

#include <limits>
#include <utility>

namespace Contact
{
  namespace
  {
    // The value of a field at a point of a cell, given in the cell's unit
    // coordinates, from the element's shape functions.
    template <int dim>
    Tensor<1, dim>
    value_in_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const Point<dim>                                     &unit,
                  const VectorType &ghosted_field)
    {
      const FiniteElement<dim>            &fe = cell->get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      cell->get_dof_indices(dof_indices);
      Tensor<1, dim> value;
      for (unsigned int i = 0; i < dof_indices.size(); ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          value[c] += ghosted_field(dof_indices[i]) *
                      fe.shape_value_component(i, unit, c);
        }
      return value;
    }


    template <int dim>
    using CellBox = std::pair<BoundingBox<dim>,
                              typename DoFHandler<dim>::active_cell_iterator>;

    // An R-tree of the bounding boxes of this process's cells, each widened
    // by round-off of the cell's size.
    template <int dim>
    RTree<CellBox<dim>> cell_tree(const DoFHandler<dim> &dof_handler)
    {
      std::vector<CellBox<dim>> boxes;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            BoundingBox<dim> box = cell->bounding_box();
            box.extend(1e-10 * cell->diameter());
            boxes.emplace_back(box, cell);
          }
      return pack_rtree(boxes);
    }


    // Per node, whether any process has it in one of its cells.
    template <int dim>
    std::vector<unsigned int> found_by_some_process(
      const std::vector<typename ReferenceInterpolation<dim>::NodeInCell>
                        &located,
      const unsigned int n_nodes)
    {
      std::vector<unsigned int> found(n_nodes, 0);
      for (const auto &node : located)
        found[node.node] = 1;
      Utilities::MPI::max(found, MPI_COMM_WORLD, found);
      return found;
    }


    // Per node, the process that takes it: the one with the nearest cell
    // (the lowest rank among equals), where that is within 0.1 of the unit
    // cell; invalid_unsigned_int where no process takes it.
    std::vector<unsigned int>
    nearest_process(const std::vector<double> &distance)
    {
      std::vector<double> smallest(distance.size());
      Utilities::MPI::min(distance, MPI_COMM_WORLD, smallest);
      std::vector<unsigned int> taker(distance.size());
      for (unsigned int m = 0; m < distance.size(); ++m)
        taker[m] = (distance[m] < 0.1 && distance[m] == smallest[m]) ?
                     Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) :
                     numbers::invalid_unsigned_int;
      Utilities::MPI::min(taker, MPI_COMM_WORLD, taker);
      return taker;
    }


    // @sect4{add_nodes_outside_every_cell}

    // A node on a curved boundary may lie just outside every cell of a
    // coarser level (the coarse cells' boundary is the mapping's polynomial,
    // or the chord, not the circle): the nearest cell of all processes takes
    // it, at its projection onto that cell. (Only on meshes of hypercubes,
    // whose distance to the unit cell deal.II 9.4 knows; the reductions are
    // collective either way.)
    template <int dim>
    void add_nodes_outside_every_cell(
      const ContactProblem<dim>                                     &level,
      const RTree<CellBox<dim>>                                     &tree,
      const std::vector<Point<dim>>                                 &all_nodes,
      std::vector<typename ReferenceInterpolation<dim>::NodeInCell> &located)
    {
      const bool hypercubes = level.get_dof_handler()
                                .get_triangulation()
                                .all_reference_cells_are_hyper_cube();
      const std::vector<unsigned int> found =
        found_by_some_process<dim>(located, all_nodes.size());
      std::vector<double> distance(all_nodes.size(),
                                   std::numeric_limits<double>::max());
      std::vector<typename ReferenceInterpolation<dim>::NodeInCell> nearest(
        all_nodes.size());
      for (unsigned int m = 0; m < all_nodes.size(); ++m)
        if (found[m] == 0 && hypercubes)
          for (const auto &[box, cell] :
               tree | boost::geometry::index::adaptors::queried(
                        boost::geometry::index::nearest(all_nodes[m], 4)))
            try
              {
                const Point<dim> unit =
                  level.get_mapping().transform_real_to_unit_cell(cell,
                                                                  all_nodes[m]);
                const double d = GeometryInfo<dim>::distance_to_unit_cell(unit);
                if (d < distance[m])
                  {
                    distance[m] = d;
                    nearest[m]  = {
                       m, cell, GeometryInfo<dim>::project_to_unit_cell(unit)};
                  }
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {}
      const std::vector<unsigned int> taker = nearest_process(distance);
      for (unsigned int m = 0; m < all_nodes.size(); ++m)
        if (taker[m] == Utilities::MPI::this_mpi_process(MPI_COMM_WORLD))
          located.push_back(nearest[m]);
    }
  } // namespace


  // @sect4{ReferenceInterpolation::ReferenceInterpolation}

  // A node is a support point of the first component's shape functions;
  // the unknowns of the other components at it follow from the element.
  // Every process gets the coordinates of all nodes (those of a reference
  // with 10^6 nodes take 24 MB in 3D, which convergence studies can
  // afford).
  template <int dim>
  ReferenceInterpolation<dim>::ReferenceInterpolation(
    const ContactProblem<dim> &reference)
    : owned_dofs(reference.get_dof_handler().locally_owned_dofs())
  {
    const DoFHandler<dim>    &dof_handler = reference.get_dof_handler();
    const FiniteElement<dim> &fe          = dof_handler.get_fe();
    FEValues<dim>             fe_values(reference.get_mapping(),
                            fe,
                            Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::vector<bool>                    seen(owned_dofs.n_elements(), false);
    std::vector<Point<dim>>              node_points;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            {
              const auto [component, node] = fe.system_to_component_index(i);
              if (component != 0 || !owned_dofs.is_element(cell_dofs[i]) ||
                  seen[owned_dofs.index_within_set(cell_dofs[i])])
                continue;
              seen[owned_dofs.index_within_set(cell_dofs[i])] = true;
              std::array<types::global_dof_index, dim> dofs;
              for (unsigned int c = 0; c < dim; ++c)
                dofs[c] = cell_dofs[fe.component_to_system_index(c, node)];
              node_dofs.push_back(dofs);
              node_points.push_back(fe_values.quadrature_point(i));
            }
        }

    const std::vector<std::vector<Point<dim>>> nodes_per_process =
      Utilities::MPI::all_gather(MPI_COMM_WORLD, node_points);
    for (unsigned int p = 0; p < nodes_per_process.size(); ++p)
      {
        if (p == Utilities::MPI::this_mpi_process(MPI_COMM_WORLD))
          first_node = all_nodes.size();
        all_nodes.insert(all_nodes.end(),
                         nodes_per_process[p].begin(),
                         nodes_per_process[p].end());
      }
  }


  // @sect4{ReferenceInterpolation::locate}

  // Candidates from an R-tree of the cells' bounding boxes, then the inverse
  // of the cell's mapping. (deal.II 9.4's
  // Utilities::MPI::RemotePointEvaluation, which would send each node only
  // to the processes whose part of the mesh may hold it, is wrong on
  // simplex meshes: it misses some nodes on several processes, and the
  // V-norm of a P1 field interpolated into a nested finer space changed by
  // 0.5 %, measured on one process too. Here it is kept to all digits.)
  template <int dim>
  std::vector<typename ReferenceInterpolation<dim>::NodeInCell>
  ReferenceInterpolation<dim>::locate(const ContactProblem<dim> &level) const
  {
    const auto              tree = cell_tree(level.get_dof_handler());
    std::vector<NodeInCell> located;
    for (unsigned int m = 0; m < all_nodes.size(); ++m)
      for (const auto &[box, cell] :
           tree | boost::geometry::index::adaptors::queried(
                    boost::geometry::index::intersects(all_nodes[m])))
        try
          {
            const Point<dim> unit =
              level.get_mapping().transform_real_to_unit_cell(cell,
                                                              all_nodes[m]);
            if (cell->reference_cell().contains_point(unit, 1e-10))
              {
                located.push_back({m, cell, unit});
                break;
              }
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {}
    add_nodes_outside_every_cell(level, tree, all_nodes, located);
    return located;
  }


  // @sect4{ReferenceInterpolation::operator()}

  // Each process evaluates the field at the nodes in its cells; the sums
  // over the processes, with the number of processes that found each node,
  // give every node's value (a node on the boundary between two processes'
  // cells is found by both; the field is continuous, so they agree).
  template <int dim>
  VectorType ReferenceInterpolation<dim>::operator()(
    const std::vector<NodeInCell> &located,
    const ContactProblem<dim>     &level,
    const VectorType              &field) const
  {
    const VectorType    ghosted_field = level.ghosted(field);
    std::vector<double> sums(all_nodes.size() * (dim + 1), 0.);
    for (const NodeInCell &node : located)
      {
        const Tensor<1, dim> value =
          value_in_cell(node.cell, node.unit_point, ghosted_field);
        for (unsigned int c = 0; c < dim; ++c)
          sums[node.node * (dim + 1) + c] += value[c];
        sums[node.node * (dim + 1) + dim] += 1.;
      }
    Utilities::MPI::sum(sums, MPI_COMM_WORLD, sums);

    VectorType result(owned_dofs, MPI_COMM_WORLD);
    for (unsigned int j = 0; j < node_dofs.size(); ++j)
      {
        const double *sum = &sums[(first_node + j) * (dim + 1)];
        AssertThrow(sum[dim] > 0,
                    ExcMessage("Convergence study: a node of the reference "
                               "mesh lies outside the mesh of a coarser "
                               "level; the levels must cover the same "
                               "domain."));
        for (unsigned int c = 0; c < dim; ++c)
          result(node_dofs[j][c]) = sum[c] / sum[dim];
      }
    result.compress(VectorOperation::insert);
    return result;
  }


#define INSTANTIATE(dim) template class ReferenceInterpolation<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
