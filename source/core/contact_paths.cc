/* Gamma_3 seen from the body: the maps C and C^T (friction_solver.h), which
   every path between the body and Gamma_3 uses. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <base/dimensions.h>
#include <core/friction_solver.h>

namespace Contact
{
  // @sect3{ContactBoundary: the maps C and C^T}

  template <int dim>
  unsigned int ContactBoundary<dim>::n_unknowns() const
  {
    return nodes.size() * (dim - 1);
  }


  template <int dim>
  double ContactBoundary<dim>::tangential_velocity(const ContactNode<dim> &node,
                                                   const unsigned int direction,
                                                   const VectorType  &w) const
  {
    double v = 0;
    for (unsigned int d = 0; d < dim; ++d)
      v += node.tangents[direction][d] * w[node.dofs[d]];
    return v;
  }


  // C w: all tangential components on Gamma_3, node-major, on every
  // process (each fills in the nodes it owns).
  template <int dim>
  Vector<double>
  ContactBoundary<dim>::tangential_velocities(const VectorType &w) const
  {
    Vector<double> v(n_unknowns());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (nodes[p].locally_owned)
        for (unsigned int i = 0; i < dim - 1; ++i)
          v[p * (dim - 1) + i] = tangential_velocity(nodes[p], i, w);
    return sum_over_processes(v);
  }


  // The sum of every process's part of a vector on Gamma_3; all processes
  // get the sum.
  template <int dim>
  Vector<double>
  ContactBoundary<dim>::sum_over_processes(const Vector<double> &part) const
  {
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      return part;
    Vector<double> sum(part.size());
    Utilities::MPI::sum(make_array_view(part),
                        mpi_communicator,
                        make_array_view(sum));
    return sum;
  }


  // C^T eta: the nodal friction forces eta_p = sum_i eta_{p,i} t_i as a
  // load on the body, condensed with the constraints like every load.
  template <int dim>
  VectorType
  ContactBoundary<dim>::friction_load(const Vector<double> &eta) const
  {
    VectorType load(locally_owned_dofs, mpi_communicator);
    for (unsigned int p = 0; p < nodes.size(); ++p)
      add_nodal_force(nodes[p], nodes[p].tangential_vector(eta, p), load);
    load.compress(VectorOperation::add);
    return load;
  }


  // A force at a node of Gamma_3 added to a load vector (condensed), by the
  // process that owns the node; compress(add) follows.
  template <int dim>
  void ContactBoundary<dim>::add_nodal_force(const ContactNode<dim> &node,
                                             const Tensor<1, dim>   &force,
                                             VectorType             &load) const
  {
    if (!node.locally_owned || force.norm_square() == 0.)
      return;
    std::vector<types::global_dof_index> node_dofs(node.dofs.begin(),
                                                   node.dofs.end());
    Vector<double>                       node_force(dim);
    for (unsigned int d = 0; d < dim; ++d)
      node_force[d] = force[d];
    constraints.distribute_local_to_global(node_force, node_dofs, load);
  }


#define INSTANTIATE(dim) template struct ContactBoundary<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
