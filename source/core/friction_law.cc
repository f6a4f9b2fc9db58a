/* The slip threshold of the friction law, and the nodal law of the
   friction problem on Gamma_3 with the energy of a step. */

#include <core/complementarity.h>
#include <core/friction.h>

#include <algorithm>
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


  // @sect3{The nodal law and the energy of a step}

  bool NodalLaw::may_be_nonconvex() const
  {
    return !(law.steepest_weakening() <
             weakening_cap_fraction * convexity_limit);
  }

  double NodalLaw::bound(const unsigned int p, const double s) const
  {
    return weights[p] * law.bound(s);
  }

  double NodalLaw::slope(const unsigned int p, const double s) const
  {
    return weights[p] * law.bound_derivative(s);
  }

  // For two iterates with v = v_free - D eta (D symmetric),
  //   eta^T D eta - eta_0^T D eta_0 = (eta + eta_0) . D (eta - eta_0)
  //                                 = (eta + eta_0) . (v_0 - v),
  // so E - eta_0^T D eta_0 / 2, which orders the iterates as E does, needs
  // no v_free (which on the constraints path costs a solve with K). A
  // solve's error in v is relative to the body's velocities, and the
  // quadratic term pairs them with the mean forces: the sum of those
  // products is the scale of its error.
  double NodalLaw::energy(const Vector<double> &reference_eta,
                          const Vector<double> &reference_v,
                          const Vector<double> &eta,
                          const Vector<double> &v,
                          double               &scale) const
  {
    AssertDimension(reference_eta.size(), eta.size());
    AssertDimension(reference_v.size(), v.size());
    const unsigned int m         = v.size() / weights.size();
    double             quadratic = 0, friction = 0, forces = 0;
    double             speed = velocity_scale;
    for (unsigned int r = 0; r < v.size(); ++r)
      {
        const double mean_force = 0.5 * (eta[r] + reference_eta[r]);
        quadratic += mean_force * (reference_v[r] - v[r]);
        forces += std::abs(mean_force);
        speed = std::max({speed, std::abs(v[r]), std::abs(reference_v[r])});
      }
    for (unsigned int p = 0; p < weights.size(); ++p)
      friction +=
        weights[p] * law.potential(Complementarity::node_norm(v, p, m));
    scale = std::abs(quadratic) + std::abs(friction) + forces * speed;
    return quadratic + friction;
  }

} // namespace Contact
