/* Newton's method on the full nonmonotone law of a step on Gamma_3: the
   iteration (FrictionNewton, parts/newton/friction_newton.h); the test of its
   end points and the exit from a saddle are in friction_newton_second_order.cc.
 */

#include <core/complementarity.h>
#include <parts/newton/friction_newton.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Contact
{
  using Complementarity::node_norm;
  using Complementarity::set_signature;

  // @sect3{The entry point}

  FrictionNewtonResult
  solve_friction_newton(const TrescaNewtonStep &newton_step,
                        const CurvatureTest    &curvature,
                        const unsigned int      m,
                        const NodalLaw         &law,
                        const Vector<double>   &c,
                        const unsigned int      max_iterations,
                        const unsigned int      max_active_set_iterations,
                        Vector<double>         &eta,
                        Vector<double>         &v,
                        std::vector<NodeState> &state)
  {
    return FrictionNewton(newton_step,
                          curvature,
                          m,
                          law,
                          c,
                          max_iterations,
                          max_active_set_iterations,
                          eta,
                          v)
      .solve(state);
  }


  // @sect3{The state of the iteration}

  namespace
  {
    // max_p g_p(0), at least the smallest positive double (a frictionless
    // step has all bounds 0).
    double largest_bound_of(const NodalLaw &law, const unsigned int n)
    {
      double largest = std::numeric_limits<double>::min();
      for (unsigned int p = 0; p < n; ++p)
        largest = std::max(largest, law.bound(p, 0.));
      return largest;
    }
  } // namespace

  FrictionNewton::FrictionNewton(const TrescaNewtonStep &step_solver,
                                 const CurvatureTest    &curvature_test,
                                 const unsigned int      n_components,
                                 const NodalLaw         &nodal_law,
                                 const Vector<double>   &parameter_c,
                                 const unsigned int      max_newton_iterations,
                                 const unsigned int      max_tresca_iterations,
                                 Vector<double>         &iterate_eta,
                                 Vector<double>         &iterate_v)
    : newton_step(step_solver)
    , curvature(curvature_test)
    , m(n_components)
    , law(nodal_law)
    , c(parameter_c)
    , max_iterations(max_newton_iterations)
    , max_active_set_iterations(max_tresca_iterations)
    , largest_bound(largest_bound_of(nodal_law, parameter_c.size()))
    , tolerance(friction_residual_tolerance * largest_bound)
    , may_uncap(std::isfinite(law.weakening_cap))
    , nonconvex(law.may_be_nonconvex())
    , eta(iterate_eta)
    , v(iterate_v)
    , capped(may_uncap)
    , residual(std::numeric_limits<double>::infinity())
    , energy(std::numeric_limits<double>::quiet_NaN())
    , solves_step(false)
    , new_energy(std::numeric_limits<double>::quiet_NaN())
    , uncap_below(constants.uncapping_residual * largest_bound)
    , capped_failed(false)
    , uncapped_failed(false)
    , creeping(0)
    , slow_steps(0)
  {
    AssertDimension(iterate_eta.size(), parameter_c.size() * m);
  }


  // @sect3{The iteration}

  // The method of the class documentation, top to bottom: the start, then
  // per iteration a Newton step with its line search (or the other model,
  // or a longer search along the true step, or a convexification step),
  // the extrapolation of slow full steps, the test for a solution (with
  // the exit from a saddle) and the stick proposal where the capped model
  // creeps.
  FrictionNewtonResult FrictionNewton::solve(std::vector<NodeState> &state)
  {
    if (nonconvex && !start())
      return result;
    linearisation = linearise(capped);
    // The start may already solve the step (a sticking step after a
    // sticking one does).
    bool solved = nonconvex && law_residual() <= tolerance && ends_step();
    while (!solved && result.iterations < max_iterations)
      {
        ++result.iterations;
        Step step = newton_step_with_line_search();
        if (try_other_model(step))
          continue;
        if (step.length == 0. && uncapped_failed)
          search_true_step_further(step);
        capped_failed = uncapped_failed = false;
        if (step.length == 0.)
          {
            if (!convexification_instead())
              {
                result.tresca_failed = true;
                break;
              }
          }
        else if (step.length < 1.)
          ++result.damped_steps;
        else if (step.capped && slow_steps >= constants.slow_limit)
          extrapolate();

        const double last_residual = residual;
        const bool   sets_repeat   = accept_trial();
        if (sets_repeat && residual <= tolerance)
          {
            solved = ends_step();
            continue;
          }
        const bool full_capped_step =
          step.capped && sets_repeat && step.length == 1.;
        count_slow_steps(full_capped_step, last_residual);
        if (creeping >= constants.creep_limit &&
            result.iterations < max_iterations && stick_proposal_taken())
          continue;
        if (may_uncap && full_capped_step && residual < uncap_below)
          {
            capped        = false;
            linearisation = linearise(capped);
          }
      }
    state.resize(c.size());
    for (unsigned int p = 0; p < c.size(); ++p)
      state[p] = linearisation[p].state;
    return result;
  }


  // @sect4{The start}

  // Where E may be nonconvex the first iterate is the convexification's,
  // the Tresca problem with the bounds of the previous slip rates, solved
  // to start_residual_tolerance; its result solves the step's equations.
  // False (and tresca_failed) if its active set method did not converge.
  bool FrictionNewton::start()
  {
    ++result.convexification_steps;
    if (!convexification_step(constants.start_residual_tolerance))
      {
        result.tresca_failed = true;
        return false;
      }
    eta.swap(new_eta);
    v.swap(new_v);
    solves_step = true;
    return true;
  }


  // @sect4{The Newton step and its line search}

  // The step of the current model from the current iterate into
  // (new_eta, new_v), line searched on E except for the first step of a
  // convex problem (whose start need not solve the step's equations, so
  // that E is not known there). The full step with the true slopes is kept
  // for search_true_step_further().
  FrictionNewton::Step FrictionNewton::newton_step_with_line_search()
  {
    new_eta    = eta;
    new_v      = v;
    new_energy = energy;
    Step step;
    step.capped = capped;
    try
      {
        newton_step(linearisation, new_eta, new_v);
      }
    catch (const ExcIndefiniteNewtonMatrix &)
      {
        // Both models give the solver the same capped matrix: straight to
        // the convexification step.
        step.refused = true;
        step.length  = 0.;
        return step;
      }
    if (result.iterations > 1 || nonconvex)
      {
        if (std::isnan(energy))
          energy = energy_here();
        if (!capped)
          {
            true_step_eta = new_eta;
            true_step_v   = new_v;
          }
        step.length = backtrack(constants.shortest_step);
      }
    return step;
  }

  // Where a model's step did not lower E, the other model (capped or true
  // slopes) is tried from the same iterate, if it has not failed there
  // and, for the true slopes, the residual is below uncap_below; a failed
  // true step halves uncap_below, so that the two models do not take turns
  // at the same residual. Returns whether the model was switched.
  bool FrictionNewton::try_other_model(const Step &step)
  {
    if (step.length != 0. || step.refused)
      return false;
    (capped ? capped_failed : uncapped_failed) = true;
    if (!(may_uncap && (capped ? !uncapped_failed && residual < uncap_below :
                                 !capped_failed)))
      return false;
    if (!capped)
      uncap_below = 0.5 * residual;
    capped        = !capped;
    linearisation = linearise(capped);
    return true;
  }

  // Neither model's step lowered E within three halvings (or the true one,
  // where no cap makes it the only model). Where the Hessian on the slip
  // set is nearly singular the true step is far too long, and a short step
  // along it may still lower E (the line search decides, as for every
  // step): it is searched down to shortest_true_step of its length, which
  // costs no solve, before the convexification step, which costs several
  // (doc/algorithm.md).
  void FrictionNewton::search_true_step_further(Step &step)
  {
    new_eta     = true_step_eta;
    new_v       = true_step_v;
    step.capped = false;
    step.length = backtrack(constants.shortest_true_step);
  }

  namespace
  {
    // The directional derivative E'(v; dv) of E at an iterate (eta, v) with
    // v = v_free - D eta, whose quadratic term has the gradient
    // D^{-1} (v - v_free) = -eta: where v_p != 0 the potential contributes
    // g_p(|v_p|) v_p / |v_p| . dv_p, where v_p = 0 its kink g_p(0) |dv_p|.
    double directional_derivative(const unsigned int    m,
                                  const NodalLaw       &law,
                                  const Vector<double> &eta,
                                  const Vector<double> &v,
                                  const Vector<double> &dv)
    {
      double derivative = 0;
      for (unsigned int p = 0; p < law.weights.size(); ++p)
        {
          const double s = node_norm(v, p, m);
          for (unsigned int i = 0; i < m; ++i)
            derivative -= eta[p * m + i] * dv[p * m + i];
          if (s > 0)
            for (unsigned int i = 0; i < m; ++i)
              derivative += law.bound(p, s) * v[p * m + i] / s * dv[p * m + i];
          else
            derivative += law.bound(p, 0.) * node_norm(dv, p, m);
        }
      return derivative;
    }

    // x = from + t (to - from): the point at length t along the step from
    // `from` to `to`.
    void point_along(const Vector<double> &from,
                     const Vector<double> &to,
                     const double          t,
                     Vector<double>       &x)
    {
      x = from;
      x.add(t, to, -t, from);
    }
  } // namespace

  // Backtracking on E from (eta, v) towards the Newton iterate
  // (new_eta, new_v), which (eta, v) move to together, v = v_free - D eta
  // being affine in eta, so that a shorter step costs no solve: halved
  // while the length stays above shortest_length. A length t is accepted
  // on sufficient decrease, E(t) <= E(0) + sufficient_decrease t min(E', 0)
  // up to the accuracy of E (law.energy_accuracy; near the solution the
  // decrease is below it). Returns the step length, 0 if none was
  // accepted.
  double FrictionNewton::backtrack(const double shortest_length)
  {
    Vector<double> dv(new_v);
    dv -= v;
    const double descent =
      std::min(directional_derivative(m, law, eta, v, dv), 0.);
    double     scale = 0;
    const auto full_eta(new_eta), full_v(new_v);
    const auto sufficient = [&](const double length) {
      new_energy = energy_at(new_eta, new_v, scale);
      // (A step whose solve broke down gives no finite E to compare.)
      return std::isfinite(new_energy) &&
             new_energy <= energy +
                             constants.sufficient_decrease * length * descent +
                             law.energy_accuracy * scale;
    };
    if (sufficient(1.))
      return 1.;
    for (double length = 0.5; length > shortest_length; length /= 2)
      {
        point_along(eta, full_eta, length, new_eta);
        point_along(v, full_v, length, new_v);
        if (sufficient(length))
          return length;
      }
    return 0.;
  }


  // @sect4{The convexification step}

  // No descent along the Newton direction: one convexification step
  // instead, solved like the start (its sets decide where Newton goes on
  // from). Should that rough solution not lower E (the exact one does), it
  // is solved to the full tolerance and taken (converged, its residual and
  // so its E are finite). Where the solver refused the first Newton step
  // of a convex problem, the iterate is still the previous step's state,
  // which does not solve this step's equations: E is not known there, and
  // the rough solution is taken. False if a Tresca problem did not
  // converge.
  bool FrictionNewton::convexification_instead()
  {
    if (std::isnan(energy) && solves_step)
      energy = energy_here();
    bool solved_step = false;
    ++result.convexification_steps;
    for (const double step_tolerance :
         {constants.start_residual_tolerance, friction_residual_tolerance})
      {
        solved_step = convexification_step(step_tolerance);
        if (!solved_step)
          break;
        if (!solves_step)
          {
            new_energy = energy_from(new_eta, new_v);
            break;
          }
        double scale = 0;
        new_energy   = energy_at(new_eta, new_v, scale);
        if (new_energy <= energy + law.energy_accuracy * scale)
          break;
      }
    return solved_step;
  }

  // One convexification step from (eta, v): the Tresca problem with the
  // bounds of the slip rates of v, which lowers E because j is concave
  // along |v| (a majorisation), its forces and velocities in
  // (new_eta, new_v). False if the active set method did not converge to
  // `relative_tolerance` (relative to the largest bound).
  bool FrictionNewton::convexification_step(const double relative_tolerance)
  {
    Vector<double> bound(c.size());
    for (unsigned int p = 0; p < c.size(); ++p)
      bound[p] = law.bound(p, node_norm(v, p, m));
    new_eta = eta;
    new_v   = v;
    // No velocity function: the active set method's first sets are those
    // of (eta, v), which costs no solve even where v is not the velocity
    // of eta this step (the previous step's state at the start of a
    // step).
    std::vector<NodeState> tresca_state;
    const TrescaResult     tresca = solve_tresca(TrescaVelocity(),
                                             newton_step,
                                             m,
                                             bound,
                                             c,
                                             max_active_set_iterations,
                                             new_eta,
                                             new_v,
                                             tresca_state,
                                             relative_tolerance);
    result.active_set_iterations += tresca.iterations;
    return tresca.converged;
  }


  // @sect4{The extrapolation of slow steps}

  // Along a step that lowered E at full length, longer lengths 2, 4, ...
  // up to longest_extrapolation while each lowers E further (no solve:
  // eta and v move together). (new_eta, new_v, new_energy) are the full
  // step on entry and the longest such step on return.
  void FrictionNewton::extrapolate()
  {
    const Vector<double> full_eta(new_eta), full_v(new_v);
    Vector<double>       trial_eta(eta.size()), trial_v(v.size());
    for (double length = 2.; length <= constants.longest_extrapolation;
         length *= 2)
      {
        point_along(eta, full_eta, length, trial_eta);
        point_along(v, full_v, length, trial_v);
        double       scale        = 0;
        const double trial_energy = energy_at(trial_eta, trial_v, scale);
        if (!(std::isfinite(trial_energy) &&
              trial_energy < new_energy - law.energy_accuracy * scale))
          return;
        new_eta.swap(trial_eta);
        new_v.swap(trial_v);
        new_energy = trial_energy;
      }
  }

  // The trial iterate becomes the iterate (the one before it is left in
  // (new_eta, new_v)), linearised with the current model. Returns whether
  // the sets repeat.
  bool FrictionNewton::accept_trial()
  {
    const std::vector<int> previous_sets = set_signature(linearisation);
    eta.swap(new_eta);
    v.swap(new_v);
    solves_step   = true;
    energy        = new_energy;
    linearisation = linearise(capped);
    residual      = law_residual();
    return set_signature(linearisation) == previous_sets;
  }

  // The counters of full capped steps on repeating sets in a row whose
  // residual grew (creeping) or fell by less than slow_contraction (slow).
  void FrictionNewton::count_slow_steps(const bool   full_capped_step,
                                        const double last)
  {
    creeping = (full_capped_step && residual > last ? creeping + 1 : 0);
    slow_steps =
      (full_capped_step && residual > constants.slow_contraction * last ?
         slow_steps + 1 :
         0);
  }


  // @sect4{The stick proposal}

  // Where the capped model creeps, one iteration proposes the nodes that
  // slow down to stick (propose_stick()). Returns whether the proposal
  // was taken, the iterate then linearised anew.
  bool FrictionNewton::stick_proposal_taken()
  {
    creeping = 0;
    ++result.iterations;
    if (!propose_stick())
      return false;
    slow_steps    = 0;
    linearisation = linearise(capped);
    residual      = law_residual();
    return true;
  }

  // The slip nodes that weaken faster than the cap and slowed down in the
  // last step (new_v holds the iterate before it) are proposed to stick:
  // one Newton step with them held at v_p = 0, taken if it lowers E.
  // Returns whether it was taken.
  bool FrictionNewton::propose_stick()
  {
    std::vector<NodeLinearisation> proposal = linearisation;
    bool                           any      = false;
    for (unsigned int p = 0; p < proposal.size(); ++p)
      {
        const double s = node_norm(v, p, m);
        if (proposal[p].state == NodeState::slip && proposal[p].bound > 0 &&
            law.slope(p, s) < proposal[p].definite_slope &&
            s < node_norm(new_v, p, m))
          {
            proposal[p].state = NodeState::stick;
            any               = true;
          }
      }
    if (!any)
      return false;
    Vector<double> trial_eta(eta), trial_v(v);
    try
      {
        newton_step(proposal, trial_eta, trial_v);
      }
    catch (const ExcIndefiniteNewtonMatrix &)
      {
        return false;
      }
    double       scale        = 0;
    const double trial_energy = energy_at(trial_eta, trial_v, scale);
    if (!(trial_energy < energy - law.energy_accuracy * scale))
      return false;
    eta.swap(trial_eta);
    v.swap(trial_v);
    energy = trial_energy;
    return true;
  }


  // @sect4{Convergence}

  // At a solution of the law: whether it ends the step, i.e. is a
  // certified local minimum, or a saddle that could not be left. A saddle
  // is left along its negative curvature (leave_saddle()) up to
  // max_saddle_exits times per step; E is then below the saddle's, which
  // no later step returns to (every one lowers E), and the method goes on
  // from there with the capped model (where the law has a cap), its
  // counters of slow and creeping steps reset.
  bool FrictionNewton::ends_step()
  {
    const Curvature verdict = test_second_order();
    if (verdict != Curvature::not_positive ||
        result.saddle_exits == constants.max_saddle_exits)
      return true;
    if (std::isnan(energy))
      energy = energy_here();
    if (!leave_saddle())
      return true;
    ++result.saddle_exits;
    // The next end point is judged on its own.
    result.minimum_not_certified  = false;
    result.beyond_convexity_limit = false;
    capped                        = may_uncap;
    capped_failed = uncapped_failed = false;
    creeping = slow_steps = 0;
    residual              = std::numeric_limits<double>::infinity();
    linearisation         = linearise(capped);
    return false;
  }


  // @sect3{The tools}

  // The linearisation at (eta, v) with the bound of the current slip rate,
  // g_p(|v_p|), and on slip nodes its tangent along zhat, capped at
  // law.weakening_cap if `capped_model`.
  std::vector<NodeLinearisation>
  FrictionNewton::linearise(const bool capped_model) const
  {
    const unsigned int n = c.size();
    Vector<double>     g(n);
    for (unsigned int p = 0; p < n; ++p)
      g[p] = law.bound(p, node_norm(v, p, m));
    std::vector<NodeLinearisation> lin =
      Complementarity::linearise(m, eta, v, g, c);
    // The force along zhat is g_p(s) + g_p'(s) zhat . (v_new - v), with
    // the slip rate s = |v_p| of the iterate: at a fixed point it is
    // g_p(s) even where v_p is not along zhat.
    for (unsigned int p = 0; p < n; ++p)
      if (lin[p].state == NodeState::slip && g[p] > 0)
        {
          double along = 0;
          for (unsigned int i = 0; i < m; ++i)
            along += lin[p].direction[i] * v[p * m + i];
          lin[p].definite_slope = -law.weakening_cap * law.weights[p];
          lin[p].slope          = law.slope(p, node_norm(v, p, m));
          if (capped_model)
            lin[p].slope = std::max(lin[p].slope, lin[p].definite_slope);
          lin[p].force = g[p] - lin[p].slope * along;
        }
    return lin;
  }

  // The complementarity residual of the iterate with the bounds of the
  // slip rates at which the law was linearised.
  double FrictionNewton::law_residual() const
  {
    Vector<double> bound(c.size());
    for (unsigned int p = 0; p < c.size(); ++p)
      bound[p] = linearisation[p].bound;
    return Complementarity::residual(m, eta, v, bound, c);
  }

  // E at (eta_at, v_at), measured from the reference iterate.
  double FrictionNewton::energy_at(const Vector<double> &eta_at,
                                   const Vector<double> &v_at,
                                   double               &scale) const
  {
    return law.energy(reference_eta, reference_v, eta_at, v_at, scale);
  }

  // E at the reference iterate, which from now on is (reference_eta,
  // reference_v): a solution of the step's equations.
  double FrictionNewton::energy_from(const Vector<double> &from_eta,
                                     const Vector<double> &from_v)
  {
    Assert(std::isnan(energy), ExcInternalError());
    reference_eta = from_eta;
    reference_v   = from_v;
    double scale  = 0;
    return energy_at(from_eta, from_v, scale);
  }

  // E at the current iterate, where it is first needed.
  double FrictionNewton::energy_here()
  {
    Assert(solves_step, ExcInternalError());
    return energy_from(eta, v);
  }

} // namespace Contact
