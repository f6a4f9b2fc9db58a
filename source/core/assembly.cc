/* Matrices and loads of the scheme (5.2)-(5.5), initial values, energies. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
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

    FEValues<dim>                        fe_values(*space.mapping,
                            space.fe,
                            space.quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim>                        mass_values(*space.mapping,
                              space.fe,
                              space.mass_quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    const unsigned int                   n_dofs = space.fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_mass(n_dofs, n_dofs);
    FullMatrix<double>                   cell_viscosity(n_dofs, n_dofs);
    FullMatrix<double>                   cell_elasticity(n_dofs, n_dofs);
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    std::vector<Tensor<1, dim>>          phi(n_dofs);
    std::vector<SymmetricTensor<2, dim>> eps(n_dofs);
    std::vector<double>                  div(n_dofs);
    std::vector<Vector<double>> cell_momentum(dim, Vector<double>(n_dofs));
    Vector<double>              cell_angular_momentum(n_dofs);

    for (const auto &cell : space.dof_handler.active_cell_iterators())
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
          space.constraints.distribute_local_to_global(cell_mass,
                                                       dof_indices,
                                                       matrices.mass);
          space.constraints.distribute_local_to_global(cell_viscosity,
                                                       dof_indices,
                                                       matrices.viscosity);
          space.constraints.distribute_local_to_global(cell_elasticity,
                                                       dof_indices,
                                                       matrices.elasticity);
          for (unsigned int d = 0; d < dim; ++d)
            matrices.momentum_density[d].add(dof_indices, cell_momentum[d]);
          matrices.angular_momentum_density.add(dof_indices,
                                                cell_angular_momentum);
        }
    for (VectorType &vector : matrices.momentum_density)
      vector.compress(VectorOperation::add);
    matrices.angular_momentum_density.compress(VectorOperation::add);
    for (MatrixType *matrix :
         {&matrices.mass, &matrices.viscosity, &matrices.elasticity})
      matrix->compress(VectorOperation::add);
    after_assembly(matrices);
    form_system_matrix();
  }


  // @sect4{ContactProblem::form_system_matrix}

  // K = (1/k) M + A_h + k B_h of (5.2), for the current k.
  template <int dim>
  void ContactProblem<dim>::form_system_matrix()
  {
    matrices.system.copy_from(matrices.mass);
    matrices.system *= 1. / time_step;
    matrices.system.add(1., matrices.viscosity);
    matrices.system.add(time_step, matrices.elasticity);
  }


  // @sect4{ContactProblem::set_initial_values}

  // u_0 and w_0 = u_1 (of the .prm or of the manufactured solution)
  // interpolated at the nodes, then made to satisfy the constraints of V_h
  // (the clamp and w.n = 0 on Gamma_3).
  template <int dim>
  void ContactProblem<dim>::set_initial_values()
  {
    VectorTools::interpolate(*space.mapping,
                             space.dof_handler,
                             loads->initial_displacement(),
                             state.displacement);
    VectorTools::interpolate(*space.mapping,
                             space.dof_handler,
                             loads->initial_velocity(),
                             state.velocity);
    if (!parameters.verification.manufactured())
      {
        warn_of_normal_component(state.displacement, "Initial displacement");
        warn_of_normal_component(state.velocity, "Initial velocity");
      }
    space.constraints.distribute(state.displacement);
    space.constraints.distribute(state.velocity);
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
    check_finite(state.displacement,
                 "Initial displacement",
                 parameters.loads.initial_displacement);
    check_finite(state.velocity,
                 "Initial velocity",
                 parameters.loads.initial_velocity);
    state.old_displacement = state.displacement;
    state.old_velocity     = state.velocity;

    state.energy = EnergyBalance();
    update_state_products();
    state.energy.initial = state.energy.kinetic + state.energy.elastic;
  }


  // @sect4{ContactProblem::update_state_products}

  // M w_n and B u_n, which the next step's right-hand side reads, and the
  // kinetic and elastic energy from them: of the initial values, and of the
  // fields carried to a new mesh.
  template <int dim>
  void ContactProblem<dim>::update_state_products()
  {
    state.mass_times_velocity.reinit(state.velocity);
    state.elasticity_times_displacement.reinit(state.displacement);
    condensed_product(matrices.mass, state.velocity, state.mass_times_velocity);
    condensed_product(matrices.elasticity,
                      state.displacement,
                      state.elasticity_times_displacement);
    state.energy.kinetic = 0.5 * (state.mass_times_velocity * state.velocity);
    state.energy.elastic =
      0.5 * (state.elasticity_times_displacement * state.displacement);
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
    space.constraints.set_zero(product);
  }


  // @sect4{ContactProblem::velocity_products}

  // M w_n, A w_n and B w_n: what the energy balance and the next step's
  // right-hand side need of the new velocity. (The program runs one thread
  // per process, main.cc, so the three products are taken one after the
  // other.)
  template <int dim>
  VelocityProducts ContactProblem<dim>::velocity_products() const
  {
    VelocityProducts products{state.velocity, state.velocity, state.velocity};
    condensed_product(matrices.mass, state.velocity, products.mass);
    condensed_product(matrices.viscosity, state.velocity, products.viscosity);
    condensed_product(matrices.elasticity, state.velocity, products.elasticity);
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
    const double       w_M_w = products.mass * state.velocity;
    // The step's own terms, kept apart from the sums over the steps (the
    // self-check of the step's identity reads them without the sums'
    // round-off).
    EnergyBalance &step = state.step_energy;
    step                = EnergyBalance();
    step.numerical_dissipation =
      0.5 * (w_M_w - 2. * (state.mass_times_velocity * state.velocity) +
             state.mass_times_velocity * state.old_velocity) +
      0.5 * k * k * (products.elasticity * state.velocity);
    step.kinetic = 0.5 * w_M_w;
    VectorType B_u(state.elasticity_times_displacement);
    B_u.add(k, products.elasticity);
    step.elastic             = 0.5 * (B_u * state.displacement);
    step.viscous_dissipation = k * (products.viscosity * state.velocity);
    step.external_work       = k * (state.load * state.velocity);
    const ContactBoundary<dim> &gamma3 = friction_solver->boundary();
    if (!friction_solver->law().is_frictionless())
      step.friction_dissipation =
        k * (friction_solver->state().friction_force *
             gamma3.tangential_velocities(state.velocity));
    state.energy.kinetic = step.kinetic;
    state.energy.elastic = step.elastic;
    state.energy.numerical_dissipation += step.numerical_dissipation;
    state.energy.viscous_dissipation += step.viscous_dissipation;
    state.energy.external_work += step.external_work;
    state.energy.friction_dissipation += step.friction_dissipation;
  }


#define INSTANTIATE(dim)                                                    \
  template void ContactProblem<dim>::assemble_matrices();                   \
  template void ContactProblem<dim>::form_system_matrix();                  \
  template void ContactProblem<dim>::set_initial_values();                  \
  template void ContactProblem<dim>::update_state_products();               \
  template void ContactProblem<dim>::warn_of_normal_component(              \
    const VectorType &, const std::string &) const;                         \
  template void ContactProblem<dim>::condensed_product(const MatrixType &,  \
                                                       const VectorType &,  \
                                                       VectorType &) const; \
  template VelocityProducts ContactProblem<dim>::velocity_products() const; \
  template void             ContactProblem<dim>::update_energy_balance(     \
    const VelocityProducts &);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
