/* One time step: the factorisation of K, the step's right-hand side, the
   friction solver, and the step cuts. */

#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>


namespace Contact
{
  // @sect4{ContactProblem::factorize_system_matrix}

  // K = (1/k) M + A_h + k B_h does not change while k is constant, so it is
  // factorised once per run and every later solve is a forward/back
  // substitution.
  template <int dim>
  void ContactProblem<dim>::factorize_system_matrix()
  {
    TimerOutput::Scope             t(computing_timer, "Factorization");
    std::vector<std::vector<bool>> constant_modes;
    if (parameters.solver.iterative_linear_solver)
      DoFTools::extract_constant_modes(space.dof_handler,
                                       ComponentMask(),
                                       constant_modes);
    factorization = Factorization::create(parameters.solver.linear_solver,
                                          matrices.system,
                                          constant_modes);
  }


  // @sect4{ContactProblem::change_time_step}

  // For a step cut: K = (1/k) M + A + k B for the new k, its factorisation
  // and everything built from it.
  template <int dim>
  void ContactProblem<dim>::change_time_step(const double k)
  {
    time_step = k;
    form_system_matrix();
    factorize_system_matrix();
    friction_solver->reinit(matrices.system, *factorization);
  }


  // @sect4{ContactProblem::advance}

  // The step from time - k to time. With 'Solver/Step cuts' > 0 a step
  // whose convexification or active set method fails is taken again as two
  // steps of k/2 (each of which may be cut again, up to the limit), from the
  // state before the failed attempt; then k is restored. Without cuts left
  // the failure ends the run with its diagnostic.
  template <int dim>
  StepStatistics ContactProblem<dim>::advance(const unsigned int cuts_left)
  {
    if (cuts_left == 0)
      return do_time_step();

    // Everything a step changes, kept to retake the step from it. The
    // postprocessors are not called for a step that fails, so they keep
    // nothing that would have to be restored.
    const StepState     saved_state          = state;
    const FrictionState saved_friction_state = friction_solver->state();
    try
      {
        return do_time_step();
      }
    catch (const ExcStepNotConverged &)
      {
        state = saved_state;
        friction_solver->set_state(saved_friction_state);
        pcout << "Step " << state.step_number << " (t = " << state.time
              << ") did not converge with k = " << time_step
              << "; cutting it into two steps of k/2 ('" + Entry::step_cuts +
                   "', "
              << cuts_left - 1 << " more allowed)." << std::endl;
      }

    const double k = time_step, end = state.time;
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


  // @sect4{ContactProblem::do_time_step}

  // One step of (5.2)-(5.5): the right-hand side from the last step,
  // step_rhs = F_n + (1/k) M w_{n-1} - B u_{n-1}, the velocity w_n and the
  // friction state from the friction solver, u_n = u_{n-1} + k w_n, and the
  // products of w_n the energy balance and the next step need.
  template <int dim>
  StepStatistics ContactProblem<dim>::do_time_step()
  {
    state.old_velocity     = state.velocity;
    state.old_displacement = state.displacement;
    loads->assemble(state.time, state.load);

    StepStatistics statistics;
    {
      TimerOutput::Scope t(computing_timer, "Time steps");
      VectorType        &step_rhs = state.step_rhs;
      step_rhs                    = state.load;
      step_rhs.add(1. / time_step, state.mass_times_velocity);
      step_rhs.add(-1., state.elasticity_times_displacement);
      space.constraints.set_zero(step_rhs);

      const unsigned long long cg_before = factorization->iterations();
      statistics =
        friction_solver->solve_step(step_rhs,
                                    state.velocity,
                                    {state.step_number, state.time, time_step});
      statistics.cg_iterations = factorization->iterations() - cg_before;
      substitution_time += friction_solver->substitution_seconds();
      state.displacement = state.old_displacement;
      state.displacement.add(time_step, state.velocity);
    }

    const VelocityProducts products = velocity_products();
    update_energy_balance(products);
    state.system_times_velocity = products.viscosity;
    state.system_times_velocity.add(1. / time_step,
                                    products.mass,
                                    time_step,
                                    products.elasticity);
    state.system_times_velocity_terms =
      products.mass.l2_norm() / time_step + products.viscosity.l2_norm() +
      time_step * products.elasticity.l2_norm();
    state.mass_times_velocity = products.mass;
    state.elasticity_times_displacement.add(time_step, products.elasticity);
    for (const auto &postprocessor : postprocessors)
      postprocessor->after_substep();
    return statistics;
  }


#define INSTANTIATE(dim)                                                       \
  template void           ContactProblem<dim>::factorize_system_matrix();      \
  template void           ContactProblem<dim>::change_time_step(const double); \
  template StepStatistics ContactProblem<dim>::advance(const unsigned int);    \
  template StepStatistics ContactProblem<dim>::do_time_step();

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
