/* One time step: the step's right-hand side, the friction solver, the
   energy balance, and the step cuts. */

#include <deal.II/base/exceptions.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>

#include <memory>
#include <utility>

namespace Contact
{
  namespace
  {
    // @sect4{update_energy_balance}

    // The terms of the energy identity of backward Euler: (5.2) tested
    // with w_n, with (5.5) and 2 a.(a - b) = |a|^2 - |b|^2 + |a - b|^2 as
    // in (5.7) and (5.9), from the products of w_n and those of the last
    // step, M w_{n-1} and B u_{n-1}: B u_n = B u_{n-1} + k B w_n by (5.5),
    // and |w_n - w_{n-1}|_M^2 expanded in the known products; on Gamma_3
    // k eta_n . v_n.
    template <int dim>
    void update_energy_balance(const VelocityProducts    &products,
                               const FrictionSolver<dim> &friction_solver,
                               StepState                 &state)
    {
      const double k     = state.time_step;
      const double w_M_w = products.mass * state.velocity;
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
      if (!friction_solver.law().is_frictionless())
        step.friction_dissipation =
          k *
          (friction_solver.state().friction_force *
           friction_solver.boundary().tangential_velocities(state.velocity));
      state.energy.kinetic = step.kinetic;
      state.energy.elastic = step.elastic;
      state.energy.numerical_dissipation += step.numerical_dissipation;
      state.energy.viscous_dissipation += step.viscous_dissipation;
      state.energy.external_work += step.external_work;
      state.energy.friction_dissipation += step.friction_dissipation;
    }


    // @sect4{update_step_products}

    // What the next step's right-hand side and the self-checks need of the
    // products of w_n: M w_n, B u_n = B u_{n-1} + k B w_n, and K w_n.
    void update_step_products(const VelocityProducts &products,
                              StepState              &state)
    {
      const double k              = state.time_step;
      state.system_times_velocity = products.viscosity;
      state.system_times_velocity.add(1. / k,
                                      products.mass,
                                      k,
                                      products.elasticity);
      state.system_times_velocity_terms = products.mass.l2_norm() / k +
                                          products.viscosity.l2_norm() +
                                          k * products.elasticity.l2_norm();
      state.mass_times_velocity = products.mass;
      state.elasticity_times_displacement.add(k, products.elasticity);
    }
  } // namespace


  // @sect4{ContactProblem::advance}

  // One step of (5.2)-(5.5) from t_n - k to t_n: the right-hand side from
  // the last step, step_rhs = F_n + (1/k) M w_{n-1} - B u_{n-1}, the
  // velocity w_n and the friction state from the friction solver,
  // u_n = u_{n-1} + k w_n, and the products of w_n the energy balance and
  // the next step need.
  //
  // With 'Solver/Step cuts' > 0 a step whose convexification or active set
  // method fails is taken again as two steps of k/2 (each of which may be
  // cut again, up to the limit), from the state before the failed attempt
  // (everything a step changes is kept for it; the postprocessors are not
  // called for a step that fails, so they keep nothing that would have to
  // be restored); then k is restored. Without cuts left the failure ends
  // the run with its diagnostic.
  template <int dim>
  StepStatistics ContactProblem<dim>::advance(const unsigned int cuts_left)
  {
    std::unique_ptr<const std::pair<StepState, FrictionState>> saved;
    if (cuts_left > 0)
      saved = std::make_unique<std::pair<StepState, FrictionState>>(
        state, friction_solver->state());
    try
      {
        state.old_velocity     = state.velocity;
        state.old_displacement = state.displacement;
        loads->assemble(state.time, state.load);
        const double   k = state.time_step;
        StepStatistics statistics;
        {
          TimerOutput::Scope t(computing_timer, "Time steps");
          VectorType        &step_rhs = state.step_rhs;
          step_rhs                    = state.load;
          step_rhs.add(1. / k, state.mass_times_velocity);
          step_rhs.add(-1., state.elasticity_times_displacement);
          space.constraints.set_zero(step_rhs);

          const Factorization     &factor    = *matrices.factorization;
          const unsigned long long cg_before = factor.iterations();
          statistics =
            friction_solver->solve_step(step_rhs,
                                        state.velocity,
                                        {state.step_number, state.time, k});
          statistics.cg_iterations = factor.iterations() - cg_before;
          run_record.substitution += friction_solver->substitution_seconds();
          state.displacement = state.old_displacement;
          state.displacement.add(k, state.velocity);
        }
        const VelocityProducts products =
          matrices.velocity_products(state.velocity, space.constraints);
        {
          TimerOutput::Scope t(computing_timer, "Energy balance");
          update_energy_balance(products, *friction_solver, state);
        }
        update_step_products(products, state);
        for (const auto &postprocessor : postprocessors)
          postprocessor->after_step(statistics, StepEnd::solve);
        return statistics;
      }
    catch (const ExcStepNotConverged &)
      {
        if (!saved)
          throw;
        state = saved->first;
        friction_solver->set_state(saved->second);
        pcout << "Step " << state.step_number << " (t = " << state.time
              << ") did not converge with k = " << state.time_step
              << "; cutting it into two steps of k/2 ('" + Entry::step_cuts +
                   "', "
              << cuts_left - 1 << " more allowed)." << std::endl;
      }

    // K = (1/k) M + A + k B for the new k, its factorisation and
    // everything built from it.
    const auto change_time_step = [this](const double new_k) {
      state.time_step = new_k;
      matrices.factorize(new_k, parameters.solver, space, computing_timer);
      friction_solver->reinit(matrices.system, *matrices.factorization);
    };
    const double k = state.time_step, end = state.time;
    change_time_step(k / 2);
    state.time            = end - k / 2;
    StepStatistics first  = advance(cuts_left - 1);
    state.time            = end;
    StepStatistics second = advance(cuts_left - 1);
    change_time_step(k);

    second.add_counts(first);
    ++second.step_cuts;
    return second;
  }


#define INSTANTIATE(dim) \
  template StepStatistics ContactProblem<dim>::advance(const unsigned int);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
