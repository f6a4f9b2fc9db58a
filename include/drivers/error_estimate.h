/**
 * 'Accuracy/Estimate error': a run that also says how accurate it is. The
 * scene runs as given, then with h and k doubled, quadrupled and (where the
 * mesh allows) multiplied by 8; from the differences of consecutive runs
 * each quantity's error at T is estimated by Richardson extrapolation with
 * the order the runs show, where they show one order consistently
 * (error_estimate.cc).
 */
#ifndef contact_error_estimate_h
#define contact_error_estimate_h

#include <core/contact_problem.h>
#include <core/mesh_plan.h>
#include <base/parameters.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace Contact
{
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
  /** The coarse runs take ceil(N / 2^l) steps; a ratio of their time step
   *  to the run's that differs from 2^l by more than this (relative) gets a
   *  warning. */
  constexpr double max_step_ratio_deviation = 0.05;
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
    double order = std::numeric_limits<double>::quiet_NaN();
    /** |d_0| / (2^order - 1); NaN where the runs give no estimate. */
    double error = std::numeric_limits<double>::quiet_NaN();
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
   *  max_order_drift; it then uses the smallest (error_estimate.cc). */
  RichardsonEstimate richardson_estimate(const std::vector<double> &differences,
                                         const bool signed_differences);

  /** One row of an estimate's table: a quantity's value (for the V-norm
   *  ||eps(u_h(T))||), the differences of consecutive runs h vs 2h, 2h vs
   *  4h (and 4h vs 8h; for the V-norm the norms of the differences), the
   *  estimate, with the separation its space and time parts, and with a
   *  manufactured solution the exact error. */
  struct EstimateRow
  {
    std::string         name;
    double              value;
    std::vector<double> differences;
    RichardsonEstimate  estimate;
    /** With the separation: the parts of the error that halving only h
     *  and only k remove (signed for a quantity), each with the order its
     *  own runs show, and whether the estimate is their sum. */
    double space_part  = std::numeric_limits<double>::quiet_NaN();
    double time_part   = std::numeric_limits<double>::quiet_NaN();
    double space_order = std::numeric_limits<double>::quiet_NaN();
    double time_order  = std::numeric_limits<double>::quiet_NaN();
    bool   from_parts  = false;
    double exact_error = std::numeric_limits<double>::quiet_NaN();
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
   *  (none for 0) and at T, interpolated by `onto` (its own for null). With
   *  a `log_file` the run's console output goes there instead (a sub-run of
   *  an estimate or a target, which the console shows in one line). */
  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride,
                      const std::string                 &log_file = "");

  /** The line that stands for a sub-run on the console: its unknowns and
   *  steps, and where its log is. */
  std::string sub_run_line(const RunSummary  &summary,
                           const std::string &log_file);

  /** Runs the scene of `parameters` and its coarse versions, and prints
   *  and writes the estimated errors (error_estimate.txt). A quantity with
   *  known orders in h and k is extrapolated with both (error_estimate.cc).
   *  On a mesh adapted by pilots (`plan`: the cycles that changed the
   *  scene's mesh) the coarse runs are on that mesh coarsened by one and
   *  two levels (MeshPlan::coarser()).
   */
  template <int dim>
  EstimatedRun run_with_error_estimate(const Parameters  &parameters,
                                       const KnownOrders &orders = {},
                                       const MeshPlan    &plan   = MeshPlan());
} // namespace Contact

#endif
