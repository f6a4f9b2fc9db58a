/* One time step: the factorisation of K, the step's right-hand side, the
   friction solver, and the step cuts. */

#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <core/contact_problem.h>

#include <tuple>

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
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(),
                                       constant_modes);
    factorization = Factorization::create(parameters.solver.linear_solver,
                                          system_matrix,
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
    friction_solver->reinit(system_matrix, *factorization);
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

    // Everything a step changes, kept to retake the step from it.
    const auto step_state = [this]() {
      return std::tie(velocity,
                      displacement,
                      mass_times_velocity,
                      elasticity_times_displacement,
                      energy,
                      energy_by_quadrature,
                      largest_checks);
    };
    const auto saved = std::apply(
      [](const auto &...values) { return std::make_tuple(values...); },
      step_state());
    const FrictionState saved_friction_state = friction_solver->state();
    try
      {
        return do_time_step();
      }
    catch (const ExcStepNotConverged &)
      {
        step_state() = saved;
        friction_solver->set_state(saved_friction_state);
        pcout << "Step " << step_number << " (t = " << time
              << ") did not converge with k = " << time_step
              << "; cutting it into two steps of k/2 ('" + Entry::step_cuts +
                   "', "
              << cuts_left - 1 << " more allowed)." << std::endl;
      }

    const double k = time_step, end = time;
    change_time_step(k / 2);
    time                  = end - k / 2;
    StepStatistics first  = advance(cuts_left - 1);
    time                  = end;
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
    old_velocity     = velocity;
    old_displacement = displacement;
    assemble_load(time, load, !body_force_is_constant, true);
    if (body_force_is_constant)
      load += constant_body_load;
    if (sabotage.load_factor != 1.)
      load *= sabotage.load_factor;

    StepStatistics statistics;
    {
      TimerOutput::Scope t(computing_timer, "Time steps");
      VectorType         step_rhs(load);
      step_rhs.add(1. / time_step, mass_times_velocity);
      step_rhs.add(-1., elasticity_times_displacement);
      constraints.set_zero(step_rhs);

      const unsigned long long cg_before = factorization->iterations();
      statistics =
        friction_solver->solve_step(step_rhs, velocity, step_label());
      statistics.cg_iterations = factorization->iterations() - cg_before;
      substitution_time += friction_solver->substitution_seconds();
      displacement = old_displacement;
      displacement.add(time_step, velocity);
    }

    const VelocityProducts products = velocity_products();
    update_energy_balance(products);
    mass_times_velocity = products.mass;
    elasticity_times_displacement.add(time_step, products.elasticity);
    check_step();
    return statistics;
  }


  template <int dim>
  StepLabel ContactProblem<dim>::step_label() const
  {
    return {step_number, time, time_step};
  }


#define INSTANTIATE(dim)                                                       \
  template void           ContactProblem<dim>::factorize_system_matrix();      \
  template void           ContactProblem<dim>::change_time_step(const double); \
  template StepStatistics ContactProblem<dim>::advance(const unsigned int);    \
  template StepStatistics ContactProblem<dim>::do_time_step();                 \
  template StepLabel      ContactProblem<dim>::step_label() const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
