/* The friction method 'Newton' (friction_method.h): Newton's method on the
   full law (FrictionNewton, friction_newton.h) for the friction problem of
   a step, with the core's convexification as the fallback where it does
   not converge. Its entry 'Max Newton iterations' is its own. */

#include <deal.II/base/exceptions.h>

#include <base/dimensions.h>
#include <core/friction_method.h>
#include <parts/newton/friction_newton.h>

#include <sstream>

namespace Contact
{
  namespace
  {
    // @sect3{The entries}

    /** The value of Newton's entries (Parameters::part<>("Newton")). */
    struct NewtonParameters
    {
      unsigned int max_iterations = 50;
    };

    const std::string method_name = "Newton";

    void declare_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Max Newton iterations",
                        "50",
                        Patterns::Integer(1),
                        "Iteration limit of the Newton method per step; "
                        "then the convexification takes over.");
    }

    std::any parse_entries(ParameterHandler &prm, const Parameters &)
    {
      NewtonParameters newton;
      newton.max_iterations = prm.get_integer("Max Newton iterations");
      return newton;
    }


    // @sect3{The method}

    // Newton's method on the full law from the previous step's forces, slip
    // velocities and sets, and the convexification (the fallback) where it
    // fails. A failure of both says first why Newton failed.
    template <int dim>
    class NewtonMethod : public FrictionMethod<dim>
    {
    public:
      void solve(FrictionStep<dim>   &step,
                 FrictionMethod<dim> &fallback,
                 StepStatistics      &statistics) override;

    private:
      std::string solve_by_newton(FrictionStep<dim> &step,
                                  StepStatistics    &statistics) const;
    };


    template <int dim>
    void NewtonMethod<dim>::solve(FrictionStep<dim>   &step,
                                  FrictionMethod<dim> &fallback,
                                  StepStatistics      &statistics)
    {
      const std::string newton_failure = solve_by_newton(step, statistics);
      if (newton_failure.empty())
        return;
      try
        {
          fallback.solve(step, fallback, statistics);
        }
      catch (const ExcStepNotConverged &failure)
        {
          // The user chose (or kept) Newton: say that it failed first, and
          // why, before what stopped its fallback.
          std::ostringstream fallback_failure;
          failure.print_info(fallback_failure);
          std::string reason = fallback_failure.str();
          reason.erase(0, reason.find_first_not_of(" \n"));
          reason.erase(reason.find_last_not_of(" \n") + 1);
          AssertThrow(false,
                      ExcStepNotConverged(
                        "Newton's method ('" + Entry::friction_method +
                        "' = Newton) did not solve step " +
                        std::to_string(step.label.step_number) + ": " +
                        newton_failure +
                        ". The convexification that took over did not "
                        "solve it either. " +
                        reason));
        }
    }


    // It returns why it failed (empty where it did not), with the state of
    // the step untouched, if it does not converge or ends on a point that
    // its curvature test does not certify as a local minimum of E
    // (friction.h). Far from the solution its model caps the weakening at
    // 0.9 times the convexity limit, where the model is still convex.
    template <int dim>
    std::string
    NewtonMethod<dim>::solve_by_newton(FrictionStep<dim> &step,
                                       StepStatistics    &statistics) const
    {
      const unsigned int max_iterations =
        step.parameters.template part<NewtonParameters>(method_name)
          .max_iterations;
      const unsigned int max_active_set_iterations =
        step.parameters.solver.max_active_set_iterations;
      Vector<double> eta(step.state.friction_force),
        v(step.state.slip_velocity);
      std::vector<NodeState> state;
      ContactPath<dim>      &path = step.path;
      NodalLaw               law{step.law,
                   step.law_weights,
                   weakening_cap_fraction * step.convexity_limit};
      law.convexity_limit               = step.convexity_limit;
      law.energy_accuracy               = path.energy_accuracy();
      law.velocity_scale                = step.velocity_scale;
      const FrictionNewtonResult result = solve_friction_newton(
        [&path](const std::vector<NodeLinearisation> &linearisation,
                Vector<double>                       &force,
                Vector<double>                       &velocity) {
          path.newton_step(linearisation, force, velocity);
        },
        [&path](const std::vector<NodeLinearisation> &linearisation) {
          return path.curvature_on_slip_set(linearisation);
        },
        dim - 1,
        law,
        step.active_set_parameter,
        max_iterations,
        max_active_set_iterations,
        eta,
        v,
        state);
      statistics.convexification_iterations += result.convexification_steps;
      statistics.active_set_iterations += result.active_set_iterations;
      statistics.newton_iterations += result.iterations;
      statistics.beyond_convexity_limit += result.beyond_convexity_limit;
      statistics.saddle_exits += result.saddle_exits;
      if (!step.all_processes(result.converged))
        {
          ++statistics.newton_fallbacks;
          statistics.minima_not_certified += result.minimum_not_certified;
          // The same reason on every process.
          if (!step.all_processes(!result.minimum_not_certified))
            return "its end point was not certified a local minimum of the "
                   "step's energy";
          if (!step.all_processes(!result.tresca_failed))
            return "a Tresca problem inside it did not converge within '" +
                   Entry::max_active_set_iterations +
                   "' = " + std::to_string(max_active_set_iterations) +
                   " iterations";
          return "it did not converge within '" + Entry::max_newton_iterations +
                 "' = " + std::to_string(max_iterations) + " iterations";
        }
      step.state.friction_force = eta;
      step.state.slip_velocity  = v;
      step.state.node_state     = state;
      return "";
    }


    // @sect3{The registration}

    // Rank 10: the first method, the default of 'Solver/Friction method'.
    // Its entry follows that one.
    template <int dim>
    bool register_newton()
    {
      return FrictionMethodRegistry<dim>::add(
        {method_name,
         "a semismooth Newton method on the full law, with the derivative of "
         "the friction coefficient in its Jacobian (on the constraints path "
         "the solver gets the matrix with the weakening capped below the "
         "convexity limit, positive definite, and the true slopes enter by a "
         "low-rank correction), a line search with sufficient decrease of "
         "the step's energy from the previous step's forces, and a "
         "convexification step (a Tresca problem) where the Newton step does "
         "not lower it. An end point beyond the convexity limit must pass a "
         "test of the energy's curvature (a local minimum, not a saddle); "
         "where it does not, or where Newton does not converge within 'Max "
         "Newton iterations', the convexification solves the step.",
         10,
         {"Solver",
          "Friction method",
          "Max Newton iterations",
          &declare_entries,
          &parse_entries},
         []() -> std::unique_ptr<FrictionMethod<dim>> {
           return std::make_unique<NewtonMethod<dim>>();
         }});
    }

#define REGISTER(dim) \
  const bool newton_registered_##dim = register_newton<dim>();
    CONTACT_INSTANTIATE(REGISTER)
#undef REGISTER
  } // namespace
} // namespace Contact
