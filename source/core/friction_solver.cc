/* The friction problem on Gamma_3 of every time step: the choice of the
   path, the convexity limit, and the method of 'Solver/Friction method'
   (friction_method.h) for the friction problem of the step. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>


#include <base/dimensions.h>
#include <core/friction_method.h>
#include <core/friction_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

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
    , chosen_method(
        FrictionMethodRegistry<dim>::create(Entry::friction_method,
                                            parameters.solver.friction_method))
    , convexification(std::make_unique<Convexification<dim>>())
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
  FrictionSolver<dim>::~FrictionSolver() = default;


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
        const bool rough = factorization.relative_residual() > 0;
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
  // other path, the active set as constraints where the build has it
  // (parts/constraints_path), is also the plain solve without friction.
  template <int dim>
  void FrictionSolver<dim>::choose_path(const MatrixType &system_matrix,
                                        Factorization    &factorization)
  {
    const std::string other =
      ContactPathRegistry<dim>::is_registered("constraints") ?
        "constraints" :
        delassus_path_name;
    std::string name = parameters.solver.contact_solver;
    if (friction_law.is_frictionless() || gamma3.nodes.empty())
      name = other;
    else if (name == "auto")
      name = delassus_operator_pays(factorization) ? delassus_path_name : other;
    path = make_path(system_matrix, factorization, name);
  }


  template <int dim>
  std::unique_ptr<ContactPath<dim>>
  FrictionSolver<dim>::make_path(const MatrixType  &system_matrix,
                                 Factorization     &factorization,
                                 const std::string &name)
  {
    return ContactPathRegistry<dim>::create(Entry::contact_solver,
                                            name,
                                            gamma3,
                                            system_matrix,
                                            factorization,
                                            computing_timer);
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
    return factorization.relative_residual() == 0 &&
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

  // The friction problem of a step on Gamma_3 by the method of 'Solver/
  // Friction method', with the convexification of the paper as the
  // fallback of the other methods. A rate independent law is one Tresca
  // problem, which the convexification solves in one iteration.
  template <int dim>
  void FrictionSolver<dim>::solve_friction_problem(const StepLabel &label,
                                                   const double velocity_scale,
                                                   StepStatistics &statistics)
  {
    FrictionStep<dim>    step{parameters,
                           friction_law,
                           gamma3,
                           law_weights,
                           active_set_parameter,
                           convexity_limit,
                           *path,
                           current,
                           label,
                           velocity_scale,
                           last_law_residual_allowance};
    FrictionMethod<dim> &method =
      friction_law.is_rate_independent() ? *convexification : *chosen_method;
    method.solve(step, *convexification, statistics);
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
