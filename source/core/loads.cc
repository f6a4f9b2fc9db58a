/* The loads of the scheme (5.2): the body force, the tractions and the
   initial values from the .prm's expressions or an exact solution. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <base/dimensions.h>
#include <core/loads.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  namespace
  {
    // The exact solution of the first part that gives one for the
    // parameters, or nullptr.
    template <int dim>
    std::unique_ptr<const ExactSolution<dim>>
    create_exact_solution(const Parameters &parameters)
    {
      for (const auto &part : ExactSolutionParts<dim>::parts())
        if (auto exact = part.create(parameters))
          return exact;
      return nullptr;
    }
  } // namespace


  // @sect4{Loads::Loads}

  template <int dim>
  Loads<dim>::Loads(const Parameters         &run_parameters,
                    const DiscreteSpace<dim> &discrete_space,
                    TimerOutput              &timer)
    : parameters(run_parameters)
    , exact(create_exact_solution<dim>(parameters))
    , space(discrete_space)
    , computing_timer(timer)
    , body_force_is_constant(
        !exact && !expression_uses_variable(parameters.loads.body_force, "t"))
  {
    body_force = parse_vector_function<dim>(Entry::body_force,
                                            parameters.loads.body_force,
                                            true);
    u0         = parse_vector_function<dim>(Entry::initial_displacement,
                                    parameters.loads.initial_displacement,
                                    false);
    u1         = parse_vector_function<dim>(Entry::initial_velocity,
                                    parameters.loads.initial_velocity,
                                    false);
    for (const auto &[id, expression] : parameters.boundary.tractions)
      tractions[id] =
        parse_vector_function<dim>(Entry::tractions + " (boundary id " +
                                     std::to_string(id) + ")",
                                   expression,
                                   true);
    if (exact)
      {
        u0 =
          std::make_unique<typename ExactSolution<dim>::Field>(*exact, false);
        u1 = std::make_unique<typename ExactSolution<dim>::Field>(*exact, true);
      }
  }


  // @sect4{Loads::setup}

  template <int dim>
  void Loads<dim>::setup(const ContactBoundary<dim> &boundary)
  {
    gamma3 = &boundary;
    // (Again on each mesh adapted during the run.)
    owned_cells.clear();
    boundary_cells.clear();
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          owned_cells.push_back(cell);
          if (cell->at_boundary())
            boundary_cells.push_back(cell);
        }
    if (body_force_is_constant)
      assemble_constant_body_load();
  }


  template <int dim>
  const Function<dim> &Loads<dim>::initial_displacement() const
  {
    return *u0;
  }

  template <int dim>
  const Function<dim> &Loads<dim>::initial_velocity() const
  {
    return *u1;
  }


  template <int dim>
  const ExactSolution<dim> *Loads<dim>::exact_solution() const
  {
    return exact.get();
  }


  // @sect4{Loads::visit_loads}

  // F_n = f(t_n) of (5.2): the body force f_0 in Omega and the tractions
  // f_2 on Gamma_2. With an exact solution they come from it (f_2 =
  // sigma n on every side that is neither clamped nor in contact), and its
  // tangential load f_3 on Gamma_3 acts with the nodal weights m_p of the
  // friction term. Every cell that carries a load is handed to `visit_cell`
  // with its (unassembled) cell vector, every node of Gamma_3 with a force
  // to `visit_node`: assemble_load() assembles them, power() tests
  // them with a velocity.
  template <int dim>
  void Loads<dim>::visit_loads(const double       load_time,
                               const bool         with_body_force,
                               const bool         with_surface_loads,
                               const CellVisitor &visit_cell,
                               const NodeVisitor &visit_node) const
  {
    body_force->set_time(load_time);
    for (const auto &traction : tractions)
      traction.second->set_time(load_time);

    // Made once: every step visits the loads twice (F_n and the
    // self-checks' power), and an FEValues object is costly to make.
    if (!cell_values)
      {
        cell_values =
          std::make_unique<FEValues<dim>>(*space.mapping,
                                          space.fe,
                                          space.quadrature,
                                          update_values |
                                            update_quadrature_points |
                                            update_JxW_values);
        face_values =
          std::make_unique<FEFaceValues<dim>>(*space.mapping,
                                              space.fe,
                                              space.face_quadrature,
                                              update_values |
                                                update_quadrature_points |
                                                update_normal_vectors |
                                                update_JxW_values);
      }

    // The surface loads alone (every step, when the body force is constant)
    // touch the boundary cells only.
    Vector<double> cell_rhs(space.fe.n_dofs_per_cell());
    for (const auto &cell : (with_body_force ? owned_cells : boundary_cells))
      {
        cell_rhs = 0;
        if (add_cell_loads(
              cell, load_time, with_body_force, with_surface_loads, cell_rhs))
          visit_cell(cell, cell_rhs);
      }

    if (exact && with_surface_loads)
      for (const ContactNode<dim> &node : gamma3->nodes)
        visit_node(node,
                   node.weight * exact->contact_load(node.location,
                                                     node.normal,
                                                     load_time));
  }


  // @sect4{Loads::add_cell_loads}

  // The loads on one cell, added to its cell vector: the body force when
  // asked for, and the tractions on its faces at the boundary. Returns
  // whether the cell carries a load.
  template <int dim>
  bool Loads<dim>::add_cell_loads(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          load_time,
    const bool                                            with_body_force,
    const bool                                            with_surface_loads,
    Vector<double>                                       &cell_rhs) const
  {
    FEValues<dim>                   &fe_values      = *cell_values;
    FEFaceValues<dim>               &fe_face_values = *face_values;
    const FEValuesExtractors::Vector displacements(0);
    Vector<double>                   value(dim);

    const auto add_force = [&](const FEValuesBase<dim> &values,
                               const auto              &force_at) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Tensor<1, dim> f = force_at(q);
          for (unsigned int i = 0; i < cell_rhs.size(); ++i)
            cell_rhs(i) +=
              values[displacements].value(i, q) * f * values.JxW(q);
        }
    };
    const auto parsed = [&](const FEValuesBase<dim> &values,
                            const Function<dim>     &function) {
      return [&](const unsigned int q) {
        function.vector_value(values.quadrature_point(q), value);
        Tensor<1, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = value[d];
        return f;
      };
    };

    bool loaded = with_body_force;
    if (with_body_force)
      {
        fe_values.reinit(cell);
        if (exact)
          add_force(fe_values, [&](const unsigned int q) {
            return exact->body_force(fe_values.quadrature_point(q), load_time);
          });
        else
          add_force(fe_values, parsed(fe_values, *body_force));
      }
    for (const unsigned int f : cell->face_indices())
      if (with_surface_loads && cell->face(f)->at_boundary())
        {
          const types::boundary_id id = cell->face(f)->boundary_id();
          if (exact && is_free_side(id))
            {
              fe_face_values.reinit(cell, f);
              add_force(fe_face_values, [&](const unsigned int q) {
                return exact->stress(fe_face_values.quadrature_point(q),
                                     load_time) *
                       fe_face_values.normal_vector(q);
              });
              loaded = true;
            }
          else if (!exact && tractions.count(id) != 0)
            {
              fe_face_values.reinit(cell, f);
              add_force(fe_face_values,
                        parsed(fe_face_values, *tractions.at(id)));
              loaded = true;
            }
        }
    return loaded;
  }


  // A side that is neither clamped nor in contact: an exact solution's
  // traction acts on it.
  template <int dim>
  bool Loads<dim>::is_free_side(const types::boundary_id id) const
  {
    const auto &boundary = parameters.boundary;
    return std::count(boundary.clamped_ids.begin(),
                      boundary.clamped_ids.end(),
                      id) +
             std::count(boundary.contact_ids.begin(),
                        boundary.contact_ids.end(),
                        id) ==
           0;
  }


  // @sect4{Loads::assemble}

  // F_n of a step: the loads at t_n, with a constant body force added from
  // its vector assembled once.
  template <int dim>
  void Loads<dim>::assemble(const double load_time,
                            VectorType  &load_vector) const
  {
    assemble_load(load_time, load_vector, !body_force_is_constant);
    if (body_force_is_constant)
      load_vector += constant_body_load;
  }


  // @sect4{Loads::assemble_load}

  // The load vector, condensed with the constraints like the matrices.
  template <int dim>
  void Loads<dim>::assemble_load(const double load_time,
                                 VectorType  &load_vector,
                                 const bool   with_body_force) const
  {
    TimerOutput::Scope                   t(computing_timer, "Assembly");
    std::vector<types::global_dof_index> dof_indices(
      space.fe.n_dofs_per_cell());
    load_vector = 0;
    visit_loads(
      load_time,
      with_body_force,
      true,
      [&](const auto &cell, const Vector<double> &cell_rhs) {
        cell->get_dof_indices(dof_indices);
        space.constraints.distribute_local_to_global(cell_rhs,
                                                     dof_indices,
                                                     load_vector);
      },
      [&](const ContactNode<dim> &node, const Tensor<1, dim> &force) {
        gamma3->add_nodal_force(node, force, load_vector);
      });
    load_vector.compress(VectorOperation::add);
  }


  // @sect4{Loads::assemble_constant_body_load}

  // A body force that does not depend on t is assembled once: condensed
  // for F_n, and without the constraints for power(), where the sum of its
  // cell vectors' products with a field's cell values is the dot product
  // of the field with it.
  template <int dim>
  void Loads<dim>::assemble_constant_body_load()
  {
    TimerOutput::Scope                   t(computing_timer, "Assembly");
    std::vector<types::global_dof_index> dof_indices(
      space.fe.n_dofs_per_cell());
    constant_body_load.reinit(space.locally_owned_dofs, space.mpi_communicator);
    unconstrained_body_load.reinit(space.locally_owned_dofs,
                                   space.locally_relevant_dofs,
                                   space.mpi_communicator);
    visit_loads(
      0.,
      true,
      false,
      [&](const auto &cell, const Vector<double> &cell_rhs) {
        cell->get_dof_indices(dof_indices);
        space.constraints.distribute_local_to_global(cell_rhs,
                                                     dof_indices,
                                                     constant_body_load);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          unconstrained_body_load[dof_indices[i]] += cell_rhs[i];
      },
      [](const ContactNode<dim> &, const Tensor<1, dim> &) {});
    constant_body_load.compress(VectorOperation::add);
    unconstrained_body_load.compress(VectorOperation::add);
  }


  // @sect4{Loads::power}

  // F(t) . w for fields w in V_h (ghosted), from the loads' expressions at
  // time t and the fields' values on each cell, without the assembled load
  // vector: int f_0 . w_h dx + int_Gamma2 f_2 . w_h ds (+ the nodal f_3 of
  // an exact solution), with the quadrature of the assembly. The
  // loads are evaluated once for all fields (the velocity's power and the
  // rotation's moment), and with each the sum of the magnitudes of the
  // products it adds up (of every cell's and node's entry, and of every
  // entry of a body force constant in time, which is integrated once:
  // unconstrained_body_load), the scale of its round-off.
  template <int dim>
  std::vector<LoadPower>
  Loads<dim>::power(const double                           load_time,
                    const std::vector<const FastVector *> &fields) const
  {
    Vector<double> w_cell(space.fe.n_dofs_per_cell());
    // Power and magnitude of field i at 2 i and 2 i + 1, summed at once.
    std::vector<double> sums(2 * fields.size());
    const auto          add = [&](const unsigned int i, const double product) {
      sums[2 * i] += product;
      sums[2 * i + 1] += std::abs(product);
    };
    const auto add_cell = [&](const auto           &cell,
                              const Vector<double> &cell_rhs) {
      for (unsigned int i = 0; i < fields.size(); ++i)
        {
          cell->get_dof_values(*fields[i], w_cell);
          for (unsigned int j = 0; j < w_cell.size(); ++j)
            add(i, cell_rhs[j] * w_cell[j]);
        }
    };
    visit_loads(load_time,
                !body_force_is_constant,
                true,
                add_cell,
                [&](const ContactNode<dim> &node, const Tensor<1, dim> &force) {
                  if (node.locally_owned)
                    for (unsigned int i = 0; i < fields.size(); ++i)
                      for (unsigned int d = 0; d < dim; ++d)
                        add(i, force[d] * (*fields[i])[node.dofs[d]]);
                });
    if (body_force_is_constant)
      for (unsigned int j = 0; j < unconstrained_body_load.locally_owned_size();
           ++j)
        for (unsigned int i = 0; i < fields.size(); ++i)
          add(i,
              unconstrained_body_load.local_element(j) *
                fields[i]->local_element(j));
    Utilities::MPI::sum(sums, space.mpi_communicator, sums);
    std::vector<LoadPower> result(fields.size());
    for (unsigned int i = 0; i < fields.size(); ++i)
      result[i] = {sums[2 * i], sums[2 * i + 1]};
    return result;
  }



#define INSTANTIATE(dim) template class Loads<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
