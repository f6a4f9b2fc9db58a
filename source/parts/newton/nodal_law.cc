/* The nodal friction law with the coefficient not frozen, and the energy
   of a step on Gamma_3 that Newton's method descends on (NodalLaw,
   friction_newton.h). */

#include <core/complementarity.h>
#include <parts/newton/friction_newton.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
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
