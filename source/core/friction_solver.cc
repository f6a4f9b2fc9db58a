/* The friction problem on Gamma_3 of every time step: the choice of the
   path, the convexity limit, Newton's method on the full law and the
   convexification of the paper around Tresca problems. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>


#include <base/dimensions.h>
#include <core/friction_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>

namespace Contact
{
  // @sect4{FrictionSolver::FrictionSolver}

  // No friction force yet and every node sticking (without friction
  // Gamma_3 only carries the normal constraint: every node slips freely).
  template <int dim>
  FrictionSolver<dim>::FrictionSolver(
    const FrictionSolverEnvironment                 &environment,
    std::vector<ContactNode<dim>>                    nodes,
    const std::function<double(const Point<dim> &)> &bound_scale)
    : parameters(environment.parameters)
    , friction_law(parameters.friction)
    , pcout(environment.pcout)
    , computing_timer(environment.computing_timer)
    , gamma3{std::move(nodes),
             environment.constraints,
             environment.locally_owned_dofs,
             environment.mpi_communicator}
  {
    current.friction_force.reinit(gamma3.n_unknowns());
    current.slip_velocity.reinit(gamma3.n_unknowns());
    current.node_state.assign(gamma3.nodes.size(),
                              friction_law.is_frictionless() ?
                                NodeState::slip :
                                NodeState::stick);
    law_weights.reinit(gamma3.nodes.size());
    for (unsigned int p = 0; p < gamma3.nodes.size(); ++p)
      law_weights[p] =
        gamma3.nodes[p].weight *
        (bound_scale ? bound_scale(gamma3.nodes[p].location) : 1.);
  }


  template <int dim>
  void FrictionSolver<dim>::set_initial_velocity(const VectorType &velocity)
  {
    current.slip_velocity = gamma3.tangential_velocities(velocity);
  }


  // @sect4{FrictionSolver::reinit}

  // What every step's friction problem needs, whichever path solves it:
  // the parameters c_p of the active set method (the 'Active set parameter'
  // times the node's stiffness t^T K t, averaged over its tangents), the
  // path, and the convexity limit of a step's problem.
  template <int dim>
  void FrictionSolver<dim>::reinit(const MatrixType &system_matrix,
                                   Factorization    &factorization)
  {
    const unsigned int n = gamma3.nodes.size(), m = dim - 1;
    active_set_parameter.reinit(n);
    for (unsigned int q = 0; q < n; ++q)
      if (gamma3.nodes[q].locally_owned)
        for (const Tensor<1, dim> &tangent : gamma3.nodes[q].tangents)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              if (!gamma3.constraints.is_constrained(gamma3.nodes[q].dofs[a]) &&
                  !gamma3.constraints.is_constrained(gamma3.nodes[q].dofs[b]))
                active_set_parameter[q] +=
                  parameters.solver.active_set_parameter / m * tangent[a] *
                  system_matrix.el(gamma3.nodes[q].dofs[a],
                                   gamma3.nodes[q].dofs[b]) *
                  tangent[b];
    active_set_parameter = gamma3.sum_over_processes(active_set_parameter);
    choose_path(system_matrix, factorization);

    // The Lanczos method applies D: dense products on the Delassus path,
    // solves with K otherwise. With CG-AMG it stops when the estimate
    // changes by less than lanczos_tolerance_iterative, which is all the
    // Newton method's cap needs; its Ritz values are below lambda_max, so
    // the printed limit is then an upper bound (1.03e3 on the coarse 3D test
    // scene, as with lanczos_tolerance).
    if (!friction_law.is_rate_independent() &&
        !friction_law.is_frictionless() && !gamma3.nodes.empty())
      {
        const bool rough = parameters.solver.iterative_linear_solver;
        const auto [eigenvalue, converged] =
          largest_weighted_delassus_eigenvalue(
            rough ? lanczos_tolerance_iterative : lanczos_tolerance);
        convexity_limit = 1. / eigenvalue;
        pcout << "Gamma_3: the friction problem of a step is convex while "
              << "S (a - b) alpha < " << std::setprecision(3) << convexity_limit
              << (!converged ? " (or less: the Lanczos method did not converge "
                               "in its steps)" :
                  rough      ? " (or a little less: estimated to " +
                            number_text(lanczos_tolerance_iterative) + ")" :
                          "")
              << "; here S (a - b) alpha = "
              << friction_law.steepest_weakening() << std::setprecision(6)
              << std::endl;
      }
  }


  // @sect4{FrictionSolver::choose_path}

  // The Delassus paths only pay with friction on a nonempty Gamma_3; the
  // constraints path is also the plain solve without friction.
  template <int dim>
  void FrictionSolver<dim>::choose_path(const MatrixType &system_matrix,
                                        Factorization    &factorization)
  {
    using ContactSolver          = SolverParameters::ContactSolver;
    const ContactSolver choice   = parameters.solver.contact_solver;
    const bool          delassus = !friction_law.is_frictionless() &&
                          !gamma3.nodes.empty() &&
                          (choice == ContactSolver::delassus ||
                           (choice == ContactSolver::automatic &&
                            delassus_operator_pays(factorization)));
    path = make_path(system_matrix, factorization, delassus);
  }


  template <int dim>
  std::unique_ptr<ContactPath<dim>>
  FrictionSolver<dim>::make_path(const MatrixType &system_matrix,
                                 Factorization    &factorization,
                                 const bool        delassus)
  {
    return make_contact_path(
      gamma3, system_matrix, factorization, delassus, computing_timer);
  }


  // @sect4{FrictionSolver::largest_weighted_delassus_eigenvalue}

  // On Gamma_3 a step minimises
  //   E(v) = 1/2 (v - v_free)^T D^{-1} (v - v_free) + sum_p m_p j(v_p),
  // and j(v) = S int_0^|v| mu is concave along |v| with curvature down to
  // -S (a - b) alpha. E is strictly convex, and the step's solution unique,
  // while D^{-1} - S (a - b) alpha M is positive definite, i.e.
  //   S (a - b) alpha < 1 / lambda_max(M^{1/2} D M^{1/2})  (strictly),
  // M = diag(m_p): the discrete, per-step counterpart of the paper's
  // condition (3.22), m_A > S lambda C_0^2, in which (rho/k) M + A + k B
  // takes the place of the viscosity and the trace constant is that of V_h.
  // lambda_max by the Lanczos method (M^{1/2} D M^{1/2} is symmetric
  // positive semidefinite), D applied as D or as C K^{-1} C^T, until the
  // estimate changes by less than `tolerance` relative (at most
  // max_lanczos_steps; false if these did not suffice). The Ritz values
  // approach lambda_max from below: an unconverged estimate overstates the
  // limit. (The power method, used before, stopped short of 1e-8 after its
  // 200 iterations on several test scenes.)
  template <int dim>
  std::pair<double, bool>
  FrictionSolver<dim>::largest_weighted_delassus_eigenvalue(
    const double tolerance)
  {
    const unsigned int n = gamma3.nodes.size(), m = dim - 1;
    Vector<double>     x(n * m), y(n * m), root_weight(n * m);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int i = 0; i < m; ++i)
        root_weight[p * m + i] = std::sqrt(gamma3.nodes[p].weight);
    const auto apply = [&](const Vector<double> &in, Vector<double> &out) {
      Vector<double> scaled(in);
      scaled.scale(root_weight);
      path->apply_delassus(scaled, out);
      out.scale(root_weight);
    };

    // Lanczos with full reorthogonalisation: the largest Ritz value of the
    // tridiagonal matrix T_j, recomputed at every step, until it changes by
    // less than `tolerance` relative or the Krylov space is invariant.
    std::vector<Vector<double>> basis;
    std::vector<double>         diagonal, off_diagonal;
    // A start vector without the symmetries of Gamma_3, which could make it
    // orthogonal to the top eigenvector (the same on every process).
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = 1. + 0.5 * std::sin(1.7 * i + 0.3);
    x /= x.l2_norm();
    double estimate = 0;
    for (unsigned int j = 0; j < max_lanczos_steps; ++j)
      {
        basis.push_back(x);
        apply(x, y);
        diagonal.push_back(x * y);
        for (const Vector<double> &q : basis)
          y.add(-(q * y), q);
        for (const Vector<double> &q : basis)
          y.add(-(q * y), q);
        const double next = y.l2_norm();

        LAPACKFullMatrix<double> tridiagonal(j + 1, j + 1);
        for (unsigned int i = 0; i <= j; ++i)
          {
            tridiagonal(i, i) = diagonal[i];
            if (i < j)
              tridiagonal(i, i + 1) = tridiagonal(i + 1, i) = off_diagonal[i];
          }
        tridiagonal.compute_eigenvalues();
        double ritz_value = 0;
        for (unsigned int i = 0; i <= j; ++i)
          ritz_value = std::max(ritz_value, tridiagonal.eigenvalue(i).real());
        const bool invariant = next <= 1e-12 * ritz_value || j + 1 == x.size();
        if (invariant ||
            std::abs(ritz_value - estimate) <= tolerance * ritz_value)
          return {ritz_value, true};
        estimate = ritz_value;
        off_diagonal.push_back(next);
        x = y;
        x /= next;
      }
    return {estimate, false};
  }


  // @sect4{FrictionSolver::delassus_operator_pays}

  // 'auto' takes the Delassus path while D and W = D^{-1} fit in 1 GB
  // (7900 tangential unknowns of Gamma_3; about twice that while D is
  // built, on every process; set by memory): its Newton steps factorise a
  // dense block of D, O(n^3), but each of the constraints path's refactorises
  // K, and bench/auto_path.md measures the Delassus path ahead on the 3D
  // scene at 2400 and 4224 unknowns of Gamma_3. Without CHOLMOD's triangular
  // factor it also needs Z = K^{-1} C^T, one solve per column and dense:
  // taken with a direct solver while Z fits in 1 GB per process; with
  // CG-AMG its columns would cost as many iterative solves as the
  // constraints path does in a run. Larger contact zones take the
  // constraints.
  template <int dim>
  bool FrictionSolver<dim>::delassus_operator_pays(
    const Factorization &factorization) const
  {
    const double n_columns = gamma3.n_unknowns();
    if (n_columns > SolverParameters::max_delassus_unknowns)
      return false;
    if (factorization.has_triangular_factor())
      return true;
    const double largest_part =
      Utilities::MPI::max(static_cast<double>(
                            gamma3.locally_owned_dofs.n_elements()),
                          gamma3.mpi_communicator);
    return !parameters.solver.iterative_linear_solver &&
           largest_part * n_columns * sizeof(double) <=
             SolverParameters::max_delassus_bytes;
  }


  // @sect4{FrictionSolver::solve_step}

  // One step of (5.2)-(5.5) on the path: the friction forces from the
  // problem on Gamma_3, then w_n. On the path from the factor of K the
  // friction problem sits between the forward and the backward substitution
  // of one solve. `velocity` is w_{n-1} on entry.
  template <int dim>
  StepStatistics FrictionSolver<dim>::solve_step(const VectorType &step_rhs,
                                                 VectorType       &velocity,
                                                 const StepLabel  &label)
  {
    StepStatistics statistics;
    last_law_residual_allowance = 0;
    path->begin_step(step_rhs, velocity);
    if (!friction_law.is_frictionless() && !gamma3.nodes.empty())
      solve_friction_problem(label, velocity.linfty_norm(), statistics);
    path->velocity(current.friction_force, velocity);
    if (friction_law.is_frictionless())
      current.slip_velocity = gamma3.tangential_velocities(velocity);
    add_contact_state(statistics);
    statistics.solves_with_K = path->solves;
    return statistics;
  }


  // @sect4{FrictionSolver::solve_friction_problem}

  // The friction problem of a step on Gamma_3: Newton's method on the full
  // law (friction.h) with 'Solver/Friction method = Newton', with the
  // convexification of the paper as the fallback where Newton does not
  // converge; the convexification alone otherwise. A rate independent law
  // is one Tresca problem either way.
  template <int dim>
  void FrictionSolver<dim>::solve_friction_problem(const StepLabel &label,
                                                   const double velocity_scale,
                                                   StepStatistics &statistics)
  {
    const bool newton = parameters.solver.friction_method ==
                          SolverParameters::FrictionMethod::newton &&
                        !friction_law.is_rate_independent();
    if (!newton)
      {
        solve_by_convexification(label, statistics);
        return;
      }
    const std::string newton_failure =
      solve_by_newton(velocity_scale, statistics);
    if (newton_failure.empty())
      return;
    try
      {
        solve_by_convexification(label, statistics);
      }
    catch (const ExcStepNotConverged &failure)
      {
        // The user chose (or kept) Newton: say that it failed first, and
        // why, before what stopped its fallback.
        std::ostringstream fallback;
        failure.print_info(fallback);
        std::string reason = fallback.str();
        reason.erase(0, reason.find_first_not_of(" \n"));
        reason.erase(reason.find_last_not_of(" \n") + 1);
        AssertThrow(false,
                    ExcStepNotConverged(
                      "Newton's method ('" + Entry::friction_method +
                      "' = Newton) did not solve step " +
                      std::to_string(label.step_number) + ": " +
                      newton_failure +
                      ". The convexification that took over did not "
                      "solve it either. " +
                      reason));
      }
  }


  // @sect4{FrictionSolver::solve_by_newton}

  // Newton's method on the full law from the previous step's forces, slip
  // velocities and sets. It returns why it failed (empty where it did not),
  // with the state of the step untouched, if it does not converge or ends
  // on a point that its curvature test does not certify as a local minimum
  // of E (friction.h).
  // Far from the solution its model caps the weakening at 0.9 times the
  // convexity limit, where the model is still convex.
  template <int dim>
  std::string FrictionSolver<dim>::solve_by_newton(const double velocity_scale,
                                                   StepStatistics &statistics)
  {
    Vector<double> eta(current.friction_force), v(current.slip_velocity);
    std::vector<NodeState> state;
    const auto             newton_step = path_operators().second;
    NodalLaw               law{friction_law,
                 law_weights,
                 weakening_cap_fraction * convexity_limit};
    law.convexity_limit               = convexity_limit;
    law.energy_accuracy               = path->energy_accuracy();
    law.velocity_scale                = velocity_scale;
    const FrictionNewtonResult result = solve_friction_newton(
      newton_step,
      [this](const std::vector<NodeLinearisation> &linearisation) {
        return path->curvature_on_slip_set(linearisation);
      },
      dim - 1,
      law,
      active_set_parameter,
      parameters.solver.max_newton_iterations,
      parameters.solver.max_active_set_iterations,
      eta,
      v,
      state);
    statistics.convexification_iterations += result.convexification_steps;
    statistics.active_set_iterations += result.active_set_iterations;
    statistics.newton_iterations += result.iterations;
    statistics.beyond_convexity_limit += result.beyond_convexity_limit;
    statistics.saddle_exits += result.saddle_exits;
    if (!all_processes(result.converged))
      {
        ++statistics.newton_fallbacks;
        statistics.minima_not_certified += result.minimum_not_certified;
        // The same reason on every process.
        if (!all_processes(!result.minimum_not_certified))
          return "its end point was not certified a local minimum of the "
                 "step's energy";
        if (!all_processes(!result.tresca_failed))
          return "a Tresca problem inside it did not converge within '" +
                 Entry::max_active_set_iterations + "' = " +
                 std::to_string(parameters.solver.max_active_set_iterations) +
                 " iterations";
        return "it did not converge within '" + Entry::max_newton_iterations +
               "' = " +
               std::to_string(parameters.solver.max_newton_iterations) +
               " iterations";
      }
    current.friction_force = eta;
    current.slip_velocity  = v;
    current.node_state     = state;
    return "";
  }


  namespace
  {
    // The slip rates |v_p| of an iterate (`new_rate`), and the largest
    // change from `rate` relative to the largest slip or free slip rate,
    // which it returns too.
    template <int dim>
    std::pair<double, double>
    slip_rate_change(const std::vector<ContactNode<dim>> &nodes,
                     const Vector<double>                &rate,
                     const Vector<double>                &v,
                     const Vector<double>                &free_slip_velocity,
                     Vector<double>                      &new_rate)
    {
      double scale = std::numeric_limits<double>::min(), residual = 0;
      for (unsigned int p = 0; p < nodes.size(); ++p)
        {
          const ContactNode<dim> &node = nodes[p];
          new_rate[p]                  = node.tangential_vector(v, p).norm();
          residual = std::max(residual, std::abs(new_rate[p] - rate[p]));
          scale =
            std::max({scale,
                      new_rate[p],
                      node.tangential_vector(free_slip_velocity, p).norm()});
        }
      return {residual / scale, scale};
    }
  } // namespace


  // @sect4{FrictionSolver::solve_by_convexification}

  // The convexification of the paper's section 6 (refs [3, 4] there):
  // freeze the coefficient at slip rates s, g_p = m_p S mu(s_p), solve the
  // convex Tresca problem with these bounds, and repeat with s = |v| until
  // the slip rates and the slip set stop changing. The first s is the
  // previous step's slip rate: when (3.22) fails the discrete problem may
  // have several solutions, and starting from the past selects the one that
  // continues the motion.
  //
  // Why it converges, and what to watch: on Gamma_3 the step minimises
  //   E(v) = 1/2 (v - v_free)^T D^{-1} (v - v_free) + sum_p m_p j(v_p),
  // j of (3.8), and j(v) = S int_0^|v| mu is concave in |v| because mu
  // decreases. So the Tresca energy with g_p = m_p S mu(s_p) majorises E and
  // touches it where |v| = s: the plain iteration decreases E at every step
  // (a majorisation-minimisation, or DC, algorithm) and cannot cycle, but
  // it may crawl where (3.22) fails. Anderson acceleration of the map
  // s -> |v(s)| ('Solver/Anderson depth') speeds it up; an accelerated
  // iterate that does not decrease E is rejected and the plain step taken
  // instead, so the safeguard keeps the descent.
  template <int dim>
  void FrictionSolver<dim>::solve_by_convexification(const StepLabel &label,
                                                     StepStatistics &statistics)
  {
    const auto           &solver             = parameters.solver;
    const unsigned int    n                  = gamma3.nodes.size();
    const Vector<double> &free_slip_velocity = path->free_slip_velocity();

    Vector<double> rate(n), bound(n), eta(current.friction_force),
      v(free_slip_velocity.size());
    const auto slip_rates = [&](const Vector<double> &velocities) {
      for (unsigned int p = 0; p < n; ++p)
        rate[p] = gamma3.nodes[p].tangential_vector(velocities, p).norm();
    };
    slip_rates(current.slip_velocity);
    // The stick/slip states of the iterate and of the last accepted one.
    std::vector<NodeState> state, previous_state;
    AndersonAcceleration   anderson(solver.anderson_depth);
    double                 accepted_energy = std::numeric_limits<double>::max();
    double                 residual        = 0;
    double                 rate_scale      = 0;
    bool                   converged       = false;
    // Its own count: where it takes over from Newton, the Tresca steps
    // Newton took do not use up its 'Max convexification iterations'.
    unsigned int iterations = 0;

    while (!converged && iterations < solver.max_convexification_iterations)
      {
        ++iterations;
        ++statistics.convexification_iterations;
        for (unsigned int p = 0; p < n; ++p)
          bound[p] = friction_law.is_frictionless() ?
                       0. :
                       law_weights[p] * friction_law.bound(rate[p]);

        const TrescaResult tresca = solve_tresca_problem(bound, eta, v, state);
        statistics.active_set_iterations += tresca.iterations;
        statistics.cycles_cured += tresca.cycles_cured;
        AssertThrow(all_processes(tresca.converged),
                    ExcStepNotConverged(
                      tresca_failure(label, iterations, tresca.cycles_cured)));

        const double energy_now = energy_on_gamma3(free_slip_velocity, eta, v);
        if (!all_processes(
              !(anderson.last_step_was_accelerated() &&
                energy_now > accepted_energy +
                               energy_round_off * std::abs(accepted_energy))))
          {
            // Safeguard: back to the plain step from the accepted iterate.
            ++statistics.rejected_accelerations;
            anderson.restart();
            slip_rates(current.slip_velocity);
            eta = current.friction_force;
            continue;
          }
        accepted_energy        = energy_now;
        current.friction_force = eta;
        current.slip_velocity  = v;
        current.node_state     = state;

        Vector<double> new_rate(n);
        std::tie(residual, rate_scale) =
          slip_rate_change(gamma3.nodes, rate, v, free_slip_velocity, new_rate);
        converged =
          all_processes(friction_law.is_rate_independent() ||
                        (residual <= solver.convexification_tolerance &&
                         state == previous_state));
        previous_state = state;
        anderson.next_iterate(rate, new_rate);
        for (double &r : rate)
          r = std::max(r, 0.);
      }

    AssertThrow(converged,
                ExcStepNotConverged(convexification_failure(residual, label)));
    if (!friction_law.is_rate_independent())
      last_law_residual_allowance =
        friction_law.one_sided_lipschitz_constant() /
        friction_law.coefficient(0.) * residual * rate_scale;
  }


  // @sect4{FrictionSolver::energy_on_gamma3}

  // E(v) with v = v_free - D eta: the quadratic term is
  // eta^T D eta / 2 = eta . (v_free - v) / 2.
  template <int dim>
  double FrictionSolver<dim>::energy_on_gamma3(
    const Vector<double> &free_slip_velocity,
    const Vector<double> &eta,
    const Vector<double> &v) const
  {
    Vector<double> velocity_change(free_slip_velocity);
    velocity_change -= v;
    double value = 0.5 * (eta * velocity_change);
    for (unsigned int p = 0; p < gamma3.nodes.size(); ++p)
      value +=
        gamma3.nodes[p].weight *
        friction_law.potential(gamma3.nodes[p].tangential_vector(v, p).norm());
    return value;
  }


  // @sect4{FrictionSolver::tresca_failure}

  // What a user needs when the active set method of a Tresca problem
  // does not converge: where, and what makes the sets cycle.
  template <int dim>
  std::string
  FrictionSolver<dim>::tresca_failure(const StepLabel   &label,
                                      const unsigned int iteration,
                                      const unsigned int cycles_cured) const
  {
    const auto &solver = parameters.solver;
    return "The active set method for the Tresca problem did not converge "
           "in step " +
           std::to_string(label.step_number) +
           " (t = " + number_text(label.time) + ", convexification iteration " +
           std::to_string(iteration) + ") within " +
           std::to_string(solver.max_active_set_iterations) + " iterations ('" +
           Entry::max_active_set_iterations +
           "'); its parameter c was halved " + std::to_string(cycles_cured) +
           " times against cycling. The sets cycle when D = C K^{-1} C^T "
           "is ill-conditioned, e.g. for a nearly incompressible material "
           "('" +
           Entry::poisson_ratio +
           "' = " + std::to_string(parameters.material.poisson_ratio) +
           "). More iterations help (each halving damps the cycling), as "
           "may a different '" +
           Entry::active_set_parameter + "' (here " +
           std::to_string(solver.active_set_parameter) + ").";
  }


  // @sect4{FrictionSolver::path_operators}

  // What the Tresca and the Newton method need of the body:
  // v = v_free - D eta for given forces, and one Newton step.
  template <int dim>
  std::pair<TrescaVelocity, TrescaNewtonStep>
  FrictionSolver<dim>::path_operators()
  {
    return {[this](const Vector<double> &eta, Vector<double> &v) {
              path->velocity_of_force(eta, v);
            },
            [this](const std::vector<NodeLinearisation> &linearisation,
                   Vector<double>                       &eta,
                   Vector<double>                       &v) {
              path->newton_step(linearisation, eta, v);
            }};
  }


  // @sect4{FrictionSolver::solve_tresca_problem}

  // The Tresca problem of one convexification iteration.
  template <int dim>
  TrescaResult
  FrictionSolver<dim>::solve_tresca_problem(const Vector<double>   &bound,
                                            Vector<double>         &eta,
                                            Vector<double>         &v,
                                            std::vector<NodeState> &state)
  {
    const auto [velocity_of_force, newton_step] = path_operators();
    return solve_tresca(velocity_of_force,
                        newton_step,
                        dim - 1,
                        bound,
                        active_set_parameter,
                        parameters.solver.max_active_set_iterations,
                        eta,
                        v,
                        state);
  }


  // @sect4{FrictionSolver::all_processes}

  // Every process solves the same problem on Gamma_3 from the same summed
  // data, so its decisions agree; they are reduced anyway, so that no
  // process can leave a loop that another one stays in.
  template <int dim>
  bool FrictionSolver<dim>::all_processes(const bool condition) const
  {
    return Utilities::MPI::min(condition ? 1 : 0, gamma3.mpi_communicator) == 1;
  }


  // @sect4{FrictionSolver::convexification_failure}

  // What a user needs when the convexification stops without converging:
  // where, how far from converged, and which data drive it.
  template <int dim>
  std::string
  FrictionSolver<dim>::convexification_failure(const double     residual,
                                               const StepLabel &label) const
  {
    const auto        &solver   = parameters.solver;
    const auto        &friction = parameters.friction;
    std::ostringstream message;
    message
      << "The convexification did not converge in step " << label.step_number
      << " (t = " << label.time << ") within "
      << solver.max_convexification_iterations
      << " iterations ('" + Entry::max_convexification_iterations + "'): the "
      << "slip rates still change by " << residual
      << " relative to the velocity (tolerance "
      << solver.convexification_tolerance
      << ", '" + Entry::convexification_tolerance + "'); the last iterate has "
      << std::count(current.node_state.begin(),
                    current.node_state.end(),
                    NodeState::stick)
      << " stick and "
      << std::count(current.node_state.begin(),
                    current.node_state.end(),
                    NodeState::slip)
      << " slip nodes on Gamma_3. It contracts fast when "
      << "S (a - b) alpha is small against the stiffness of K on "
      << "Gamma_3; here S = " << friction.bound_S
      << ", (a - b) alpha = " << friction_law.one_sided_lipschitz_constant()
      << ", k = " << label.time_step
      << " (a step's problem is convex while S (a - b) alpha < "
      << convexity_limit << ")"
      << ". More iterations or a larger '" + Entry::anderson_depth + "' help "
      << "most (doc/stability.md); a smaller '" + Entry::time_step + "' (or "
      << "'" + Entry::step_cuts + "') and a smaller '" +
           Entry::friction_bound_S + "' "
      << "make the step's problem more convex.";
    return message.str();
  }


  // @sect4{FrictionSolver::add_contact_state}

  template <int dim>
  void FrictionSolver<dim>::add_contact_state(StepStatistics &statistics) const
  {
    Tensor<1, dim> resultant;
    for (unsigned int p = 0; p < gamma3.nodes.size(); ++p)
      {
        if (current.node_state[p] == NodeState::stick)
          ++statistics.n_stick;
        else
          ++statistics.n_slip;
        statistics.max_slip_rate = std::max(
          statistics.max_slip_rate,
          gamma3.nodes[p].tangential_vector(current.slip_velocity, p).norm());
        resultant +=
          gamma3.nodes[p].tangential_vector(current.friction_force, p);
      }
    statistics.friction_force = resultant.norm();
  }


  template <int dim>
  double FrictionSolver<dim>::law_residual_allowance() const
  {
    return last_law_residual_allowance;
  }

  template <int dim>
  const ContactBoundary<dim> &FrictionSolver<dim>::boundary() const
  {
    return gamma3;
  }

  template <int dim>
  const FrictionLaw &FrictionSolver<dim>::law() const
  {
    return friction_law;
  }

  template <int dim>
  const FrictionState &FrictionSolver<dim>::state() const
  {
    return current;
  }

  template <int dim>
  void FrictionSolver<dim>::set_state(const FrictionState &state)
  {
    current = state;
  }

  template <int dim>
  std::string FrictionSolver<dim>::description() const
  {
    return path->description();
  }

  template <int dim>
  double FrictionSolver<dim>::substitution_seconds() const
  {
    return path->substitution_seconds;
  }

  template <int dim>
  double FrictionSolver<dim>::free_slip_speed() const
  {
    return path->free_slip_speed();
  }


#define INSTANTIATE(dim) template class FrictionSolver<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
