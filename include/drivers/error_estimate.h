/**
 * 'Accuracy/Estimate error': a run that also says how accurate it is. The
 * scene runs as given, then with h and k doubled and with h and k
 * quadrupled; from the three values of each quantity at T the error of the
 * given run is estimated by Richardson extrapolation with the order the
 * three runs show (error_estimate.cc).
 */
#ifndef contact_error_estimate_h
#define contact_error_estimate_h

#include <core/contact_problem.h>
#include <base/parameters.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

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
  /** Orders in h and k closer than this are not told apart: the estimate
   *  then uses the one order the runs show. */
  constexpr double min_order_separation = 0.25;

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

  /** One row of an estimate's table: a quantity's value (for the V-norm
   *  ||eps(u_h(T))||), its differences to the runs with 2h and 4h (for the
   *  V-norm the norms of the differences), the estimate, with the
   *  separation its space and time parts, and with a manufactured solution
   *  the exact error. */
  struct EstimateRow
  {
    std::string        name;
    double             value;
    double             d_fine;
    double             d_coarse;
    RichardsonEstimate estimate;
    double             space_part  = std::numeric_limits<double>::quiet_NaN();
    double             time_part   = std::numeric_limits<double>::quiet_NaN();
    double             exact_error = std::numeric_limits<double>::quiet_NaN();
    /** For worst_V_error: the time of the largest estimate. */
    double time = std::numeric_limits<double>::quiet_NaN();
  };

  /** A run with its error estimate: its summary, the table, and the wall
   *  time of all its runs. */
  struct EstimatedRun
  {
    RunSummary               summary;
    std::vector<EstimateRow> rows;
    double                   wall_time = 0;
  };

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
   *  is e_h + e_k with the known orders (error_estimate.cc); `field`: the
   *  d are norms of field differences, else signed differences. NaN where
   *  p and q are too close to tell the parts apart. */
  double two_order_error_estimate(const double     d_fine,
                                  const double     d_coarse,
                                  const TwoOrders &orders,
                                  const bool       field);


  /** A run's summary, and its displacement at T and at the times of a
   *  coarser time grid, interpolated onto another run's mesh. */
  struct RunAtTimes
  {
    RunSummary              summary;
    VectorType              displacement;
    std::vector<VectorType> history;
  };

  template <int dim>
  class ReferenceInterpolation;

  /** Runs `problem`, keeping its displacement at every `stride`-th step
   *  (none for 0) and at T, interpolated by `onto` (its own for null). */
  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride);

  /** The estimate of a field from its three differences, with two known
   *  orders where given (two_order_error_estimate) and else with the one
   *  the runs show (field_error_estimate). */
  RichardsonEstimate field_estimate(const double     d_fine,
                                    const double     d_coarse,
                                    const double     d_across,
                                    const TwoOrders *known);

  /** Runs the scene of `parameters` and its two coarse versions, and prints
   *  and writes the estimated errors (error_estimate.txt). A quantity with
   *  known orders in h and k is extrapolated with both (error_estimate.cc).
   */
  template <int dim>
  EstimatedRun run_with_error_estimate(const Parameters  &parameters,
                                       const KnownOrders &orders = {});
} // namespace Contact

#endif
