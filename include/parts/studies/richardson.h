/**
 * Richardson extrapolation with the order that the runs show, and with two
 * known orders in h and k: the formulas that the error estimate
 * (error_estimate.cc) and the target's pilots (target_error_pilots.cc)
 * share (richardson.cc).
 */
#ifndef contact_richardson_h
#define contact_richardson_h

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace Contact
{
  /** A value that is not there: not measured, not defined, no estimate. */
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  /** An observed order outside this range means the runs are not in the
   *  asymptotic range: the scheme is first order for smooth solutions,
   *  about 2/3 with the corner singularity of the paper's scene, up to 2 in
   *  space with quadratic elements. */
  constexpr double min_plausible_order = 0.5;
  constexpr double max_plausible_order = 3;
  /** Where every observed order is below this, the differences hardly
   *  shrink (by less than 2^0.25 = 1.19 per halving): the quantity does not
   *  converge on these runs. */
  constexpr double min_converging_order = 0.25;
  /** Two observed orders (of the pairs h, 2h, 4h and 2h, 4h, 8h) that
   *  differ by more than this do not describe one power of h. */
  constexpr double max_order_drift = 0.5;
  /** Orders in h and k closer than this are not told apart: the estimate
   *  then uses the one order the runs show. */
  constexpr double min_order_separation = 0.25;

  /** The estimate from one quantity's differences between consecutive runs
   *  of the sequence h, 2h, 4h (, 8h): d_0 = Q_h - Q_2h, d_1 = Q_2h - Q_4h,
   *  d_2 = Q_4h - Q_8h (or the norms of the differences, for a field). */
  struct RichardsonEstimate
  {
    /** log2(|d_{i+1}| / |d_i|), finest pair first; NaN where a difference
     *  is zero or not defined. */
    std::vector<double> measured_orders;
    /** The order the estimate uses, the smallest measured one (which gives
     *  the larger estimate); NaN where there is no estimate. */
    double order = nan;
    /** |d_0| / (2^order - 1); NaN where the runs give no estimate. */
    double error = nan;
    /** Empty where the estimate rests on consistent runs; else a short
     *  verdict ("not asymptotic", "does not converge", ...), with the reason
     *  in `reason`. */
    std::string status;
    std::string reason;
  };

  /** The estimate from the differences of a sequence of runs (finest
   *  first; two or three of them). `signed_differences`: differences of a
   *  scalar, whose signs must agree, rather than norms of field
   *  differences. An estimate is given only where every order is in
   *  [min_plausible_order, max_plausible_order] and the orders agree within
   *  max_order_drift; it then uses the smallest. */
  RichardsonEstimate richardson_estimate(const std::vector<double> &differences,
                                         const bool signed_differences);

  /** |e_h + e_k| for errors of norms E_h, E_k whose directions have the
   *  cosine c (for a quantity: c = 1, their sizes add). */
  inline double combined_error(const double space_error,
                               const double time_error,
                               const double cosine)
  {
    return std::sqrt(space_error * space_error + time_error * time_error +
                     2 * cosine * space_error * time_error);
  }

  /** The orders p in h and q in k of a quantity's error, and the cosine of
   *  the angle between its space and time errors, where other runs (a
   *  target's pilots) measured them. */
  struct TwoOrders
  {
    double space;
    double time;
    double cosine;
  };
  using KnownOrders = std::map<std::string, TwoOrders>;

  /** The error of a run from d_fine and d_coarse (as above) where the error
   *  is e_h + e_k with the known orders; `field`: the
   *  d are norms of field differences, else signed differences. NaN where
   *  p and q are too close to tell the parts apart. */
  double two_order_error_estimate(const double     d_fine,
                                  const double     d_coarse,
                                  const TwoOrders &orders,
                                  const bool       field);

  /** "0.65" or "0.65 and 0.71": measured orders as the reasons of an
   *  estimate name them. */
  std::string orders_text(const std::vector<double> &orders);
} // namespace Contact

#endif
