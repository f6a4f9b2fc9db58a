/* The slip threshold of the friction law. */

#include <core/friction.h>

#include <cmath>

namespace Contact
{
  // @sect3{The friction law}

  // The law itself is one file of source/base/friction_laws/; here only what
  // holds for every law: S = 0 leaves no friction term, and a rate
  // independent law has no derivative and the potential S mu(0) s (the law
  // is not asked, so that its formula need not handle its constant cases,
  // e.g. alpha = 0 in (6.1), where it would divide by zero).
  FrictionLaw::FrictionLaw(const FrictionParameters &parameters)
    : law(parameters.law)
    , S(parameters.bound_S)
    , frictionless(S == 0. || (law && law->is_frictionless()))
    , rate_independent(law && law->is_rate_independent())
  {
    AssertThrow(law,
                ExcMessage("FrictionLaw: the parameters hold no friction law "
                           "(FrictionParameters::parse_parameters() reads "
                           "it)."));
  }

  double FrictionLaw::coefficient(const double slip_rate) const
  {
    return law->coefficient(slip_rate);
  }

  double FrictionLaw::bound(const double slip_rate) const
  {
    return S * law->coefficient(slip_rate);
  }

  double FrictionLaw::bound_derivative(const double slip_rate) const
  {
    if (frictionless || rate_independent)
      return 0.;
    return law->bound_derivative(S, slip_rate);
  }

  double FrictionLaw::potential(const double slip_velocity) const
  {
    const double s = std::abs(slip_velocity);
    if (frictionless)
      return 0.;
    if (rate_independent)
      return S * law->coefficient(0.) * s;
    return law->potential(S, s);
  }

  bool FrictionLaw::is_frictionless() const
  {
    return frictionless;
  }

  bool FrictionLaw::is_rate_independent() const
  {
    return rate_independent;
  }

  double FrictionLaw::one_sided_lipschitz_constant() const
  {
    return rate_independent ? 0. : law->one_sided_lipschitz_constant();
  }

  double FrictionLaw::steepest_weakening() const
  {
    return frictionless ? 0. : S * one_sided_lipschitz_constant();
  }

} // namespace Contact
