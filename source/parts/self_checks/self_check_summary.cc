/* The self-checks' report (doc/verification.md): their largest values
   in the summary, their columns of time_series.csv, their checkpoint
   data, and the error that ends a run which failed one of them. */

#include <deal.II/base/exceptions.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <base/dimensions.h>
#include <core/geometry.h>
#include <parts/self_checks/self_checks.h>

#include <iomanip>
#include <sstream>

namespace Contact
{
  // @sect4{SelfChecks::checkpoint}

  // The checks' largest values so far: a resumed run reports the largest
  // over the whole run.
  template <int dim>
  void SelfChecks<dim>::checkpoint(CheckpointArchive &archive)
  {
    archive &largest_checks;
  }


  // @sect4{SelfChecks::finish}

  template <int dim>
  void SelfChecks<dim>::finish(RunSummary &)
  {
    // A value far below the tolerance is round-off, whose digits depend
    // on the machine (an exact zero on one BLAS kernel is round-off on
    // another): only its bound is printed.
    const auto line =
      [&](const std::string &name, const double value, const double violation) {
        this->pcout() << "  " << name << ": " << std::setprecision(2);
        if (value < round_off_bound)
          this->pcout() << "below " << round_off_bound;
        else
          this->pcout() << value;
        this->pcout() << (violation < tolerance ? "" : "  FAILED") << std::endl;
      };
    this->pcout()
      << "Self-checks, largest over the steps (each relative to the "
      << "step's own scale; each must stay below " << tolerance
      << "):" << std::endl;
    const SelfCheckValues &c = largest_checks;
    const auto check = [&](const std::string &name, const double value) {
      line(name, value, value);
    };
    check("matrices against the integrals of their forms", c.matrices);
    check("energy identity of each step (the solve)", c.algebraic_energy);
    check("load vector against the loads' integral", c.load_power);
    check("velocity in V_h (the constraints)", c.constraints);
    check("equations (5.2) from the stored fields", c.equation_residual);
    line("friction law at the stored velocities",
         c.friction_law,
         c.friction_law_excess);
    if (c.friction_law >= tolerance && c.friction_law_excess < tolerance)
      this->pcout() << "    (within what '" + Entry::convexification_tolerance +
                         "' allows, "
                    << "up to " << c.friction_law_allowance << ")" << std::endl;
    check("sticking nodes at rest", c.stick_motion);
    check("negative friction power on slipping nodes",
          c.negative_friction_power);
    if (moment_balance_is_checked)
      check("balance of moments about the z-axis", c.moment_balance);
    else if (this->problem().get_geometry().is_symmetric_about_z_axis())
      print_why_moments_are_not_checked();
  }


  // @sect4{SelfChecks::print_why_moments_are_not_checked}

  // On a round body, where a user expects the balance of moments, the
  // reason it is not a self-check of this run (setup_moment_balance()).
  template <int dim>
  void SelfChecks<dim>::print_why_moments_are_not_checked() const
  {
    this->pcout() << "  (balance of moments about the z-axis: not checked, ";
    if (!this->parameters().boundary.clamped_ids.empty())
      this->pcout() << "a clamp holds the body against turning; column "
                       "reaction_moment of time_series.csv is its moment)";
    else
      this->pcout()
        << (this->space().triangulation->has_hanging_nodes() ?
              "hanging nodes of the refined curved mesh follow their coarse "
              "cells, not the circle," :
              "the mapping's degree is above the element's,")
        << " so the rigid rotation is not in the finite element space; "
           "column reaction_moment of time_series.csv shows how far the "
           "balance holds)";
    this->pcout() << std::endl;
  }


  // @sect4{SelfChecks::require_success}

  // The end of a run whose self-check failed: an error that names the
  // check and the column of time_series.csv that shows from which step on.
  template <int dim>
  void SelfChecks<dim>::require_success() const
  {
    std::ostringstream failures;
    failures << std::setprecision(2);
    const auto add = [&](const double       value,
                         const std::string &what,
                         const std::string &column) {
      if (!(value < tolerance))
        failures << "\n  " << what << " holds only to " << value
                 << (column.empty() ?
                       "" :
                       " (column " + column + " of time_series.csv)");
    };
    add(largest_checks.matrices,
        "the matrices M, A, B against the integrals of their forms (before "
        "the first step)",
        "");
    add(largest_checks.algebraic_energy,
        "the energy identity of a step from the matrices, i.e. the steps' "
        "linear solves,",
        "algebraic_energy_residual, the sum over the steps in J,");
    add(largest_checks.load_power,
        "the load power of a step with the load vector against the loads' "
        "integral",
        "load_power_residual");
    add(largest_checks.constraints,
        "the constraints of V_h (clamp, bilateral contact) on the velocity",
        "constraint_residual");
    add(largest_checks.equation_residual,
        "the equations (5.2) of the step, from the stored fields with the "
        "friction forces put on the body by the checks' own map of Gamma_3,",
        "equation_residual");
    add(largest_checks.friction_law_excess,
        "the friction law at the stored velocities",
        "friction_law_residual");
    add(largest_checks.stick_motion,
        "the rest of the nodes the solver says stick (their speed relative "
        "to the larger of max |w_n| and max |v_free|)",
        "stick_speed");
    add(largest_checks.negative_friction_power,
        "the friction power on the slipping nodes, which must not be "
        "negative,",
        "friction_dissipation");
    add(largest_checks.moment_balance,
        "the balance of moments about the z-axis (the reactions of the "
        "constraints must have no moment)",
        "reaction_moment");
    std::ostringstream message;
    message << "Self-check failed (tolerance " << tolerance
            << "):" << failures.str() << "\nThe results in '"
            << this->parameters().output.directory
            << "' are not a solution of the scheme.";
    AssertThrow(failures.str().empty(), ExcMessage(message.str()));
  }


  // @sect4{SelfChecks::add_columns}

  // The checks' values of the step, with the momentum and the moments the
  // balance of moments adds up (columns of time_series.csv).
  template <int dim>
  void SelfChecks<dim>::add_columns(TimeSeriesRow &row) const
  {
    const StepState     &state = this->state();
    const Tensor<1, dim> p     = this->matrices().momentum(state.velocity);
    row.add("algebraic_energy_residual", state.energy.residual());
    row.add("load_power_residual", step_checks.load_power);
    row.add("constraint_residual", step_checks.constraints);
    row.add("equation_residual", step_checks.equation_residual);
    row.add("friction_law_residual", step_checks.friction_law);
    row.add("stick_speed", step_checks.stick_motion);
    for (unsigned int d = 0; d < dim; ++d)
      row.add(std::string("momentum_") + "xyz"[d], p[d]);
    row.add("angular_momentum", moments.angular_momentum);
    row.add("applied_moment", moments.applied);
    row.add("friction_moment", moments.friction);
    row.add("reaction_moment", moments.reaction);
  }


  // The members above, instantiated here as those of self_checks.cc are
  // there (the class is explicitly instantiated in that file only).
#define INSTANTIATE(dim)                                                    \
  template void SelfChecks<dim>::checkpoint(CheckpointArchive &);           \
  template void SelfChecks<dim>::finish(RunSummary &);                      \
  template void SelfChecks<dim>::print_why_moments_are_not_checked() const; \
  template void SelfChecks<dim>::require_success() const;                   \
  template void SelfChecks<dim>::add_columns(TimeSeriesRow &) const;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE

  namespace
  {
    const PostprocessorRegistration<SelfChecks> registration("self-checks", 30);
  }
} // namespace Contact
