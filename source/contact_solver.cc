/* One time step: the factorised K, the Delassus operator on Gamma_3 and the
   convexification loop around the nodal Tresca problem. */

#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_problem.h>

#include <algorithm>
#include <iomanip>
#include <cmath>
#include <limits>
#include <sstream>
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
    if (parameters.solver.linear_solver == "CG-AMG")
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(),
                                       constant_modes);
    factorization = Factorization::create(parameters.solver.linear_solver,
                                          system_matrix,
                                          constant_modes);
  }


  // @sect4{ContactProblem::tangential_velocity}

  template <int dim>
  double ContactProblem<dim>::tangential_velocity(const ContactNode<dim> &node,
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
  ContactProblem<dim>::tangential_velocities(const VectorType &w) const
  {
    Vector<double> v(contact_nodes.size() * (dim - 1));
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      if (contact_nodes[p].locally_owned)
        for (unsigned int i = 0; i < dim - 1; ++i)
          v[p * (dim - 1) + i] = tangential_velocity(contact_nodes[p], i, w);
    return sum_over_processes(v);
  }


  // The sum of every process's part of a vector on Gamma_3; all processes
  // get the sum.
  template <int dim>
  Vector<double>
  ContactProblem<dim>::sum_over_processes(const Vector<double> &part) const
  {
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      return part;
    Vector<double> sum(part.size());
    Utilities::MPI::sum(make_array_view(part),
                        mpi_communicator,
                        make_array_view(sum));
    return sum;
  }


  // @sect4{ContactProblem::friction_load}

  // C^T eta: the nodal friction forces eta_p = sum_i eta_{p,i} t_i as a
  // load on the body, condensed with the constraints like every load.
  template <int dim>
  VectorType ContactProblem<dim>::friction_load(const Vector<double> &eta) const
  {
    VectorType load(locally_owned_dofs, mpi_communicator);
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      add_nodal_force(contact_nodes[p],
                      contact_nodes[p].tangential_vector(eta, p),
                      load);
    load.compress(VectorOperation::add);
    return load;
  }


  // A force at a node of Gamma_3 added to a load vector (condensed), by the
  // process that owns the node; compress(add) follows.
  template <int dim>
  void ContactProblem<dim>::add_nodal_force(const ContactNode<dim> &node,
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


  // @sect4{ContactProblem::setup_contact_solver}

  // What every step's friction problem needs, whichever path solves it:
  // the parameters c_p of the active set method (the 'Active set parameter'
  // times the node's stiffness t^T K t, averaged over its tangents), and on
  // the Delassus path D with Y or Z.
  template <int dim>
  void ContactProblem<dim>::setup_contact_solver()
  {
    const unsigned int n = contact_nodes.size(), m = dim - 1;
    use_delassus_operator = false;
    if (friction_law.is_frictionless() || contact_nodes.empty())
      return;

    active_set_parameter.reinit(n);
    for (unsigned int q = 0; q < n; ++q)
      if (contact_nodes[q].locally_owned)
        for (const Tensor<1, dim> &tangent : contact_nodes[q].tangents)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              if (!constraints.is_constrained(contact_nodes[q].dofs[a]) &&
                  !constraints.is_constrained(contact_nodes[q].dofs[b]))
                active_set_parameter[q] +=
                  parameters.solver.active_set_parameter / m * tangent[a] *
                  system_matrix.el(contact_nodes[q].dofs[a],
                                   contact_nodes[q].dofs[b]) *
                  tangent[b];
    active_set_parameter = sum_over_processes(active_set_parameter);

    const std::string &choice = parameters.solver.contact_solver;
    use_delassus_operator =
      (choice == "Delassus" || (choice == "auto" && delassus_operator_pays()));
    if (use_delassus_operator)
      build_delassus_operator();

    // The power method applies D: dense products on the Delassus path,
    // solves with K otherwise. With CG-AMG it stops when the estimate
    // changes by less than 1e-3, which is all the Newton method's cap
    // needs; its Rayleigh quotient is below lambda_max, so the printed
    // limit is then an upper bound (1.04e3 against 1.03e3 converged on the
    // coarse 3D test scene).
    if (!friction_law.is_rate_independent())
      {
        const bool rough = (parameters.solver.linear_solver == "CG-AMG");
        convexity_limit =
          1. / largest_weighted_delassus_eigenvalue(rough ? 1e-3 : 1e-8);
        pcout << "Gamma_3: the friction problem of a step is convex while "
              << "S (a - b) alpha < " << std::setprecision(3) << convexity_limit
              << (rough ? " (or a little less: estimated to 1e-3)" : "")
              << "; here S (a - b) alpha = "
              << parameters.friction.bound_S *
                   friction_law.one_sided_lipschitz_constant()
              << std::setprecision(6) << std::endl;
      }
  }


  // @sect4{ContactProblem::initialise_contact_state}

  // No friction force yet, the initial slip velocity, and every node
  // sticking (without friction Gamma_3 only carries the normal constraint:
  // every node slips freely).
  template <int dim>
  void ContactProblem<dim>::initialise_contact_state()
  {
    friction_force.reinit(contact_nodes.size() * (dim - 1));
    slip_velocity = tangential_velocities(velocity);
    node_state.assign(contact_nodes.size(),
                      friction_law.is_frictionless() ? NodeState::slip :
                                                       NodeState::stick);
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
    setup_contact_solver();
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
    const auto step = [this]() {
      const StepStatistics statistics = do_time_step();
      update_energy_balance();
      return statistics;
    };
    if (cuts_left == 0)
      return step();

    // Everything a step changes, kept to retake the step from it.
    const auto step_state = [this]() {
      return std::tie(velocity,
                      displacement,
                      mass_times_velocity,
                      elasticity_times_displacement,
                      friction_force,
                      slip_velocity,
                      node_state,
                      energy);
    };
    const auto saved = std::apply(
      [](const auto &...values) { return std::make_tuple(values...); },
      step_state());
    try
      {
        return step();
      }
    catch (const ExceptionBase &failure)
      {
        step_state() = saved;
        pcout << "Step " << step_number << " (t = " << time
              << ") did not converge with k = " << time_step
              << "; cutting it into two steps of k/2 ('Solver/Step cuts', "
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


  // @sect4{ContactProblem::largest_weighted_delassus_eigenvalue}

  // On Gamma_3 a step minimises
  //   E(v) = 1/2 (v - v_free)^T D^{-1} (v - v_free) + sum_p m_p j(v_p),
  // and j(v) = S int_0^|v| mu is concave along |v| with curvature down to
  // -S (a - b) alpha. E is convex, and the step's solution unique, while
  //   D^{-1} - S (a - b) alpha M >= 0,  i.e.
  //   S (a - b) alpha < 1 / lambda_max(M^{1/2} D M^{1/2}),
  // M = diag(m_p): the discrete, per-step counterpart of the paper's
  // condition (3.22), m_A > S lambda C_0^2, in which (rho/k) M + A + k B
  // takes the place of the viscosity and the trace constant is that of V_h.
  // lambda_max by the power method (M^{1/2} D M^{1/2} is symmetric positive
  // semidefinite), D applied as D or as C K^{-1} C^T, until the estimate
  // changes by less than `tolerance` relative (at most 200 iterations).
  template <int dim>
  double ContactProblem<dim>::largest_weighted_delassus_eigenvalue(
    const double tolerance)
  {
    const unsigned int n = contact_nodes.size(), m = dim - 1;
    Vector<double>     x(n * m), y(n * m), root_weight(n * m);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int i = 0; i < m; ++i)
        root_weight[p * m + i] = std::sqrt(contact_nodes[p].weight);
    const auto apply = [&](const Vector<double> &in, Vector<double> &out) {
      Vector<double> scaled(in);
      scaled.scale(root_weight);
      if (use_delassus_operator)
        delassus_operator.vmult(out, scaled);
      else
        {
          VectorType w(locally_owned_dofs, mpi_communicator);
          factorization->solve(w, friction_load(scaled));
          constraints.distribute(w);
          out = tangential_velocities(w);
        }
      out.scale(root_weight);
    };

    x               = 1.;
    double estimate = 0;
    for (unsigned int iteration = 0; iteration < 200; ++iteration)
      {
        x /= x.l2_norm();
        apply(x, y);
        const double rayleigh_quotient = x * y;
        x.swap(y);
        if (std::abs(rayleigh_quotient - estimate) <=
            tolerance * rayleigh_quotient)
          return rayleigh_quotient;
        estimate = rayleigh_quotient;
      }
    return estimate;
  }


  // @sect4{ContactProblem::delassus_operator_pays}

  // 'auto' takes the Delassus path while Gamma_3 has at most 2000
  // tangential unknowns (every Newton step factorises a dense block of D,
  // O(n^3)): the paper's scene in 2D down to h = 1/1024, 3D boxes like
  // prm/barboteu2015_3d.prm down to h = 1/32. Without CHOLMOD's triangular
  // factor it also needs Z = K^{-1} C^T, one solve per column and dense:
  // taken with a direct solver while Z fits in 1 GB per process; with
  // CG-AMG its columns would cost as many iterative solves as the
  // constraints path does in a run. Larger contact zones take the
  // constraints.
  template <int dim>
  bool ContactProblem<dim>::delassus_operator_pays() const
  {
    const double n_columns = contact_nodes.size() * (dim - 1);
    if (n_columns > 2000)
      return false;
    if (factorization->has_triangular_factor())
      return true;
    const double largest_part =
      Utilities::MPI::max(static_cast<double>(locally_owned_dofs.n_elements()),
                          mpi_communicator);
    return parameters.solver.linear_solver != "CG-AMG" &&
           largest_part * n_columns * sizeof(double) <= 1e9;
  }


  // @sect4{ContactProblem::build_delassus_operator}

  // The friction forces act on the body through C^T eta, where column p of
  // C^T is the unit tangent at node p (condensed with the constraints like
  // every load). The velocity of a step is
  //   w_n = K^{-1} (step_rhs - C^T eta),
  //   step_rhs = F_n + (1/k) M w_{n-1} - B u_{n-1},
  // and on Gamma_3 v = C w_n = v_free - D eta with the Delassus operator
  // D = C K^{-1} C^T, symmetric positive definite: the nonsmooth part of
  // every step lives on the few unknowns of Gamma_3 (doc/algorithm.md).
  template <int dim>
  void ContactProblem<dim>::build_delassus_operator()
  {
    TimerOutput::Scope t(computing_timer, "Delassus operator");
    if (factorization->has_triangular_factor())
      build_delassus_from_factor();
    else
      build_delassus_from_solves();
  }


  // @sect4{ContactProblem::build_delassus_from_factor}

  // With CHOLMOD's K = P^T L L^T P and Y = L^{-1} P C^T,
  //   D = Y^T Y,  v_free = Y^T y,  w_n = P^T L^{-T} (y - Y eta),
  // where y = L^{-1} P step_rhs: a step is one forward substitution, the
  // friction problem, and one backward substitution, i.e. one solve. Y is
  // sparse (column p is nonzero only on the elimination tree path from
  // node p's dofs to the root, a few separators), unlike K^{-1} C^T, which
  // is dense; it is stored transposed, as a sparse matrix with one row per
  // tangential unknown of Gamma_3.
  template <int dim>
  void ContactProblem<dim>::build_delassus_from_factor()
  {
    const unsigned int n_columns = contact_nodes.size() * (dim - 1);
    const unsigned int block     = 64;
    std::vector<std::vector<std::pair<unsigned int, double>>> columns_of_Y(
      n_columns);
    Vector<double> unit(n_columns);
    for (unsigned int first = 0; first < n_columns; first += block)
      {
        const unsigned int          size = std::min(block, n_columns - first);
        std::vector<VectorType>     loads(size);
        std::vector<Vector<double>> columns;
        for (unsigned int c = 0; c < size; ++c)
          {
            unit[first + c] = 1.;
            loads[c]        = friction_load(unit);
            unit[first + c] = 0.;
          }
        factorization->forward_substitution(columns, loads);
        for (unsigned int c = 0; c < size; ++c)
          for (unsigned int row = 0; row < columns[c].size(); ++row)
            if (columns[c][row] != 0.)
              columns_of_Y[first + c].emplace_back(row, columns[c][row]);
      }

    const unsigned int n_rows = locally_owned_dofs.n_elements();
    {
      DynamicSparsityPattern pattern(n_columns, n_rows);
      for (unsigned int s = 0; s < n_columns; ++s)
        for (const auto &entry : columns_of_Y[s])
          pattern.add(s, entry.first);
      delassus_factor_pattern.copy_from(pattern);
    }
    delassus_factor.reinit(delassus_factor_pattern);
    for (unsigned int s = 0; s < n_columns; ++s)
      for (const auto &[row, value] : columns_of_Y[s])
        delassus_factor.set(s, row, value);

    // D = Y^T Y, each entry once, so D is exactly symmetric.
    FullMatrix<double> D(n_columns, n_columns);
    Vector<double>     column(n_rows);
    for (unsigned int s = 0; s < n_columns; ++s)
      {
        for (const auto &[row, value] : columns_of_Y[s])
          column[row] = value;
        for (unsigned int r = 0; r <= s; ++r)
          {
            double entry = 0;
            for (const auto &[row, value] : columns_of_Y[r])
              entry += value * column[row];
            D(r, s) = D(s, r) = entry;
          }
        for (const auto &[row, value] : columns_of_Y[s])
          column[row] = 0.;
      }
    delassus_operator = DelassusOperator(D, dim - 1);
  }


  // @sect4{ContactProblem::build_delassus_from_solves}

  // Without a triangular factor (Amesos solvers, several processes), D
  // comes from the columns of Z = K^{-1} C^T, one solve each, kept as one
  // dense block over the locally owned unknowns: a step is then one solve
  // for w_free, the friction problem on Gamma_3 with v_free = C w_free, and
  // w_n = w_free - Z eta, one gemv (doc/algorithm.md).
  template <int dim>
  void ContactProblem<dim>::build_delassus_from_solves()
  {
    const unsigned int n_columns = contact_nodes.size() * (dim - 1);
    delassus_columns.reinit(locally_owned_dofs.n_elements(), n_columns);
    FullMatrix<double> D(n_columns, n_columns);
    Vector<double>     unit(n_columns);
    VectorType         column(locally_owned_dofs, mpi_communicator);
    for (unsigned int s = 0; s < n_columns; ++s)
      {
        unit[s] = 1.;
        factorization->solve(column, friction_load(unit));
        unit[s] = 0.;
        constraints.distribute(column);
        const Vector<double> v = tangential_velocities(column);
        for (unsigned int r = 0; r < n_columns; ++r)
          D(r, s) = v[r];
        unsigned int row = 0;
        for (const double value : column)
          delassus_columns(row++, s) = value;
      }

    // D is symmetric up to the round-off of the solves; the active set
    // method relies on it (Cholesky on the stick set), so it is made exactly
    // symmetric after checking that nothing more than round-off is removed.
    double asymmetry = 0, largest = 0;
    for (unsigned int r = 0; r < n_columns; ++r)
      {
        largest = std::max(largest, D(r, r));
        for (unsigned int s = 0; s < r; ++s)
          {
            const double mean = (D(r, s) + D(s, r)) / 2;
            asymmetry         = std::max(asymmetry, std::abs(D(r, s) - mean));
            D(r, s) = D(s, r) = mean;
          }
      }
    AssertThrow(asymmetry <= 1e-8 * largest,
                ExcMessage("The Delassus operator C K^{-1} C^T is not "
                           "symmetric beyond round-off (largest deviation " +
                           std::to_string(asymmetry / largest) +
                           " of its largest entry): the solves with K are "
                           "not accurate enough for the Delassus path; "
                           "choose 'Solver/Contact solver = constraints'."));
    delassus_operator = DelassusOperator(D, dim - 1);
  }


  // w -= Z eta on this process's unknowns: the velocity change that the
  // friction forces eta cause (Z's columns are distributed already).
  template <int dim>
  void ContactProblem<dim>::subtract_delassus_columns(const Vector<double> &eta,
                                                      VectorType &w) const
  {
    Vector<double> change(locally_owned_dofs.n_elements());
    delassus_columns.vmult(change, eta);
    auto value = w.begin();
    for (const double c : change)
      *value++ -= c;
  }


  // @sect4{ContactProblem::do_time_step}

  // One step of (5.2)-(5.5): the free velocity from the factorised K, the
  // friction forces from the problem on Gamma_3, then w_n and
  // u_n = u_{n-1} + k w_n. On the Delassus path the friction problem sits
  // between the forward and the backward substitution of one solve.
  template <int dim>
  StepStatistics ContactProblem<dim>::do_time_step()
  {
    old_velocity     = velocity;
    old_displacement = displacement;
    assemble_load(time, load, !body_force_is_constant, true);
    if (body_force_is_constant)
      load += constant_body_load;

    TimerOutput::Scope t(computing_timer, "Time steps");
    step_rhs = load;
    step_rhs.add(1. / time_step, mass_times_velocity);
    step_rhs.add(-1., elasticity_times_displacement);
    constraints.set_zero(step_rhs);

    StepStatistics statistics;
    Timer          substitution;
    solves_in_step = 0;
    recent_newton_solves.clear();
    const unsigned long long cg_iterations_before = factorization->iterations();
    if (use_delassus_operator && factorization->has_triangular_factor())
      {
        ++solves_in_step;
        std::vector<Vector<double>> y;
        factorization->forward_substitution(y, {step_rhs});
        double substitution_seconds = substitution.wall_time();

        Vector<double> free_slip_velocity(friction_force.size());
        delassus_factor.vmult(free_slip_velocity, y[0]);
        statistics = solve_friction_problem(free_slip_velocity);

        Vector<double> minus_eta(friction_force);
        minus_eta *= -1.;
        delassus_factor.Tvmult_add(y[0], minus_eta);
        substitution.restart();
        factorization->backward_substitution(velocity, y[0]);
        substitution_seconds += substitution.wall_time();
        substitution_time += substitution_seconds / n_time_steps;
        constraints.distribute(velocity);
      }
    else
      {
        solve_with_K(velocity, step_rhs);
        substitution_time += substitution.wall_time() / n_time_steps;
        constraints.distribute(velocity);
        if (friction_law.is_frictionless())
          {
            slip_velocity = tangential_velocities(velocity);
            add_contact_state(statistics);
          }
        else if (!contact_nodes.empty())
          {
            statistics =
              solve_friction_problem(tangential_velocities(velocity));
            if (use_delassus_operator)
              subtract_delassus_columns(friction_force, velocity);
            else
              velocity_for_friction_force(friction_force, velocity);
          }
      }

    statistics.solves_with_K = solves_in_step;
    statistics.cg_iterations =
      factorization->iterations() - cg_iterations_before;
    displacement = old_displacement;
    displacement.add(time_step, velocity);
    return statistics;
  }


  // @sect4{ContactProblem::solve_friction_problem}

  // The friction problem of a step on Gamma_3: by default Newton's method
  // on the full law (friction.h), with the convexification of the paper as
  // the fallback where Newton does not converge; 'Solver/Friction method =
  // convexification' takes the latter alone. A rate independent law (or no
  // friction) is one Tresca problem either way.
  template <int dim>
  StepStatistics ContactProblem<dim>::solve_friction_problem(
    const Vector<double> &free_slip_velocity)
  {
    StepStatistics statistics;
    const bool     newton = parameters.solver.friction_method == "Newton" &&
                        !friction_law.is_rate_independent();
    if (!newton || !solve_by_newton(free_slip_velocity, statistics))
      solve_by_convexification(free_slip_velocity, statistics);
    add_contact_state(statistics);
    return statistics;
  }


  // @sect4{ContactProblem::solve_by_newton}

  // Newton's method on the full law from the previous step's forces, slip
  // velocities and sets. It returns false, with the state of the step
  // untouched, if it does not converge. Far from the solution its model
  // caps the weakening at 0.9 times the convexity limit, where the model is
  // still convex (friction.h).
  template <int dim>
  bool
  ContactProblem<dim>::solve_by_newton(const Vector<double> &free_slip_velocity,
                                       StepStatistics       &statistics)
  {
    Vector<double>         eta(friction_force), v(slip_velocity);
    Vector<double>         weights(contact_nodes.size());
    std::vector<NodeState> state;
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      weights[p] = contact_nodes[p].weight;
    const auto [velocity_of_force, newton_step] =
      friction_operators(free_slip_velocity);
    const FrictionNewtonResult result = solve_friction_newton(
      velocity_of_force,
      newton_step,
      dim - 1,
      NodalLaw{friction_law, weights, 0.9 * convexity_limit},
      free_slip_velocity,
      active_set_parameter,
      parameters.solver.max_newton_iterations,
      parameters.solver.max_active_set_iterations,
      eta,
      v,
      state);
    statistics.convexification_iterations += result.convexification_steps;
    statistics.active_set_iterations += result.active_set_iterations;
    statistics.newton_iterations += result.iterations;
    if (!result.converged)
      {
        ++statistics.newton_fallbacks;
        return false;
      }
    friction_force = eta;
    slip_velocity  = v;
    node_state     = state;
    return true;
  }


  // @sect4{ContactProblem::solve_by_convexification}

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
  void ContactProblem<dim>::solve_by_convexification(
    const Vector<double> &free_slip_velocity,
    StepStatistics       &statistics)
  {
    const auto        &solver = parameters.solver;
    const unsigned int n      = contact_nodes.size();

    Vector<double> rate(n), bound(n), eta(friction_force),
      v(free_slip_velocity.size());
    const auto slip_rates = [&](const Vector<double> &velocities) {
      for (unsigned int p = 0; p < n; ++p)
        rate[p] = contact_nodes[p].tangential_vector(velocities, p).norm();
    };
    slip_rates(slip_velocity);
    std::vector<NodeState> state;
    std::vector<bool>      slip_set, previous_slip_set;
    AndersonAcceleration   anderson(solver.anderson_depth);
    double                 accepted_energy = std::numeric_limits<double>::max();
    double                 residual        = 0;
    bool                   converged       = false;

    const auto energy_on_gamma3 = [&]() {
      // E(v) with v = v_free - D eta: the quadratic term is
      // eta^T D eta / 2 = eta . (v_free - v) / 2.
      Vector<double> velocity_change(free_slip_velocity);
      velocity_change -= v;
      double value = 0.5 * (eta * velocity_change);
      for (unsigned int p = 0; p < n; ++p)
        value += contact_nodes[p].weight *
                 friction_law.potential(
                   contact_nodes[p].tangential_vector(v, p).norm());
      return value;
    };

    while (!converged && statistics.convexification_iterations <
                           solver.max_convexification_iterations)
      {
        ++statistics.convexification_iterations;
        for (unsigned int p = 0; p < n; ++p)
          bound[p] = friction_law.is_frictionless() ?
                       0. :
                       contact_nodes[p].weight * friction_law.bound(rate[p]);

        const TrescaResult tresca =
          solve_tresca_problem(free_slip_velocity, bound, eta, v, state);
        statistics.active_set_iterations += tresca.iterations;
        statistics.cycles_cured += tresca.cycles_cured;
        AssertThrow(
          tresca.converged,
          ExcMessage(
            "The active set method for the Tresca problem did not converge "
            "in step " +
            std::to_string(step_number) + " (t = " + std::to_string(time) +
            ", convexification iteration " +
            std::to_string(statistics.convexification_iterations) +
            ") within " + std::to_string(solver.max_active_set_iterations) +
            " iterations ('Solver/Max active set iterations'); its "
            "parameter c was halved " +
            std::to_string(tresca.cycles_cured) +
            " times against cycling. The sets cycle when D = C K^{-1} C^T "
            "is ill-conditioned, e.g. for a nearly incompressible material "
            "('Material/Poisson ratio' = " +
            std::to_string(parameters.material.poisson_ratio) +
            "). More iterations help (each halving damps the cycling), as "
            "may a different 'Solver/Active set parameter' (here " +
            std::to_string(solver.active_set_parameter) + ")."));

        const double energy_now = energy_on_gamma3();
        if (anderson.last_step_was_accelerated() &&
            energy_now > accepted_energy + 1e-13 * std::abs(accepted_energy))
          {
            // Safeguard: back to the plain step from the accepted iterate.
            ++statistics.rejected_accelerations;
            anderson.restart();
            slip_rates(slip_velocity);
            eta = friction_force;
            continue;
          }
        accepted_energy = energy_now;
        friction_force  = eta;
        slip_velocity   = v;
        node_state      = state;

        double scale = std::numeric_limits<double>::min();
        residual     = 0;
        slip_set.resize(n);
        Vector<double> new_rate(n);
        for (unsigned int p = 0; p < n; ++p)
          {
            new_rate[p] = contact_nodes[p].tangential_vector(v, p).norm();
            residual    = std::max(residual, std::abs(new_rate[p] - rate[p]));
            scale       = std::max({scale,
                                    new_rate[p],
                                    contact_nodes[p]
                                      .tangential_vector(free_slip_velocity, p)
                                      .norm()});
            slip_set[p] = (state[p] != NodeState::stick);
          }
        residual /= scale;
        converged = friction_law.is_rate_independent() ||
                    (residual <= solver.convexification_tolerance &&
                     slip_set == previous_slip_set);
        previous_slip_set = slip_set;
        anderson.next_iterate(rate, new_rate);
        for (double &r : rate)
          r = std::max(r, 0.);
      }

    AssertThrow(converged, ExcMessage(convexification_failure(residual)));
  }


  // @sect4{ContactProblem::friction_operators}

  // What the Tresca and the Newton method need of the body, on D or on the
  // whole body (active_set_constraints.cc): v = v_free - D eta for given
  // forces, and one Newton step for a linearisation. Both paths give the
  // same iterates; only the linear algebra differs.
  template <int dim>
  std::pair<TrescaVelocity, TrescaNewtonStep>
  ContactProblem<dim>::friction_operators(
    const Vector<double> &free_slip_velocity)
  {
    if (use_delassus_operator)
      return {[this, &free_slip_velocity](const Vector<double> &eta,
                                          Vector<double>       &v) {
                delassus_operator.vmult(v, eta);
                v.sadd(-1., 1., free_slip_velocity);
              },
              [this, &free_slip_velocity](
                const std::vector<NodeLinearisation> &linearisation,
                Vector<double>                       &eta,
                Vector<double>                       &v) {
                delassus_operator.newton_step(linearisation,
                                              free_slip_velocity,
                                              eta,
                                              v);
              }};
    return {[this](const Vector<double> &eta, Vector<double> &v) {
              VectorType w;
              velocity_for_friction_force(eta, w);
              v = tangential_velocities(w);
            },
            [this](const std::vector<NodeLinearisation> &linearisation,
                   Vector<double>                       &eta,
                   Vector<double>                       &v) {
              newton_step_with_constraints(linearisation, eta, v);
            }};
  }


  // @sect4{ContactProblem::solve_tresca_problem}

  // The Tresca problem of one convexification iteration.
  template <int dim>
  TrescaResult ContactProblem<dim>::solve_tresca_problem(
    const Vector<double>   &free_slip_velocity,
    const Vector<double>   &bound,
    Vector<double>         &eta,
    Vector<double>         &v,
    std::vector<NodeState> &state)
  {
    const auto [velocity_of_force, newton_step] =
      friction_operators(free_slip_velocity);
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


  // @sect4{ContactProblem::solve_with_K}

  // x = K^{-1} b, counted for the step's statistics; CG starts from x.
  template <int dim>
  void ContactProblem<dim>::solve_with_K(VectorType &x, const VectorType &b)
  {
    ++solves_in_step;
    factorization->solve(x, b);
  }


  // @sect4{ContactProblem::convexification_failure}

  // What a user needs when the convexification stops without converging:
  // where, how far from converged, and which data drive it.
  template <int dim>
  std::string
  ContactProblem<dim>::convexification_failure(const double residual) const
  {
    const auto        &solver   = parameters.solver;
    const auto        &friction = parameters.friction;
    std::ostringstream message;
    message << "The convexification did not converge in step " << step_number
            << " (t = " << time << ") within "
            << solver.max_convexification_iterations
            << " iterations ('Solver/Max convexification iterations'): the "
            << "slip rates still change by " << residual
            << " relative to the velocity (tolerance "
            << solver.convexification_tolerance
            << ", 'Solver/Convexification tolerance'); the last iterate has "
            << std::count(node_state.begin(),
                          node_state.end(),
                          NodeState::stick)
            << " stick and "
            << std::count(node_state.begin(), node_state.end(), NodeState::slip)
            << " slip nodes on Gamma_3. It contracts fast when "
            << "S (a - b) alpha is small against the stiffness of K on "
            << "Gamma_3; here S = " << friction.bound_S << ", (a - b) alpha = "
            << friction_law.one_sided_lipschitz_constant()
            << ", k = " << time_step
            << " (a step's problem is convex while S (a - b) alpha < "
            << convexity_limit << ")"
            << ". More iterations or a larger 'Solver/Anderson depth' help "
            << "most (doc/stability.md); a smaller 'Time/Time step' (or "
            << "'Solver/Step cuts') and a smaller 'Friction/Friction bound S' "
            << "make the step's problem more convex.";
    return message.str();
  }


  // @sect4{ContactProblem::add_contact_state}

  template <int dim>
  void ContactProblem<dim>::add_contact_state(StepStatistics &statistics) const
  {
    Tensor<1, dim> resultant;
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        if (node_state[p] == NodeState::stick)
          ++statistics.n_stick;
        else
          ++statistics.n_slip;
        statistics.max_slip_rate =
          std::max(statistics.max_slip_rate,
                   contact_nodes[p].tangential_vector(slip_velocity, p).norm());
        resultant += contact_nodes[p].tangential_vector(friction_force, p);
      }
    statistics.friction_force = resultant.norm();
  }


#define INSTANTIATE(dim)                                                         \
  template void   ContactProblem<dim>::factorize_system_matrix();                \
  template double ContactProblem<dim>::tangential_velocity(                      \
    const ContactNode<dim> &, const unsigned int, const VectorType &) const;     \
  template Vector<double> ContactProblem<dim>::tangential_velocities(            \
    const VectorType &) const;                                                   \
  template Vector<double> ContactProblem<dim>::sum_over_processes(               \
    const Vector<double> &) const;                                               \
  template void ContactProblem<dim>::build_delassus_operator();                  \
  template void ContactProblem<dim>::build_delassus_from_factor();               \
  template void ContactProblem<dim>::build_delassus_from_solves();               \
  template bool ContactProblem<dim>::delassus_operator_pays() const;             \
  template void ContactProblem<dim>::subtract_delassus_columns(                  \
    const Vector<double> &, VectorType &) const;                                 \
  template void           ContactProblem<dim>::setup_contact_solver();           \
  template void           ContactProblem<dim>::initialise_contact_state();       \
  template void           ContactProblem<dim>::change_time_step(const double);   \
  template StepStatistics ContactProblem<dim>::advance(const unsigned int);      \
  template VectorType     ContactProblem<dim>::friction_load(                    \
    const Vector<double> &) const;                                           \
  template void ContactProblem<dim>::add_nodal_force(const ContactNode<dim> &,   \
                                                     const Tensor<1, dim> &,     \
                                                     VectorType &) const;        \
  template TrescaResult ContactProblem<dim>::solve_tresca_problem(               \
    const Vector<double> &,                                                      \
    const Vector<double> &,                                                      \
    Vector<double> &,                                                            \
    Vector<double> &,                                                            \
    std::vector<NodeState> &);                                                   \
  template StepStatistics ContactProblem<dim>::do_time_step();                   \
  template std::string    ContactProblem<dim>::convexification_failure(          \
    const double) const;                                                      \
  template void ContactProblem<dim>::add_contact_state(StepStatistics &)         \
    const;                                                                       \
  template StepStatistics ContactProblem<dim>::solve_friction_problem(           \
    const Vector<double> &);                                                     \
  template bool ContactProblem<dim>::solve_by_newton(const Vector<double> &,     \
                                                     StepStatistics &);          \
  template void ContactProblem<dim>::solve_by_convexification(                   \
    const Vector<double> &, StepStatistics &);                                   \
  template std::pair<TrescaVelocity, TrescaNewtonStep>                           \
                ContactProblem<dim>::friction_operators(const Vector<double> &); \
  template void ContactProblem<dim>::solve_with_K(VectorType &,                  \
                                                  const VectorType &);

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
