/**
 * 'Accuracy/Estimate error': a run that also says how accurate it is. The
 * scene runs as given, then with h and k doubled and with h and k
 * quadrupled; from the three values of each quantity at T the error of the
 * given run is estimated by Richardson extrapolation with the order the
 * three runs show (error_estimate.cc).
 */
#ifndef contact_error_estimate_h
#define contact_error_estimate_h

#include <deal.II/base/parameter_handler.h>

#include <parameters.h>

#include <limits>
#include <string>

namespace Contact
{
  /** An observed order outside this range gets a warning: the scheme is
   *  first order for smooth solutions, about 2/3 with the corner
   *  singularity of the paper's scene, up to 2 in space with quadratic
   *  elements. */
  constexpr double min_plausible_order = 0.5;
  constexpr double max_plausible_order = 3;
  /** The coarse runs take ceil(N / 2) and ceil(N / 4) steps; a ratio of
   *  their time step to the run's that differs from 2 or 4 by more than
   *  this (relative) gets a warning. */
  constexpr double max_step_ratio_deviation = 0.05;

  /** The estimate from one quantity's values on the run (h, k), with 2h
   *  and with 4h, for differences d_fine = Q_h - Q_2h and d_coarse =
   *  Q_2h - Q_4h (or their norms, for a field). */
  struct RichardsonEstimate
  {
    /** log2(|d_coarse| / |d_fine|); NaN where it is not defined. */
    double order = 0;
    /** |d_fine| / (2^order - 1), or |d_fine| where the differences do not
     *  shrink or change sign (no extrapolation then), or |d_coarse| / 2
     *  where d_fine = 0. */
    double error = 0;
    /** For a field: the correlation c of the error fields of consecutive
     *  runs that the three differences show (1: the error keeps its
     *  shape, Richardson's assumption); NaN for a scalar. */
    double correlation = std::numeric_limits<double>::quiet_NaN();
    /** Why the three runs are not in the asymptotic range, or empty. */
    std::string warning;
  };

  /** `signed_differences`: whether d_fine and d_coarse are differences of
   *  a scalar (whose signs must agree) or norms of field differences. */
  RichardsonEstimate richardson_estimate(const double d_fine,
                                         const double d_coarse,
                                         const bool   signed_differences);

  /** The error of a quantity at T: Richardson's estimate with its own
   *  order, or with the V-norm's `field_order` where its own is lower or
   *  not defined (the differences do not shrink) but the differences keep
   *  their sign (error_estimate.cc). */
  RichardsonEstimate scalar_error_estimate(const double d_fine,
                                           const double d_coarse,
                                           const double field_order);

  /** The error of a field from the norms of the differences of its three
   *  runs, d_fine = ||u_h - u_2h||, d_coarse = ||u_2h - u_4h|| and d_across
   *  = ||u_h - u_4h|| (error_estimate.cc explains the model). */
  RichardsonEstimate field_error_estimate(const double d_fine,
                                          const double d_coarse,
                                          const double d_across);

  /** Runs the scene of `parameters` and its two coarse versions, and prints
   *  and writes the estimated errors (error_estimate.txt). */
  template <int dim>
  void run_with_error_estimate(ParameterHandler &prm,
                               const Parameters &parameters);
} // namespace Contact

#endif
