/* ---------------------------------------------------------------------
 * The error estimate of a run ('Accuracy/Estimate error').
 *
 * The scheme converges as O(h^p + k^q) (Corollary 5.3, (5.26): p = q = 1
 * for smooth solutions and linear elements; less where the solution is
 * singular, about 2/3 on the paper's scene). Running the scene also with h
 * and k doubled and quadrupled gives, for any quantity Q at T, the
 * differences d_fine = Q_h - Q_2h and d_coarse = Q_2h - Q_4h. If the
 * error behaves like C h^p on all three runs, d_coarse / d_fine = 2^p,
 * and the error of the finest run is
 *
 *   Q - Q_h = d_fine / (2^p - 1)               (Richardson extrapolation)
 *
 * with p measured, not assumed (for the V-norm allowing for error fields
 * that change shape, below). Where the differences change sign the runs
 * are not in that range and the estimate is |d_fine|, with a warning; a
 * quantity whose own order is below the V-norm's takes the V-norm's.
 * --------------------------------------------------------------------- */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <base/dimensions.h>
#include <base/scene_variant.h>
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <drivers/error_estimate.h>
#include <drivers/reference_interpolation.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace Contact
{
  namespace
  {
    // What an error estimate writes into its output directory: its table
    // and the coarse runs.
    const ResultFiles       estimate_table("error_estimate\\.txt");
    const ResultDirectories coarse_runs("coarse-(1|2|space|time)");
  } // namespace


  // @sect3{Richardson extrapolation with the observed order}

  RichardsonEstimate richardson_estimate(const double d_fine,
                                         const double d_coarse,
                                         const bool   signed_differences)
  {
    RichardsonEstimate estimate;
    estimate.order = std::numeric_limits<double>::quiet_NaN();
    estimate.error = std::abs(d_fine);
    if (!std::isfinite(d_fine) || !std::isfinite(d_coarse))
      {
        estimate.error   = std::numeric_limits<double>::quiet_NaN();
        estimate.warning = "not defined on every run";
        return estimate;
      }
    if (d_fine == 0)
      {
        // A quantity that takes few values (a share of nodes, a node's
        // position) can stay put between the finer runs and still have an
        // error; first order would make it half the coarser difference.
        estimate.error = std::abs(d_coarse) / 2;
        if (d_coarse != 0)
          estimate.warning = "the same on the two finer runs; the estimate "
                             "|2h vs 4h| / 2 assumes first order";
        return estimate;
      }
    if (signed_differences && d_fine * d_coarse < 0)
      {
        estimate.warning = "the differences between the runs change sign: "
                           "not in the asymptotic range";
        return estimate;
      }
    const double ratio = std::abs(d_coarse) / std::abs(d_fine);
    estimate.order     = std::log2(ratio);
    if (ratio <= 1)
      {
        estimate.warning = "the difference does not shrink from the coarser "
                           "to the finer pair of runs: not in the "
                           "asymptotic range";
        return estimate;
      }
    estimate.error = std::abs(d_fine) / (ratio - 1);
    // First order is what the scheme gives for smooth solutions; a corner
    // singularity lowers it to about 2/3, quadratic elements raise the
    // space part to 2. Orders far outside suggest that the three runs are
    // not yet in the range where one power of h describes the error.
    if (estimate.order < min_plausible_order ||
        estimate.order > max_plausible_order)
      estimate.warning =
        "observed order outside [" + number_text(min_plausible_order) + ", " +
        number_text(max_plausible_order) + "]: the estimate may be far off";
    return estimate;
  }


  // @sect3{The error of a field}
  //
  // Richardson's formula assumes that the error keeps its shape from one
  // run to the next, e_2h = 2^p e_h. The V-norm error of Lagrange elements
  // is dominated by the oscillation of the gradient inside each cell,
  // whose pattern moves with the mesh: the error fields of h and 2h are
  // partly orthogonal, and d_fine = ||e_2h - e_h|| is then larger than
  // (2^p - 1) ||e_h||. The model here: ||e_2h|| = r ||e_h||, ||e_4h|| =
  // r^2 ||e_h||, the errors of consecutive runs correlate with c and those
  // of h and 4h with c^2. Then, with E = ||e_h||,
  //
  //   d_fine^2   = E^2 (1 + r^2 - 2 r c),      d_coarse = r d_fine,
  //   (u_h - u_2h).(u_2h - u_4h) / (d_fine d_coarse)
  //              = (r^2 c - r - r c^2 + c) / (1 + r^2 - 2 r c) =: f(c),
  //
  // and the left side is known from the third difference, d_across, by
  // polarisation. f grows from -r/(1 + r^2) at c = 0 to 1 at c = 1; solving
  // f(c) for c in [0, 1] gives E = d_fine / sqrt(1 + r^2 - 2 r c), which is
  // Richardson's d_fine / (r - 1) for c = 1.
  RichardsonEstimate field_error_estimate(const double d_fine,
                                          const double d_coarse,
                                          const double d_across)
  {
    RichardsonEstimate estimate = richardson_estimate(d_fine, d_coarse, false);
    const double       r        = d_coarse / d_fine;
    if (!(d_fine > 0) || !(r > 1) || !std::isfinite(d_across))
      return estimate;
    const auto f = [r](const double c) {
      return (r * r * c - r - r * c * c + c) / (1 + r * r - 2 * r * c);
    };
    const double cosine =
      (d_across * d_across - d_fine * d_fine - d_coarse * d_coarse) /
      (2 * d_fine * d_coarse);
    double low = 0, high = 1;
    if (cosine >= f(high))
      low = high;
    else if (cosine <= f(low))
      high = low;
    for (unsigned int i = 0; i < 60 && high - low > 1e-14; ++i)
      {
        const double middle               = (low + high) / 2;
        (f(middle) < cosine ? low : high) = middle;
      }
    estimate.correlation = (low + high) / 2;
    estimate.error =
      d_fine / std::sqrt(1 + r * r - 2 * r * estimate.correlation);
    return estimate;
  }


  // @sect3{The error of a quantity at T}
  //
  // Displacements at a point and integrals such as the dissipation converge
  // at least as fast as the V-norm (for smooth solutions: second order in
  // space against first; near a singularity 2 lambda against lambda). An
  // order observed below the V-norm's, or differences that do not shrink,
  // come from coarse runs that are not yet asymptotic for that quantity:
  // then the V-norm's order, measured on the same runs, extrapolates
  // instead, provided it is itself plausible. Where the quantity's own
  // order is positive this gives the smaller of the two estimates: the
  // choice trusts the theory over the quantity's pre-asymptotic order
  // (bench/error_estimate.md compares both with a finer run).
  RichardsonEstimate scalar_error_estimate(const double d_fine,
                                           const double d_coarse,
                                           const double field_order)
  {
    RichardsonEstimate estimate  = richardson_estimate(d_fine, d_coarse, true);
    const bool         same_sign = d_fine * d_coarse > 0;
    if (!same_sign || !std::isfinite(field_order) ||
        field_order < min_plausible_order ||
        field_order > max_plausible_order ||
        (std::isfinite(estimate.order) && estimate.order >= field_order))
      return estimate;
    const double own_order = estimate.order;
    estimate.error         = std::abs(d_fine) / (std::pow(2., field_order) - 1);
    estimate.order         = field_order;
    estimate.warning =
      "its own order, " + number_text(own_order) + ", is below the V-norm's" +
      (own_order <= 0 ? " (its differences do not shrink)" : "") +
      ": extrapolated with the V-norm's order";
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
      return std::numeric_limits<double>::quiet_NaN();
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


  // @sect3{Runs and their histories}

  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride)
  {
    using NodesInCells =
      std::vector<typename ReferenceInterpolation<dim>::NodeInCell>;
    RunAtTimes                  result;
    std::optional<NodesInCells> located;
    const auto                  carry = [&](const ContactProblem<dim> &run) {
      if (!onto)
        return run.get_displacement();
      // The mesh exists once the run has started.
      if (!located)
        located = onto->locate(run);
      return (*onto)(*located, run, run.get_displacement());
    };
    // (A problem runs once: the observer is not called after run().)
    if (stride > 0)
      problem.add_postprocessor(std::make_unique<StepObserver<dim>>(
        [&](const ContactProblem<dim> &run) {
          if (run.get_step_number() % stride == 0)
            result.history.push_back(carry(run));
        }));
    result.summary      = problem.run();
    result.displacement = carry(problem);
    return result;
  }


  RichardsonEstimate field_estimate(const double     d_fine,
                                    const double     d_coarse,
                                    const double     d_across,
                                    const TwoOrders *known)
  {
    RichardsonEstimate estimate =
      field_error_estimate(d_fine, d_coarse, d_across);
    const double error =
      known ? two_order_error_estimate(d_fine, d_coarse, *known, true) :
              std::numeric_limits<double>::quiet_NaN();
    if (std::isfinite(error))
      estimate = {estimate.order,
                  error,
                  std::numeric_limits<double>::quiet_NaN(),
                  ""};
    return estimate;
  }


  namespace
  {
    // The error of a run over time: at each time that all three runs share,
    // the estimate from the three differences; the row is that of the
    // largest.
    template <int dim>
    EstimateRow worst_time_row(const ContactProblem<dim> &fine,
                               const RunAtTimes          &f,
                               const RunAtTimes          &m,
                               const RunAtTimes          &c,
                               const double               coarse_time_step,
                               const TwoOrders           *known)
    {
      const auto distance = [&](const VectorType &a, const VectorType &b) {
        return strain_distance(fine, a, b);
      };
      EstimateRow worst{worst_V_error, 0, 0, 0, {}};
      worst.estimate.error = -1;
      const std::size_t n_times =
        std::min({f.history.size(), m.history.size(), c.history.size()});
      for (std::size_t j = 0; j < n_times; ++j)
        {
          const double d_fine   = distance(f.history[j], m.history[j]);
          const double d_coarse = distance(m.history[j], c.history[j]);
          const RichardsonEstimate estimate = field_estimate(
            d_fine, d_coarse, distance(f.history[j], c.history[j]), known);
          if (estimate.error > worst.estimate.error)
            worst = {worst_V_error,
                     fine.strain_norm(f.history[j]),
                     d_fine,
                     d_coarse,
                     estimate,
                     std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::quiet_NaN(),
                     f.summary.max_errors.displacement_V,
                     (j + 1) * coarse_time_step};
        }
      return worst;
    }


    // @sect3{The coarse runs}

    // The scene with h times `space_factor` and k times `time_factor`, its
    // state at T and at the times of the run with 4k (every (4 /
    // time_factor)-th step where N is a multiple of 4) on the given run's
    // mesh.
    template <int dim>
    RunAtTimes run_coarse(const Parameters                  &base,
                          const unsigned int                 space_factor,
                          const unsigned int                 time_factor,
                          const std::string                 &name,
                          const ReferenceInterpolation<dim> &interpolate)
    {
      // factors 1, 2 or 4: 0, 1 or 2 levels coarser; T / ceil(N / factor)
      // steps, so that every run ends at T.
      ContactProblem<dim> coarse(
        parameters_of(base,
                      {-static_cast<int>(space_factor / 2),
                       (base.time.n_steps() + time_factor - 1) / time_factor,
                       base.geometry.fe_degree,
                       base.output.directory + "/" + name,
                       true}));
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << std::endl
                  << "Error estimate: the scene with h times " << space_factor
                  << " and k times " << time_factor << " (" << name << ")"
                  << std::endl;
      return run_onto(coarse,
                      &interpolate,
                      base.time.n_steps() % 4 == 0 ? 4 / time_factor : 0);
    }


    // @sect3{The estimates}

    // The part of the error that halving only h (or only k) removes: the
    // difference to the run with 2h (or 2k), scaled as the total is
    // scaled from its difference (the same order, for a field the same
    // correlation of consecutive errors). For a quantity it carries the
    // sign of its difference relative to the total's: parts of opposite
    // signs, or a part larger than the total, are space and time errors
    // that cancel. Where the part's order is known (a target's pilots), the
    // difference is extrapolated with it.
    double part_of_error(const EstimateRow &row,
                         const double       difference,
                         const bool         is_field,
                         const double       known_order)
    {
      if (std::isfinite(known_order))
        return difference / (std::pow(2., known_order) - 1);
      if (!std::isfinite(difference) || row.d_fine == 0)
        return std::numeric_limits<double>::quiet_NaN();
      const double ratio = difference / row.d_fine;
      return row.estimate.error * (is_field ? std::abs(ratio) : ratio);
    }

    // runs: the given one, 2h/2k, 4h/4k, and with the separation 2h/k and
    // h/2k.
    template <int dim>
    std::vector<EstimateRow> estimate_rows(const ContactProblem<dim>     &fine,
                                           const std::vector<RunAtTimes> &runs,
                                           const KnownOrders &orders)
    {
      const auto known = [&](const std::string &name) {
        const auto found = orders.find(name);
        return found == orders.end() ? nullptr : &found->second;
      };
      const auto distance = [&](const unsigned int a, const unsigned int b) {
        return strain_distance(fine,
                               runs[a].displacement,
                               runs[b].displacement);
      };
      // The orders of a row's two parts where they are known and tell the
      // parts apart (the estimate then uses them), else NaN.
      const auto two_orders = [&](const std::string &name) {
        const TwoOrders *orders_of_row = known(name);
        return orders_of_row &&
                   std::abs(orders_of_row->space - orders_of_row->time) >=
                     min_order_separation ?
                 orders_of_row :
                 nullptr;
      };
      const auto space_order = [&](const std::string &name) {
        const TwoOrders *orders_of_row = two_orders(name);
        return orders_of_row ? orders_of_row->space :
                               std::numeric_limits<double>::quiet_NaN();
      };
      const auto time_order = [&](const std::string &name) {
        const TwoOrders *orders_of_row = two_orders(name);
        return orders_of_row ? orders_of_row->time :
                               std::numeric_limits<double>::quiet_NaN();
      };
      const bool               separate = runs.size() == 5;
      std::vector<EstimateRow> rows;
      EstimateRow              v{V_norm,
                    runs[0].summary.displacement_V_norm,
                    distance(0, 1),
                    distance(1, 2),
                    {}};
      v.estimate =
        field_estimate(v.d_fine, v.d_coarse, distance(0, 2), known(v.name));
      v.exact_error = runs[0].summary.final_errors.displacement_V;
      if (separate)
        {
          v.space_part =
            part_of_error(v, distance(0, 3), true, space_order(v.name));
          v.time_part =
            part_of_error(v, distance(0, 4), true, time_order(v.name));
        }
      rows.push_back(v);
      if (!runs[2].history.empty())
        rows.push_back(worst_time_row(fine,
                                      runs[0],
                                      runs[1],
                                      runs[2],
                                      runs[2].summary.time_step,
                                      known(worst_V_error)));

      const auto value = [&](const unsigned int run, const unsigned int q) {
        return runs[run].summary.final_quantities[q].second;
      };
      for (unsigned int q = 0; q < runs[0].summary.final_quantities.size(); ++q)
        {
          EstimateRow row{runs[0].summary.final_quantities[q].first,
                          value(0, q),
                          value(0, q) - value(1, q),
                          value(1, q) - value(2, q),
                          {}};
          row.estimate =
            scalar_error_estimate(row.d_fine, row.d_coarse, v.estimate.order);
          if (const TwoOrders *orders_of_row = known(row.name))
            {
              const double error = two_order_error_estimate(row.d_fine,
                                                            row.d_coarse,
                                                            *orders_of_row,
                                                            false);
              if (std::isfinite(error))
                row.estimate = {row.estimate.order,
                                error,
                                std::numeric_limits<double>::quiet_NaN(),
                                ""};
            }
          if (separate)
            {
              row.space_part = part_of_error(row,
                                             value(0, q) - value(3, q),
                                             false,
                                             space_order(row.name));
              row.time_part  = part_of_error(row,
                                            value(0, q) - value(4, q),
                                            false,
                                            time_order(row.name));
            }
          rows.push_back(row);
        }
      return rows;
    }


    // @sect3{The report}

    void write_table(const std::vector<EstimateRow> &rows,
                     const bool                      with_exact,
                     const bool                      separate,
                     std::ostream                   &out)
    {
      TableHandler             table;
      std::vector<std::string> numbers = {"value",
                                          "h vs 2h",
                                          "2h vs 4h",
                                          "estimated error"};
      for (const EstimateRow &row : rows)
        {
          table.add_value("quantity", row.name);
          table.add_value("value", row.value);
          table.add_value("h vs 2h", row.d_fine);
          table.add_value("2h vs 4h", row.d_coarse);
          table.add_value("order", row.estimate.order);
          table.add_value("estimated error", row.estimate.error);
          if (separate)
            {
              table.add_value("space part", row.space_part);
              table.add_value("time part", row.time_part);
            }
          if (with_exact)
            table.add_value("exact error", row.exact_error);
        }
      if (separate)
        numbers.insert(numbers.end(), {"space part", "time part"});
      if (with_exact)
        numbers.push_back("exact error");
      for (const std::string &column : numbers)
        {
          table.set_scientific(column, true);
          table.set_precision(column, 3);
        }
      table.set_precision("order", 2);
      table.write_text(out, TableHandler::TextOutputFormat::org_mode_table);
    }

    std::string report(const Parameters               &parameters,
                       const std::vector<RunAtTimes>  &runs,
                       const std::vector<EstimateRow> &rows,
                       const KnownOrders              &orders)
    {
      const bool         exact    = parameters.verification.manufactured();
      const bool         separate = runs.size() == 5;
      std::ostringstream out;
      out << "Error estimate of this run at T = " << parameters.time.end_time
          << " (h = " << runs[0].summary.cell_size
          << ", k = " << runs[0].summary.time_step << "), from the runs with";
      for (unsigned int r = 1; r < runs.size(); ++r)
        out << (r == 1               ? " " :
                r + 1 == runs.size() ? " and " :
                                       ", ")
            << "h = " << runs[r].summary.cell_size
            << ", k = " << runs[r].summary.time_step;
      out << ": order = log2(|2h vs 4h| / |h vs 2h|), estimated error = "
          << "|h vs 2h| / (2^order - 1); the V-norm of u is ||eps(u(T))||, "
          << "its differences are the V-norms of the differences, and its "
          << "estimate allows for error fields that change shape from run "
          << "to run (correlation c below)"
          << (separate ? "; space and time part: what halving only h or "
                         "only k removes" :
                         "")
          << (exact ? "; exact error: against the manufactured solution" : "")
          << std::endl;
      for (const auto &[name, known] : orders)
        out << name << ": the target's pilots measured the orders "
            << known.space << " in h and " << known.time << " in k; "
            << (std::abs(known.space - known.time) >= min_order_separation ?
                  "estimated as the sum of a space and a time part with "
                  "these orders (the order column is what the three runs "
                  "show)." :
                  "too close to tell the parts apart: one order, as for "
                  "the other rows.")
            << std::endl;
      write_table(rows, exact, separate, out);
      for (const EstimateRow &row : rows)
        if (std::isfinite(row.time))
          out << row.name << ": the largest estimate over the times of the "
              << "run with 4h and 4k is at t = " << row.time
              << (exact ? "; its exact error: the largest over all steps" : "")
              << "." << std::endl;
      if (std::isfinite(rows[0].estimate.correlation))
        out << "V-norm of u: the error fields of consecutive runs correlate "
            << "with c = " << std::setprecision(2)
            << rows[0].estimate.correlation
            << " (c = 1 is Richardson's assumption; for order 1, c = 0, "
            << "orthogonal errors, gives 0.45 times its estimate)." << std::endl
            << std::setprecision(6);
      if (separate)
        for (const EstimateRow &row : rows)
          if (row.space_part * row.time_part < 0 ||
              std::abs(row.space_part) > row.estimate.error ||
              std::abs(row.time_part) > row.estimate.error)
            out << "Note: " << row.name << ": its space and time errors "
                << "partly cancel (parts of opposite sign, or a part larger "
                << "than the total)." << std::endl;
      if (exact)
        out << "Exact V-error at T of this run: "
            << runs[0].summary.final_errors.displacement_V
            << "; exact max V-error over the steps: "
            << runs[0].summary.max_errors.displacement_V << std::endl;
      // The time steps are T / ceil(N / 2^l): for N not a multiple of 4
      // their ratios differ a little from 2 and 4.
      for (unsigned int level = 1; level <= 2; ++level)
        {
          const double ratio =
            runs[level].summary.time_step / runs[0].summary.time_step;
          if (std::abs(ratio / (1u << level) - 1) > max_step_ratio_deviation)
            out << "Warning: the time step of the run with " << (1u << level)
                << "h is " << ratio << " times that of this run, not "
                << (1u << level) << " (choose N = T/k a multiple of 4)."
                << std::endl;
        }
      for (const EstimateRow &row : rows)
        if (!row.estimate.warning.empty())
          out << "Warning: " << row.name << ": " << row.estimate.warning << "."
              << std::endl;
      return out.str();
    }
  } // namespace


  // @sect3{run_with_error_estimate}

  template <int dim>
  EstimatedRun run_with_error_estimate(const Parameters  &parameters,
                                       const KnownOrders &orders)
  {
    Timer timer;
    // The run itself first; it stays, since the other runs' displacements
    // are interpolated onto its mesh.
    ContactProblem<dim>     fine(parameters);
    std::vector<RunAtTimes> runs = {
      run_onto<dim>(fine, nullptr, parameters.time.n_steps() % 4 == 0 ? 4 : 0)};
    const ReferenceInterpolation<dim> interpolate(fine);
    runs.push_back(run_coarse(parameters, 2, 2, "coarse-1", interpolate));
    runs.push_back(run_coarse(parameters, 4, 4, "coarse-2", interpolate));
    if (parameters.accuracy.separate_space_and_time)
      {
        runs.push_back(
          run_coarse(parameters, 2, 1, "coarse-space", interpolate));
        runs.push_back(
          run_coarse(parameters, 1, 2, "coarse-time", interpolate));
      }

    EstimatedRun result{runs[0].summary, estimate_rows(fine, runs, orders), 0};
    const std::string text = report(parameters, runs, result.rows, orders);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::cout << std::endl << text;
        std::ofstream file(parameters.output.directory + "/error_estimate.txt");
        file << text;
        AssertThrow(file.good(),
                    ExcMessage("Cannot write '" + parameters.output.directory +
                               "/error_estimate.txt'."));
      }
    result.wall_time = timer.wall_time();
    return result;
  }


#define INSTANTIATE(dim)                                                   \
  template RunAtTimes   run_onto<dim>(ContactProblem<dim> &,               \
                                    const ReferenceInterpolation<dim> *, \
                                    const unsigned int);                 \
  template EstimatedRun run_with_error_estimate<dim>(const Parameters &,   \
                                                     const KnownOrders &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
