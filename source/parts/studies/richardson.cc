/* ---------------------------------------------------------------------
 * Richardson extrapolation (include/parts/studies/richardson.h).
 *
 * The scheme converges as O(h^p + k^q) (Corollary 5.3, (5.26)). Where the
 * error behaves like C h^p on a sequence of runs with h, 2h, 4h (and 8h),
 * the differences d_i of consecutive runs satisfy d_{i+1} / d_i = 2^p, and
 * the error of the finest run is
 *
 *   Q - Q_h = d_0 / (2^p - 1)                  (Richardson extrapolation)
 *
 * with p measured, not assumed. The error estimate of a run
 * (error_estimate.cc) and the pilots of a target (target_error_pilots.cc)
 * both extrapolate with these formulas.
 * --------------------------------------------------------------------- */

#include <deal.II/base/exceptions.h>

#include <core/parameters.h>
#include <parts/studies/richardson.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace Contact
{
  // "0.65" or "0.65 and 0.71".
  std::string orders_text(const std::vector<double> &orders)
  {
    std::ostringstream text;
    text << std::fixed << std::setprecision(2);
    for (unsigned int i = 0; i < orders.size(); ++i)
      text << (i == 0 ? "" : " and ") << orders[i];
    return text.str();
  }


  // @sect3{Richardson extrapolation with the observed order}
  //
  // A field's differences are norms, so only their sizes are compared;
  // Richardson's formula then assumes that the error keeps its shape from
  // one run to the next. Where it does not (the oscillation of the
  // gradient of Lagrange elements moves with the mesh), the differences
  // are larger than (2^p - 1) ||e_h|| and the estimate errs on the safe
  // side: by up to 3.2 for first order and orthogonal error fields
  // (tests/unit/richardson_estimate).
  RichardsonEstimate richardson_estimate(const std::vector<double> &differences,
                                         const bool signed_differences)
  {
    AssertThrow(differences.size() >= 2, ExcInternalError());
    RichardsonEstimate estimate;
    const auto         verdict = [&](const std::string &status,
                             const std::string &reason) {
      estimate.status = status;
      estimate.reason = reason;
      return estimate;
    };
    for (unsigned int i = 0; i + 1 < differences.size(); ++i)
      estimate.measured_orders.push_back(
        differences[i] == 0 || differences[i + 1] == 0 ?
          nan :
          std::log2(std::abs(differences[i + 1]) / std::abs(differences[i])));
    bool all_zero = true, some_zero = false, signs_differ = false;
    for (const double d : differences)
      {
        if (!std::isfinite(d))
          return verdict("not defined", "not defined on every run");
        all_zero     = all_zero && d == 0;
        some_zero    = some_zero || d == 0;
        signs_differ = signs_differ || d * differences[0] < 0;
      }
    if (all_zero)
      return verdict("the same on every run", "the runs cannot show its error");
    if (some_zero)
      return verdict("not asymptotic",
                     "the same on two consecutive runs but not on all");
    if (signed_differences && signs_differ)
      return verdict("not asymptotic",
                     "the differences between consecutive runs change sign");
    const auto [lowest, highest] =
      std::minmax_element(estimate.measured_orders.begin(),
                          estimate.measured_orders.end());
    if (*highest < min_converging_order)
      return verdict("does not converge",
                     "the differences do not shrink (orders measured " +
                       orders_text(estimate.measured_orders) + ")");
    if (*lowest < min_plausible_order || *highest > max_plausible_order)
      return verdict("not asymptotic",
                     "orders measured " +
                       orders_text(estimate.measured_orders) +
                       ", not all in [" + number_text(min_plausible_order) +
                       ", " + number_text(max_plausible_order) + "]");
    if (*highest - *lowest > max_order_drift)
      return verdict("not asymptotic",
                     "orders measured " +
                       orders_text(estimate.measured_orders) +
                       ", which differ by more than " +
                       number_text(max_order_drift));
    estimate.order = *lowest;
    estimate.error =
      std::abs(differences[0]) / (std::pow(2., estimate.order) - 1);
    return estimate;
  }


  // @sect3{Two orders}
  //
  // With quadratic elements the space error falls with h^2 and the time
  // error with k: where one part dominates the coarse runs and the other
  // the fine one, the one order that the three runs show describes
  // neither. With the orders p and q known, e = e_h + e_k and
  //
  //   d_fine   = a1 e_h + b1 e_k,   a1 = 2^p - 1, b1 = 2^q - 1,
  //   d_coarse = a2 e_h + b2 e_k,   a2 = 2^p a1,  b2 = 2^q b1.
  //
  // For a quantity these are two linear equations for the two parts. For a
  // field only norms are known, and with the cosine c of the angle between
  // e_h and e_k (measured by the pilots) the ratio rho = |e_h| / |e_k|
  // solves
  //
  //   d_coarse^2 / d_fine^2 = (a2^2 rho^2 + b2^2 + 2 c a2 b2 rho)
  //                         / (a1^2 rho^2 + b1^2 + 2 c a1 b1 rho),
  //
  // which moves monotonically from 4^q (rho = 0) to 4^p (rho = infinity);
  // a ratio outside is all time or all space error.
  double two_order_error_estimate(const double     d_fine,
                                  const double     d_coarse,
                                  const TwoOrders &orders,
                                  const bool       field)
  {
    if (!(std::abs(orders.space - orders.time) >= min_order_separation) ||
        !std::isfinite(d_fine) || !std::isfinite(d_coarse))
      return nan;
    const double a1 = std::pow(2., orders.space) - 1;
    const double a2 = std::pow(2., orders.space) * a1;
    const double b1 = std::pow(2., orders.time) - 1;
    const double b2 = std::pow(2., orders.time) * b1;
    if (!field)
      {
        const double determinant = a1 * b2 - a2 * b1;
        return std::abs(((b2 - a2) * d_fine + (a1 - b1) * d_coarse) /
                        determinant);
      }
    const double c     = orders.cosine;
    const auto   ratio = [&](const double rho) {
      return (a2 * a2 * rho * rho + b2 * b2 + 2 * c * a2 * b2 * rho) /
             (a1 * a1 * rho * rho + b1 * b1 + 2 * c * a1 * b1 * rho);
    };
    const double observed = d_coarse * d_coarse / (d_fine * d_fine);
    // Bisection in s = rho / (1 + rho), from 0 (all time) to 1 (all space).
    double low = 0, high = 1;
    for (unsigned int i = 0; i < 60; ++i)
      {
        const double middle = (low + high) / 2;
        const bool   space_dominated_enough =
          ratio(middle / (1 - middle)) >= observed;
        (space_dominated_enough == (orders.space > orders.time) ? high : low) =
          middle;
      }
    const double s = (low + high) / 2;
    if (s >= 1 - 1e-12)
      return d_fine / a1;
    const double rho = s / (1 - s);
    const double time_error =
      d_fine / std::sqrt(a1 * a1 * rho * rho + b1 * b1 + 2 * c * a1 * b1 * rho);
    return combined_error(rho * time_error, time_error, c);
  }
} // namespace Contact
