/* The core's method for the friction problem of a step on Gamma_3: the
   convexification of the paper's section 6 around Tresca problems, a part
   of the kind FrictionMethod (friction_method.h) like any other method. */

#include <deal.II/base/exceptions.h>

#include <base/dimensions.h>
#include <core/friction_method.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace Contact
{
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


    // @sect4{The energy on Gamma_3}

    // E(v) with v = v_free - D eta: the quadratic term is
    // eta^T D eta / 2 = eta . (v_free - v) / 2.
    template <int dim>
    double energy_on_gamma3(const FrictionStep<dim> &step,
                            const Vector<double>    &free_slip_velocity,
                            const Vector<double>    &eta,
                            const Vector<double>    &v)
    {
      const auto    &nodes = step.gamma3.nodes;
      Vector<double> velocity_change(free_slip_velocity);
      velocity_change -= v;
      double value = 0.5 * (eta * velocity_change);
      for (unsigned int p = 0; p < nodes.size(); ++p)
        value += nodes[p].weight *
                 step.law.potential(nodes[p].tangential_vector(v, p).norm());
      return value;
    }


    // @sect4{The failures}

    // What a user needs when the active set method of a Tresca problem
    // does not converge: where, and what makes the sets cycle.
    template <int dim>
    std::string tresca_failure(const FrictionStep<dim> &step,
                               const unsigned int       iteration,
                               const unsigned int       cycles_cured)
    {
      const auto &solver = step.parameters.solver;
      return "The active set method for the Tresca problem did not converge "
             "in step " +
             std::to_string(step.label.step_number) +
             " (t = " + number_text(step.label.time) +
             ", convexification iteration " + std::to_string(iteration) +
             ") within " + std::to_string(solver.max_active_set_iterations) +
             " iterations ('" + Entry::max_active_set_iterations +
             "'); its parameter c was halved " + std::to_string(cycles_cured) +
             " times against cycling. The sets cycle when D = C K^{-1} C^T "
             "is ill-conditioned, e.g. for a nearly incompressible material "
             "('" +
             Entry::poisson_ratio +
             "' = " + std::to_string(step.parameters.material.poisson_ratio) +
             "). More iterations help (each halving damps the cycling), as "
             "may a different '" +
             Entry::active_set_parameter + "' (here " +
             std::to_string(solver.active_set_parameter) + ").";
    }


    // @sect4{The Tresca problem of an iteration}

    // The Tresca problem with the bounds g_p = m_p S mu(s_p) of the slip
    // rates s, on the step's path: v = v_free - D eta for given forces and
    // one Newton step are what the Tresca method needs of the body. Its
    // iterations are counted; where it does not converge, the step is not
    // solved.
    template <int dim>
    void solve_tresca_problem(const FrictionStep<dim> &step,
                              const Vector<double>    &rate,
                              const unsigned int       iteration,
                              Vector<double>          &eta,
                              Vector<double>          &v,
                              std::vector<NodeState>  &state,
                              StepStatistics          &statistics)
    {
      const FrictionLaw &law = step.law;
      Vector<double>     bound(rate.size());
      for (unsigned int p = 0; p < rate.size(); ++p)
        bound[p] =
          law.is_frictionless() ? 0. : step.law_weights[p] * law.bound(rate[p]);
      ContactPath<dim>  &path   = step.path;
      const TrescaResult tresca = solve_tresca(
        [&path](const Vector<double> &force, Vector<double> &velocity) {
          path.velocity_of_force(force, velocity);
        },
        [&path](const std::vector<NodeLinearisation> &linearisation,
                Vector<double>                       &force,
                Vector<double>                       &velocity) {
          path.newton_step(linearisation, force, velocity);
        },
        dim - 1,
        bound,
        step.active_set_parameter,
        step.parameters.solver.max_active_set_iterations,
        eta,
        v,
        state);
      statistics.active_set_iterations += tresca.iterations;
      statistics.cycles_cured += tresca.cycles_cured;
      AssertThrow(step.all_processes(tresca.converged),
                  ExcStepNotConverged(
                    tresca_failure(step, iteration, tresca.cycles_cured)));
    }


    // @sect4{When the convexification does not converge}

    // What a user needs when the convexification stops without
    // converging: where, how far from converged, and which data drive it.
    template <int dim>
    std::string convexification_failure(const FrictionStep<dim> &step,
                                        const double             residual)
    {
      const auto        &solver   = step.parameters.solver;
      const auto        &friction = step.parameters.friction;
      const auto        &states   = step.state.node_state;
      std::ostringstream message;
      message
        << "The convexification did not converge in step "
        << step.label.step_number << " (t = " << step.label.time << ") within "
        << solver.max_convexification_iterations
        << " iterations ('" + Entry::max_convexification_iterations + "'): the "
        << "slip rates still change by " << residual
        << " relative to the velocity (tolerance "
        << solver.convexification_tolerance
        << ", '" + Entry::convexification_tolerance +
             "'); the last iterate has "
        << std::count(states.begin(), states.end(), NodeState::stick)
        << " stick and "
        << std::count(states.begin(), states.end(), NodeState::slip)
        << " slip nodes on Gamma_3. It contracts fast when "
        << "S (a - b) alpha is small against the stiffness of K on "
        << "Gamma_3; here S = " << friction.bound_S
        << ", (a - b) alpha = " << step.law.one_sided_lipschitz_constant()
        << ", k = " << step.label.time_step
        << " (a step's problem is convex while S (a - b) alpha < "
        << step.convexity_limit << ")"
        << ". More iterations or a larger '" + Entry::anderson_depth + "' help "
        << "most (doc/stability.md); a smaller '" + Entry::time_step + "' (or "
        << "'" + Entry::step_cuts + "') and a smaller '" +
             Entry::friction_bound_S + "' "
        << "make the step's problem more convex.";
      return message.str();
    }
  } // namespace


  // @sect4{Convexification::solve}

  // The convexification of the paper's section 6 (refs [3, 4] there):
  // freeze the coefficient at slip rates s, g_p = m_p S mu(s_p), solve the
  // convex Tresca problem with these bounds, and repeat with s = |v| until
  // the slip rates and the slip set stop changing. The first s is the
  // previous step's slip rate: when (3.22) fails the discrete problem may
  // have several solutions, and starting from the past selects the one that
  // continues the motion. A rate independent law is one Tresca problem.
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
  void Convexification<dim>::solve(FrictionStep<dim> &step,
                                   FrictionMethod<dim> & /*fallback*/,
                                   StepStatistics &statistics)
  {
    const auto           &solver             = step.parameters.solver;
    const FrictionLaw    &law                = step.law;
    FrictionState        &current            = step.state;
    const auto           &nodes              = step.gamma3.nodes;
    const unsigned int    n                  = nodes.size();
    const Vector<double> &free_slip_velocity = step.path.free_slip_velocity();

    Vector<double> rate(n), eta(current.friction_force),
      v(free_slip_velocity.size());
    const auto slip_rates = [&](const Vector<double> &velocities) {
      for (unsigned int p = 0; p < n; ++p)
        rate[p] = nodes[p].tangential_vector(velocities, p).norm();
    };
    slip_rates(current.slip_velocity);
    // The stick/slip states of the iterate and of the last accepted one.
    std::vector<NodeState> state, previous_state;
    AndersonAcceleration   anderson(solver.anderson_depth);
    double                 accepted_energy = std::numeric_limits<double>::max();
    double                 residual = 0, rate_scale = 0;
    bool                   converged = false;
    // Its own count: where it takes over from another method, the Tresca
    // steps that one took do not use up its 'Max convexification
    // iterations'.
    unsigned int iterations = 0;

    while (!converged && iterations < solver.max_convexification_iterations)
      {
        ++iterations;
        ++statistics.convexification_iterations;
        solve_tresca_problem(step, rate, iterations, eta, v, state, statistics);

        const double energy_now =
          energy_on_gamma3(step, free_slip_velocity, eta, v);
        if (!step.all_processes(
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
          slip_rate_change(nodes, rate, v, free_slip_velocity, new_rate);
        converged =
          step.all_processes(law.is_rate_independent() ||
                             (residual <= solver.convexification_tolerance &&
                              state == previous_state));
        previous_state = state;
        anderson.next_iterate(rate, new_rate);
        for (double &r : rate)
          r = std::max(r, 0.);
      }

    AssertThrow(converged,
                ExcStepNotConverged(convexification_failure(step, residual)));
    if (!law.is_rate_independent())
      step.law_residual_allowance = law.one_sided_lipschitz_constant() /
                                    law.coefficient(0.) * residual * rate_scale;
  }


  namespace
  {
    // The convexification is the core's method, registered like every
    // other one. Rank 20: after the method that it is the fallback of,
    // Newton's (a part), which its description compares it with, as the
    // help text of 'Solver/Friction method' always did.
    template <int dim>
    bool register_convexification()
    {
      return FrictionMethodRegistry<dim>::add(
        {"convexification",
         "the paper's fixed point, one Tresca "
         "problem per iteration (with Anderson acceleration), solved by the "
         "primal-dual active set method; it is the fallback of Newton. Both "
         "find the same solution where the step problem has one; where it "
         "has several (S (a - b) alpha above the convexity limit printed at "
         "start-up) both start with the same Tresca step from the previous "
         "step's state and may then end on different local minima: Newton "
         "returns the one its descent on the step's energy reaches "
         "(doc/algorithm.md), and its summary line counts the steps beyond "
         "the convexity limit and the steps the convexification took over.",
         20,
         {},
         []() -> std::unique_ptr<FrictionMethod<dim>> {
           return std::make_unique<Convexification<dim>>();
         }});
    }

#define REGISTER(dim) \
  const bool convexification_registered_##dim = register_convexification<dim>();
    CONTACT_INSTANTIATE(REGISTER)
#undef REGISTER
  } // namespace


#define INSTANTIATE(dim) template class Convexification<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
