/* Matrices and loads of the scheme (5.2)-(5.5), initial values, energies. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <core/contact_problem.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  // @sect4{ContactProblem::assemble_matrices}

  // The three bilinear forms of (5.2) on V_h: the mass (rho w, v), the
  // viscosity (A eps(w), eps(v)) with A tau = mu_1 tr(tau) I + mu_2 tau and
  // the elasticity (B eps(u), eps(v)) with
  // B tau = lambda tr(tau) I + 2G tau, lambda = E kappa/((1+kappa)(1-2kappa)),
  // 2G = E/(1+kappa) (the paper's formula, plane strain in 2D; plane
  // stress replaces lambda by 2 lambda G/(lambda + 2G)). A lumped mass
  // matrix comes from the Gauss-Lobatto rule, whose points are the nodes of
  // Q_p: M is then diagonal. The constant
  // matrix of a step follows from backward Euler, (5.2) with (5.5):
  //   K w_n = F_n + (1/k) M w_{n-1} - B u_{n-1} - C^T eta_n,
  //   K = (1/k) M + A + k B.
  template <int dim>
  void ContactProblem<dim>::assemble_matrices()
  {
    TimerOutput::Scope t(computing_timer, "Assembly");

    const auto  &material = parameters.material;
    const double two_G    = material.two_G();
    const double lambda   = material.lambda(dim);
    const double rho      = material.density;
    const double mu1      = material.viscosity_mu1;
    const double mu2      = material.viscosity_mu2;

    FEValues<dim>                        fe_values(*mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim>                        mass_values(*mapping,
                              fe,
                              mass_quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    const unsigned int                   n_dofs = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_mass(n_dofs, n_dofs);
    FullMatrix<double>                   cell_viscosity(n_dofs, n_dofs);
    FullMatrix<double>                   cell_elasticity(n_dofs, n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    std::vector<Tensor<1, dim>>          phi(n_dofs);
    std::vector<SymmetricTensor<2, dim>> eps(n_dofs);
    std::vector<double>                  div(n_dofs);
    std::vector<Vector<double>> cell_momentum(dim, Vector<double>(n_dofs));
    Vector<double>              cell_angular_momentum(n_dofs);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          mass_values.reinit(cell);
          cell_mass       = 0;
          cell_viscosity  = 0;
          cell_elasticity = 0;
          for (auto &vector : cell_momentum)
            vector = 0;
          cell_angular_momentum = 0;
          for (const unsigned int q : mass_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n_dofs; ++i)
                phi[i] = mass_values[displacements].value(i, q);
              const double      JxW = mass_values.JxW(q);
              const Point<dim> &x   = mass_values.quadrature_point(q);
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    cell_momentum[d](i) += rho * phi[i][d] * JxW;
                  cell_angular_momentum(i) +=
                    rho * (x[0] * phi[i][1] - x[1] * phi[i][0]) * JxW;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    cell_mass(i, j) += rho * phi[i] * phi[j] * JxW;
                }
            }
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  eps[i] = fe_values[displacements].symmetric_gradient(i, q);
                  div[i] = trace(eps[i]);
                }
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n_dofs; ++i)
                for (unsigned int j = 0; j < n_dofs; ++j)
                  {
                    const double div_div = div[i] * div[j];
                    const double eps_eps = eps[i] * eps[j];
                    cell_viscosity(i, j) +=
                      (mu1 * div_div + mu2 * eps_eps) * JxW;
                    cell_elasticity(i, j) +=
                      (lambda * div_div + two_G * eps_eps) * JxW;
                  }
            }
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_mass,
                                                 dof_indices,
                                                 mass_matrix);
          constraints.distribute_local_to_global(cell_viscosity,
                                                 dof_indices,
                                                 viscosity_matrix);
          constraints.distribute_local_to_global(cell_elasticity,
                                                 dof_indices,
                                                 elasticity_matrix);
          for (unsigned int d = 0; d < dim; ++d)
            momentum_density[d].add(dof_indices, cell_momentum[d]);
          angular_momentum_density.add(dof_indices, cell_angular_momentum);
        }
    for (VectorType &vector : momentum_density)
      vector.compress(VectorOperation::add);
    angular_momentum_density.compress(VectorOperation::add);
    for (MatrixType *matrix :
         {&mass_matrix, &viscosity_matrix, &elasticity_matrix})
      matrix->compress(VectorOperation::add);
    form_system_matrix();
  }


  // @sect4{ContactProblem::form_system_matrix}

  // K = (1/k) M + A_h + k B_h of (5.2), for the current k.
  template <int dim>
  void ContactProblem<dim>::form_system_matrix()
  {
    system_matrix.copy_from(mass_matrix);
    system_matrix *= 1. / time_step;
    system_matrix.add(1., viscosity_matrix);
    system_matrix.add(time_step, elasticity_matrix);
  }


  // @sect4{ContactProblem::visit_loads}

  // F_n = f(t_n) of (5.2): the body force f_0 in Omega and the tractions
  // f_2 on Gamma_2. With a manufactured solution they come from it (f_2 =
  // sigma n on every side that is neither clamped nor in contact), and its
  // tangential load f_3 on Gamma_3 acts with the nodal weights m_p of the
  // friction term. Every cell that carries a load is handed to `visit_cell`
  // with its (unassembled) cell vector, every node of Gamma_3 with a force
  // to `visit_node`: assemble_load() assembles them, load_power() tests
  // them with a velocity.
  template <int dim>
  void ContactProblem<dim>::visit_loads(const double       load_time,
                                        const bool         with_body_force,
                                        const bool         with_surface_loads,
                                        const CellVisitor &visit_cell,
                                        const NodeVisitor &visit_node) const
  {
    body_force->set_time(load_time);
    for (const auto &traction : tractions)
      traction.second->set_time(load_time);

    FEValues<dim>                    fe_values(*mapping,
                            fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                fe_face_values(*mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    const FEValuesExtractors::Vector displacements(0);
    const unsigned int               n_dofs = fe.n_dofs_per_cell();
    Vector<double>                   cell_rhs(n_dofs);
    Vector<double>                   value(dim);

    const auto add_force = [&](const FEValuesBase<dim> &values,
                               const auto              &force_at) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Tensor<1, dim> f = force_at(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
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
    const auto exact_body_force = [&](const unsigned int q) {
      return exact_solution->body_force(fe_values.quadrature_point(q),
                                        load_time);
    };
    const auto exact_traction = [&](const unsigned int q) {
      return exact_solution->stress(fe_face_values.quadrature_point(q),
                                    load_time) *
             fe_face_values.normal_vector(q);
    };
    const auto is_free_side = [&](const types::boundary_id id) {
      const auto &boundary = parameters.boundary;
      return std::count(boundary.clamped_ids.begin(),
                        boundary.clamped_ids.end(),
                        id) +
               std::count(boundary.contact_ids.begin(),
                          boundary.contact_ids.end(),
                          id) ==
             0;
    };

    // The surface loads alone (every step, when the body force is constant)
    // touch the boundary cells only.
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && (with_body_force || cell->at_boundary()))
        {
          cell_rhs    = 0;
          bool loaded = with_body_force;
          if (with_body_force)
            {
              fe_values.reinit(cell);
              if (exact_solution)
                add_force(fe_values, exact_body_force);
              else
                add_force(fe_values, parsed(fe_values, *body_force));
            }
          for (const unsigned int f : cell->face_indices())
            if (with_surface_loads && cell->face(f)->at_boundary())
              {
                const types::boundary_id id = cell->face(f)->boundary_id();
                if (exact_solution && is_free_side(id))
                  {
                    fe_face_values.reinit(cell, f);
                    add_force(fe_face_values, exact_traction);
                    loaded = true;
                  }
                else if (!exact_solution && tractions.count(id) != 0)
                  {
                    fe_face_values.reinit(cell, f);
                    add_force(fe_face_values,
                              parsed(fe_face_values, *tractions.at(id)));
                    loaded = true;
                  }
              }
          if (loaded)
            visit_cell(cell, cell_rhs);
        }

    if (exact_solution && with_surface_loads)
      for (const ContactNode<dim> &node : friction_solver->boundary().nodes)
        visit_node(node,
                   node.weight * exact_solution->contact_load(node.location,
                                                              node.normal,
                                                              load_time));
  }


  // @sect4{ContactProblem::assemble_load}

  // The load vector, condensed with the constraints like the matrices.
  template <int dim>
  void ContactProblem<dim>::assemble_load(const double load_time,
                                          VectorType  &load_vector,
                                          const bool   with_body_force,
                                          const bool   with_surface_loads) const
  {
    TimerOutput::Scope                   t(computing_timer, "Assembly");
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    load_vector = 0;
    visit_loads(
      load_time,
      with_body_force,
      with_surface_loads,
      [&](const auto &cell, const Vector<double> &cell_rhs) {
        cell->get_dof_indices(dof_indices);
        constraints.distribute_local_to_global(cell_rhs,
                                               dof_indices,
                                               load_vector);
      },
      [&](const ContactNode<dim> &node, const Tensor<1, dim> &force) {
        friction_solver->boundary().add_nodal_force(node, force, load_vector);
      });
    load_vector.compress(VectorOperation::add);
  }


  // @sect4{ContactProblem::assemble_constant_body_load}

  // A body force that does not depend on t is assembled once; its cell
  // vectors are kept for load_power().
  template <int dim>
  void ContactProblem<dim>::assemble_constant_body_load()
  {
    TimerOutput::Scope                   t(computing_timer, "Assembly");
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    constant_body_load.reinit(locally_owned_dofs, mpi_communicator);
    constant_body_cell_loads.clear();
    visit_loads(
      0.,
      true,
      false,
      [&](const auto &cell, const Vector<double> &cell_rhs) {
        constant_body_cell_loads.push_back(cell_rhs);
        cell->get_dof_indices(dof_indices);
        constraints.distribute_local_to_global(cell_rhs,
                                               dof_indices,
                                               constant_body_load);
      },
      [](const ContactNode<dim> &, const Tensor<1, dim> &) {});
    constant_body_load.compress(VectorOperation::add);
  }


  // @sect4{ContactProblem::load_power}

  // F(t) . w for fields w in V_h (ghosted), from the loads' expressions at
  // time t and the fields' values on each cell, without the assembled load
  // vector: int f_0 . w_h dx + int_Gamma2 f_2 . w_h ds (+ the nodal f_3 of
  // a manufactured solution), with the quadrature of the assembly. The
  // loads are evaluated once for all fields (the velocity's power and the
  // rotation's moment), and with each the sum of the magnitudes of the
  // products it adds up (of every cell's and node's entry), the scale of its
  // round-off. A body force constant in time is integrated once
  // (constant_body_cell_loads holds its cell vectors).
  template <int dim>
  std::vector<LoadPower> ContactProblem<dim>::load_power(
    const double                           load_time,
    const std::vector<const FastVector *> &fields) const
  {
    Vector<double> w_cell(fe.n_dofs_per_cell());
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
      {
        unsigned int index = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            add_cell(cell, constant_body_cell_loads[index++]);
      }
    Utilities::MPI::sum(sums, mpi_communicator, sums);
    std::vector<LoadPower> result(fields.size());
    for (unsigned int i = 0; i < fields.size(); ++i)
      result[i] = {sums[2 * i], sums[2 * i + 1]};
    return result;
  }


  // @sect4{ContactProblem::set_initial_values}

  // u_0 and w_0 = u_1 (of the .prm or of the manufactured solution)
  // interpolated at the nodes, then made to satisfy the constraints of V_h
  // (the clamp and w.n = 0 on Gamma_3).
  template <int dim>
  void ContactProblem<dim>::set_initial_values()
  {
    const Function<dim>           *u0 = initial_displacement.get();
    const Function<dim>           *u1 = initial_velocity.get();
    std::unique_ptr<Function<dim>> exact_u0, exact_u1;
    if (exact_solution)
      {
        exact_u0 = std::make_unique<typename ManufacturedSolution<dim>::Field>(
          *exact_solution, false);
        exact_u1 = std::make_unique<typename ManufacturedSolution<dim>::Field>(
          *exact_solution, true);
        u0 = exact_u0.get();
        u1 = exact_u1.get();
      }
    VectorTools::interpolate(*mapping, dof_handler, *u0, displacement);
    VectorTools::interpolate(*mapping, dof_handler, *u1, velocity);
    if (!exact_solution)
      {
        warn_of_normal_component(displacement, "Initial displacement");
        warn_of_normal_component(velocity, "Initial velocity");
      }
    constraints.distribute(displacement);
    constraints.distribute(velocity);
    // Before anything is written: a NaN here would be blamed on step 1.
    const auto check_finite = [](const VectorType  &values,
                                 const std::string &entry,
                                 const std::string &expression) {
      // (The maximum norm skips NaN; the sum of the entries does not.)
      AssertThrow(std::isfinite(values.linfty_norm()) &&
                    !std::isnan(values.l1_norm()),
                  ExcMessage("Entry 'Loads and initial values/" + entry +
                             "' = '" + expression +
                             "' is not a finite number at some node of the "
                             "mesh (a division by zero, or the root or "
                             "logarithm of a negative number there?); "
                             "allowed are expressions finite on the whole "
                             "body."));
    };
    check_finite(displacement,
                 "Initial displacement",
                 parameters.loads.initial_displacement);
    check_finite(velocity,
                 "Initial velocity",
                 parameters.loads.initial_velocity);
    old_displacement = displacement;
    old_velocity     = velocity;

    mass_times_velocity.reinit(velocity);
    elasticity_times_displacement.reinit(displacement);
    condensed_product(mass_matrix, velocity, mass_times_velocity);
    condensed_product(elasticity_matrix,
                      displacement,
                      elasticity_times_displacement);
    energy         = EnergyBalance();
    energy.kinetic = 0.5 * (mass_times_velocity * velocity);
    energy.elastic = 0.5 * (elasticity_times_displacement * displacement);
    energy.initial = energy.kinetic + energy.elastic;
  }


  // @sect4{ContactProblem::warn_of_normal_component}

  // The bilateral contact holds u.n = w.n = 0 on Gamma_3, and the
  // constraints of V_h set the normal component of the initial values
  // there to zero; where the .prm gives one that is not, the user is told
  // that it was removed.
  template <int dim>
  void
  ContactProblem<dim>::warn_of_normal_component(const VectorType  &values,
                                                const std::string &entry) const
  {
    double normal = 0, largest = values.linfty_norm();
    for (const ContactNode<dim> &node : friction_solver->boundary().nodes)
      if (node.locally_owned)
        {
          double component = 0;
          for (unsigned int d = 0; d < dim; ++d)
            component += node.normal[d] * values[node.dofs[d]];
          normal = std::max(normal, std::abs(component));
        }
    normal = Utilities::MPI::max(normal, mpi_communicator);
    if (normal > 1e-12 * largest)
      pcout << "Warning: 'Loads and initial values/" << entry
            << "' has a normal component on Gamma_3 (up to " << normal
            << "), which the bilateral contact (u.n = w.n = 0 there) "
            << "does not allow; it is set to zero." << std::endl;
  }


  // @sect4{ContactProblem::condensed_product}

  // M x for x in V_h, with M condensed: the rows of constrained dofs carry
  // only a diagonal entry that has nothing to do with the form, so they are
  // zeroed. (For the unconstrained rows, condensed M times x is P^T M x,
  // and y . P^T M x = y^T M x for y, x in V_h because x = P x_free.)
  template <int dim>
  void ContactProblem<dim>::condensed_product(const MatrixType &matrix,
                                              const VectorType &x,
                                              VectorType       &product) const
  {
    matrix.vmult(product, x);
    constraints.set_zero(product);
  }


  // @sect4{ContactProblem::momentum}

  // int rho w dx: not condensed, since the translations it is tested with
  // need not lie in V_h.
  template <int dim>
  Tensor<1, dim> ContactProblem<dim>::momentum() const
  {
    Tensor<1, dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = momentum_density[d] * velocity;
    return result;
  }


  // @sect4{ContactProblem::velocity_products}

  // M w_n, A w_n and B w_n: what the energy balance and the next step's
  // right-hand side need of the new velocity. (The program runs one thread
  // per process, main.cc, so the three products are taken one after the
  // other.)
  template <int dim>
  VelocityProducts ContactProblem<dim>::velocity_products() const
  {
    VelocityProducts products{velocity, velocity, velocity};
    condensed_product(mass_matrix, velocity, products.mass);
    condensed_product(viscosity_matrix, velocity, products.viscosity);
    condensed_product(elasticity_matrix, velocity, products.elasticity);
    return products;
  }


  // @sect4{ContactProblem::update_energy_balance}

  // The terms of the energy identity of backward Euler: (5.2) tested with
  // w_n, with (5.5) and 2 a.(a - b) = |a|^2 - |b|^2 + |a - b|^2 as in (5.7)
  // and (5.9), from the products of w_n and those of the last step,
  // M w_{n-1} and B u_{n-1}: B u_n = B u_{n-1} + k B w_n by (5.5), and
  // |w_n - w_{n-1}|_M^2 expanded in the known products.
  template <int dim>
  void
  ContactProblem<dim>::update_energy_balance(const VelocityProducts &products)
  {
    TimerOutput::Scope t(computing_timer, "Energy balance");
    const double       k     = time_step;
    const double       w_M_w = products.mass * velocity;
    energy.numerical_dissipation +=
      0.5 * (w_M_w - 2. * (mass_times_velocity * velocity) +
             mass_times_velocity * old_velocity) +
      0.5 * k * k * (products.elasticity * velocity);
    energy.kinetic = 0.5 * w_M_w;
    VectorType B_u(elasticity_times_displacement);
    B_u.add(k, products.elasticity);
    energy.elastic = 0.5 * (B_u * displacement);
    energy.viscous_dissipation += k * (products.viscosity * velocity);
    energy.external_work += k * (load * velocity);
    const ContactBoundary<dim> &gamma3 = friction_solver->boundary();
    if (!friction_law.is_frictionless())
      energy.friction_dissipation +=
        k * (friction_solver->state().friction_force *
             gamma3.tangential_velocities(velocity));
  }


#define INSTANTIATE(dim)                                                     \
  template void ContactProblem<dim>::assemble_matrices();                    \
  template void ContactProblem<dim>::form_system_matrix();                   \
  template void ContactProblem<dim>::assemble_load(const double,             \
                                                   VectorType &,             \
                                                   const bool,               \
                                                   const bool) const;        \
  template void ContactProblem<dim>::visit_loads(const double,               \
                                                 const bool,                 \
                                                 const bool,                 \
                                                 const CellVisitor &,        \
                                                 const NodeVisitor &) const; \
  template void ContactProblem<dim>::assemble_constant_body_load();          \
  template std::vector<LoadPower> ContactProblem<dim>::load_power(           \
    const double, const std::vector<const FastVector *> &) const;            \
  template void ContactProblem<dim>::set_initial_values();                   \
  template void ContactProblem<dim>::warn_of_normal_component(               \
    const VectorType &, const std::string &) const;                          \
  template void ContactProblem<dim>::condensed_product(const MatrixType &,   \
                                                       const VectorType &,   \
                                                       VectorType &) const;  \
  template void ContactProblem<dim>::update_energy_balance(                  \
    const VelocityProducts &);                                               \
  template VelocityProducts ContactProblem<dim>::velocity_products() const;  \
  template Tensor<1, dim>   ContactProblem<dim>::momentum() const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
