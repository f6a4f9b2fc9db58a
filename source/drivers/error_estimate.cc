/* ---------------------------------------------------------------------
 * The error estimate of a run ('Accuracy/Estimate error').
 *
 * The scheme converges as O(h^p + k^q) (Corollary 5.3, (5.26): p = q = 1
 * for smooth solutions and linear elements; less where the solution is
 * singular, about 2/3 on the paper's scene). Running the scene also with h
 * and k doubled, quadrupled and multiplied by 8 gives, for any quantity Q
 * at T, the differences d_0 = Q_h - Q_2h, d_1 = Q_2h - Q_4h and d_2 =
 * Q_4h - Q_8h. If the error behaves like C h^p on all runs, d_{i+1} / d_i
 * = 2^p for every i, and the error of the finest run is
 *
 *   Q - Q_h = d_0 / (2^p - 1)                  (Richardson extrapolation)
 *
 * with p measured, not assumed. Each quantity is judged on its own
 * differences: an estimate is given only where they have one sign, shrink
 * at a plausible order, and the two orders agree (the run with 8h checks
 * the order that the three finer runs show); otherwise the row says why
 * there is none. Of two plausible orders the smaller is used, which gives
 * the larger estimate.
 * --------------------------------------------------------------------- */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <base/dimensions.h>
#include <base/geometry_base.h>
#include <base/quantity.h>
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <drivers/error_estimate.h>
#include <drivers/mesh_adaptation.h>
#include <drivers/reference_interpolation.h>
#include <drivers/scene_variant.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

namespace Contact
{
  namespace
  {
    // What an error estimate writes into its output directory: its table
    // and the coarse runs.
    const ResultFiles estimate_table("error_estimate\\.txt");
    const ResultDirectories
      coarse_runs("coarse-(1|2|3|space|time|space-1|space-2|time-1|time-2)");

    // "0.65" or "0.65 and 0.71".
    std::string orders_text(const std::vector<double> &orders)
    {
      std::ostringstream text;
      text << std::fixed << std::setprecision(2);
      for (unsigned int i = 0; i < orders.size(); ++i)
        text << (i == 0 ? "" : " and ") << orders[i];
      return text.str();
    }
  } // namespace


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
          std::numeric_limits<double>::quiet_NaN() :
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

  namespace
  {
    // The console output of a sub-run, kept while it runs and written to
    // its log file when it ends, however it ends (the directory exists by
    // then, since the run made it).
    class ConsoleToFile
    {
    public:
      explicit ConsoleToFile(const std::string &file)
        : log_file(file)
        , console(file.empty() ? nullptr : std::cout.rdbuf(captured.rdbuf()))
      {}
      ~ConsoleToFile()
      {
        if (!console)
          return;
        std::cout.rdbuf(console);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::ofstream(log_file) << captured.str();
      }
      ConsoleToFile(const ConsoleToFile &)            = delete;
      ConsoleToFile &operator=(const ConsoleToFile &) = delete;

    private:
      const std::string  log_file;
      std::ostringstream captured;
      std::streambuf    *console;
    };
  } // namespace


  std::string sub_run_line(const RunSummary  &summary,
                           const std::string &log_file)
  {
    std::ostringstream line;
    line << summary.n_dofs << " unknowns, " << summary.n_steps
         << " steps; log in " << log_file;
    return line.str();
  }


  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride,
                      const std::string                 &log_file)
  {
    const ConsoleToFile log(log_file);
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


  namespace
  {
    // The estimate of a row from its differences. Where a target's pilots
    // measured two orders that tell the parts apart, the two-order
    // estimate (two_order_error_estimate) may raise the row's own, never
    // lower it, and never replaces a verdict of the row's own runs.
    RichardsonEstimate estimate_of(const std::vector<double> &differences,
                                   const bool                 field,
                                   const TwoOrders           *known)
    {
      RichardsonEstimate estimate = richardson_estimate(differences, !field);
      // A scalar's one measured order is no evidence: on a mesh without the
      // run with 8h the time of the first slip shows the order 2.28, and its
      // estimate was 0.06 times its difference to an 8 times finer run
      // (4.38e-2, bench/error_estimate.md). A field's norm keeps its
      // estimate, which errs on the large side (above).
      if (!field && differences.size() < 3 && estimate.status.empty())
        {
          estimate.status = "order not checked";
          estimate.reason = "one measured order, " +
                            orders_text(estimate.measured_orders) +
                            ", which no run with 8h checks";
          estimate.error = std::numeric_limits<double>::quiet_NaN();
          estimate.order = std::numeric_limits<double>::quiet_NaN();
        }
      if (!known || !estimate.status.empty())
        return estimate;
      const double error =
        two_order_error_estimate(differences[0], differences[1], *known, field);
      if (error > estimate.error)
        {
          estimate.error = error;
          estimate.order = std::numeric_limits<double>::quiet_NaN();
          estimate.reason =
            "the sum of a space and a time part with the pilots' orders, "
            "larger than the estimate of its own order";
        }
      return estimate;
    }


    // The error of a run over time: at each time that all runs share, the
    // estimate from the differences of consecutive runs; the row is that
    // of the largest estimate, and has none where a time has none.
    template <int dim>
    EstimateRow worst_time_row(const ContactProblem<dim>     &fine,
                               const std::vector<RunAtTimes> &runs,
                               const double                   coarse_time_step,
                               const TwoOrders               *known)
    {
      EstimateRow worst{worst_V_error, 0, {}, {}};
      double      largest = -1;
      std::string without_estimate;
      std::size_t n_times = runs[0].history.size();
      for (const RunAtTimes &run : runs)
        n_times = std::min(n_times, run.history.size());
      for (std::size_t j = 0; j < n_times; ++j)
        {
          std::vector<double> differences;
          for (unsigned int r = 0; r + 1 < runs.size(); ++r)
            differences.push_back(strain_distance(fine,
                                                  runs[r].history[j],
                                                  runs[r + 1].history[j]));
          const RichardsonEstimate estimate =
            estimate_of(differences, true, known);
          if (!estimate.status.empty() && without_estimate.empty())
            without_estimate =
              "at t = " + number_text((j + 1) * coarse_time_step) + ": " +
              estimate.reason;
          const double size =
            std::isfinite(estimate.error) ? estimate.error : differences[0];
          if (size > largest)
            {
              largest           = size;
              worst             = {worst_V_error,
                                   fine.strain_norm(runs[0].history[j]),
                                   differences,
                                   estimate};
              worst.exact_error = runs[0].summary.max_errors.displacement_V;
              worst.time        = (j + 1) * coarse_time_step;
            }
        }
      // One time without an estimate leaves the largest unknown.
      if (!without_estimate.empty())
        {
          worst.estimate.error  = std::numeric_limits<double>::quiet_NaN();
          worst.estimate.order  = std::numeric_limits<double>::quiet_NaN();
          worst.estimate.status = "not asymptotic";
          worst.estimate.reason = without_estimate;
        }
      return worst;
    }


    // @sect3{The coarse runs}

    // Whether the mesh allows the run with 8h, which checks the order the
    // finer runs show (the runs with 2h and 4h are checked by
    // Parameters::check_error_estimate()).
    bool has_check_run(const Parameters &parameters)
    {
      return create_geometry(parameters)->coarsening_obstacle(3).empty();
    }

    // The scene with h and k times the factors, its state at T and, for
    // equal factors up to `history_factor` (0: none), at the times of the
    // run with that factor, on the given run's mesh.
    template <int dim>
    RunAtTimes run_coarse(const Parameters                  &base,
                          const MeshPlan                    &plan,
                          const unsigned int                 space_factor,
                          const unsigned int                 time_factor,
                          const unsigned int                 history_factor,
                          const std::string                 &name,
                          const ReferenceInterpolation<dim> &interpolate)
    {
      int halvings = 0;
      while ((1u << -halvings) < space_factor)
        --halvings;
      // T / ceil(N / factor) steps, so that every run ends at T.
      const Parameters parameters =
        parameters_of(base,
                      {halvings,
                       (base.time.n_steps() + time_factor - 1) / time_factor,
                       base.geometry.fe_degree,
                       base.output.directory + "/" + name,
                       true});
      ContactProblem<dim> coarse(parameters);
      coarse.adapt_mesh(plan.coarser(-halvings));
      if (parameters.mesh_adaptation.interval > 0)
        adapt_during_run(coarse, parameters.mesh_adaptation);
      const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (root)
        std::cout << "Error estimate: the scene with h times " << space_factor
                  << " and k times " << time_factor << " (" << name
                  << "): " << std::flush;
      const std::string log_file =
        base.output.directory + "/" + name + "/console.log";
      RunAtTimes run =
        run_onto(coarse,
                 &interpolate,
                 // Only the sequence's runs keep histories.
                 space_factor == time_factor && time_factor <= history_factor ?
                   history_factor / time_factor :
                   0,
                 log_file);
      if (root)
        std::cout << sub_run_line(run.summary, log_file) << std::endl;
      return run;
    }


    // @sect3{The estimates}

    // The runs of an estimate: the given one and those with 2h, 4h (and
    // 8h) in the sequence; with the separation, those with 2h and 4h at k
    // (space) and with 2k and 4k at h (time).
    struct EstimateRuns
    {
      std::vector<RunAtTimes> sequence;
      std::vector<RunAtTimes> space;
      std::vector<RunAtTimes> time;
    };

    // The part of the error that halving only h (or only k) removes, from
    // the given run and the two runs of that direction, with the order
    // they show (or the pilots' order where a target measured it), and
    // for a quantity with the sign of its first difference. Where the
    // errors in h and k have different orders (quadratic elements: h^2
    // and k) the one order of the sequence misreads their sum; the parts
    // extrapolate each with its own.
    template <typename Difference>
    std::pair<double, double>
    part_of_error(const Difference              &difference,
                  const RunAtTimes              &run,
                  const std::vector<RunAtTimes> &chain,
                  const bool                     field,
                  const double                   known_order)
    {
      const double d_0 = difference(run, chain[0]);
      if (std::isfinite(known_order))
        return {d_0 / (std::pow(2., known_order) - 1), known_order};
      const RichardsonEstimate part =
        richardson_estimate({d_0, difference(chain[0], chain[1])}, !field);
      return {d_0 < 0 ? -part.error : part.error, part.order};
    }

    // With the separation, a row's estimate is the larger of the
    // sequence's and |space part| + |time part| (the sum where the parts
    // may add, which is what the sequence cannot tell).
    template <typename Difference>
    void add_parts(EstimateRow        &row,
                   const EstimateRuns &runs,
                   const Difference   &difference,
                   const bool          field,
                   const TwoOrders    *known)
    {
      if (runs.space.empty())
        return;
      const bool apart =
        known && std::abs(known->space - known->time) >= min_order_separation;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      std::tie(row.space_part, row.space_order) =
        part_of_error(difference,
                      runs.sequence[0],
                      runs.space,
                      field,
                      apart ? known->space : nan);
      std::tie(row.time_part, row.time_order) =
        part_of_error(difference,
                      runs.sequence[0],
                      runs.time,
                      field,
                      apart ? known->time : nan);
      // The parts raise an estimate of the sequence, never replace its
      // verdict: each rests on one order that no run checks.
      const double sum = std::abs(row.space_part) + std::abs(row.time_part);
      if (row.estimate.status.empty() && std::isfinite(sum) &&
          sum > row.estimate.error)
        {
          row.estimate.error = sum;
          row.estimate.order = nan;
          row.from_parts     = true;
        }
    }

    // A quantity's value on a run, found by its name: a quantity that a
    // coarse run does not have (e.g. one of the free nodes on Gamma_3 where
    // the coarsest mesh has none) is NaN there.
    double value_of(const RunSummary &summary, const std::string &name)
    {
      for (const auto &[quantity, value] : summary.final_quantities)
        if (quantity == name)
          return value;
      return std::numeric_limits<double>::quiet_NaN();
    }

    template <int dim>
    std::vector<EstimateRow> estimate_rows(const ContactProblem<dim> &fine,
                                           const EstimateRuns        &runs,
                                           const KnownOrders         &orders)
    {
      const auto known = [&](const std::string &name) {
        const auto found = orders.find(name);
        return found == orders.end() ? nullptr : &found->second;
      };
      const std::vector<RunAtTimes> &sequence = runs.sequence;

      std::vector<EstimateRow> rows;
      {
        const auto distance = [&](const RunAtTimes &a, const RunAtTimes &b) {
          return strain_distance(fine, a.displacement, b.displacement);
        };
        EstimateRow v{V_norm, sequence[0].summary.displacement_V_norm, {}, {}};
        for (unsigned int r = 0; r + 1 < sequence.size(); ++r)
          v.differences.push_back(distance(sequence[r], sequence[r + 1]));
        v.estimate    = estimate_of(v.differences, true, known(v.name));
        v.exact_error = sequence[0].summary.final_errors.displacement_V;
        add_parts(v, runs, distance, true, known(v.name));
        rows.push_back(v);
      }
      // The runs that kept their states at shared times: all of them, or
      // without the one with 8h where N is a multiple of 4 but not of 8.
      std::vector<RunAtTimes> with_history;
      for (const RunAtTimes &run : sequence)
        if (!run.history.empty())
          with_history.push_back(run);
      if (with_history.size() >= 3)
        {
          EstimateRow worst =
            worst_time_row(fine,
                           with_history,
                           with_history.back().summary.time_step,
                           known(worst_V_error));
          // T is one of the times, and there all runs are compared: without
          // the run with 8h the largest over time takes the row at T (its
          // differences with the sequence's order, never the separation's
          // parts, which split the rows at T only) where that has no
          // estimate or a larger one.
          const EstimateRow       &at_T = rows.front();
          const RichardsonEstimate at_T_own =
            estimate_of(at_T.differences, true, known(worst_V_error));
          if (with_history.size() < sequence.size() &&
              (!at_T_own.status.empty() ||
               (worst.estimate.status.empty() &&
                at_T_own.error > worst.estimate.error)))
            {
              worst = {worst_V_error,
                       at_T.value,
                       at_T.differences,
                       at_T_own,
                       std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::quiet_NaN(),
                       false,
                       worst.exact_error,
                       sequence[0].summary.n_steps *
                         sequence[0].summary.time_step};
              if (!worst.estimate.reason.empty())
                worst.estimate.reason = "at T: " + worst.estimate.reason;
            }
          rows.push_back(worst);
        }

      for (const auto &[name, value] : sequence[0].summary.final_quantities)
        {
          EstimateRow row{name, value, {}, {}};
          for (unsigned int r = 0; r + 1 < sequence.size(); ++r)
            row.differences.push_back(value_of(sequence[r].summary, name) -
                                      value_of(sequence[r + 1].summary, name));
          row.estimate = estimate_of(row.differences, false, known(name));
          add_parts(
            row,
            runs,
            [&](const RunAtTimes &a, const RunAtTimes &b) {
              return value_of(a.summary, name) - value_of(b.summary, name);
            },
            false,
            known(name));
          rows.push_back(row);
        }
      return rows;
    }


    // @sect3{The report}

    // A number of the table, or "-" where there is none.
    std::string table_text(const double value, const bool scientific)
    {
      if (std::isnan(value))
        return "-";
      std::ostringstream text;
      if (scientific)
        text << std::scientific << std::setprecision(3) << value;
      else
        text << std::fixed << std::setprecision(2) << value;
      return text.str();
    }

    std::string scientific(const double value)
    {
      return table_text(value, true);
    }

    std::string fixed(const double value)
    {
      return table_text(value, false);
    }

    void write_table(const std::vector<EstimateRow> &rows,
                     const unsigned int              dim,
                     const unsigned int              n_differences,
                     const bool                      with_exact,
                     const bool                      separate,
                     std::ostream                   &out)
    {
      const std::array<std::string, 3> difference_names = {
        {"h vs 2h", "2h vs 4h", "4h vs 8h"}};
      TableHandler table;
      for (const EstimateRow &row : rows)
        {
          table.add_value("quantity", row.name);
          table.add_value("unit", Quantity::parse(row.name).unit(dim));
          table.add_value("value", scientific(row.value));
          // The largest over time may come without the run with 8h.
          for (unsigned int i = 0; i < n_differences; ++i)
            table.add_value(difference_names[i],
                            i < row.differences.size() ?
                              scientific(row.differences[i]) :
                              std::string("-"));
          std::string measured;
          for (const double order : row.estimate.measured_orders)
            measured += (measured.empty() ? "" : ", ") + fixed(order);
          table.add_value("orders measured", measured);
          table.add_value("order used",
                          row.from_parts ? "h " + fixed(row.space_order) +
                                             ", k " + fixed(row.time_order) :
                                           fixed(row.estimate.order));
          table.add_value("estimated error", scientific(row.estimate.error));
          table.add_value("relative",
                          row.value == 0 ? std::string("-") :
                                           scientific(row.estimate.error /
                                                      std::abs(row.value)));
          if (separate)
            {
              table.add_value("space part", scientific(row.space_part));
              table.add_value("time part", scientific(row.time_part));
            }
          if (with_exact)
            table.add_value("exact error", scientific(row.exact_error));
          table.add_value("status",
                          row.estimate.status.empty() ?
                            std::string("estimated") :
                            row.estimate.status);
        }
      table.write_text(out, TableHandler::TextOutputFormat::org_mode_table);
    }

    std::string report(const Parameters               &parameters,
                       const EstimateRuns             &runs,
                       const std::vector<EstimateRow> &rows,
                       const KnownOrders              &orders)
    {
      const bool exact    = parameters.verification.manufactured();
      const bool separate = !runs.space.empty();
      const std::vector<RunAtTimes> &sequence = runs.sequence;
      std::ostringstream             out;
      out << "Error estimate of this run at T = " << parameters.time.end_time
          << " (h = " << sequence[0].summary.cell_size
          << ", k = " << sequence[0].summary.time_step
          << "), from the runs with";
      std::vector<const RunAtTimes *> others;
      for (unsigned int r = 1; r < sequence.size(); ++r)
        others.push_back(&sequence[r]);
      for (const auto *chain : {&runs.space, &runs.time})
        for (const RunAtTimes &run : *chain)
          others.push_back(&run);
      for (unsigned int r = 0; r < others.size(); ++r)
        out << (r == 0                 ? " " :
                r + 1 == others.size() ? " and " :
                                         ", ")
            << "h = " << others[r]->summary.cell_size
            << ", k = " << others[r]->summary.time_step;
      out << ". Orders measured: log2(|2h vs 4h| / |h vs 2h|)"
          << (sequence.size() == 4 ? " and log2(|4h vs 8h| / |2h vs 4h|)" : "")
          << "; a row is estimated where the differences have one sign and "
          << "shrink at orders in [" << number_text(min_plausible_order) << ", "
          << number_text(max_plausible_order) << "]"
          << (sequence.size() == 4 ?
                " that agree within " + number_text(max_order_drift) :
                std::string())
          << ", as |h vs 2h| / (2^order - 1) with the smallest order; the "
          << "V-norm of u is ||eps(u(T))||, its differences are the V-norms "
          << "of the differences"
          << (separate ?
                "; space and time part: what halving only h or only k "
                "removes, each extrapolated with the order of its own runs "
                "(2h and 4h at k; 2k and 4k at h), and a row's estimate is "
                "|space part| + |time part| where that is larger" :
                "")
          << (exact ? "; exact error: against the manufactured solution" : "")
          << "." << std::endl;
      if (sequence.size() < 4)
        out << "The order is not checked by a run with 8h and 8k: the mesh "
            << "does not allow it ("
            << create_geometry(parameters)->coarsening_obstacle(3)
            << "); the V-norm's estimate rests on one measured order, and "
            << "the other quantities get none." << std::endl;
      if (!separate && orders.empty() && parameters.geometry.fe_degree >= 2)
        out << "Note: with degree " << parameters.geometry.fe_degree
            << " elements the space error may fall faster than the time "
            << "error (h^2 against k), and one order cannot describe their "
            << "sum: where both matter these estimates are too small (0.64 "
            << "of the exact V-error on the manufactured solution at h = k = "
            << "1/16). '" << Entry::separate_space_and_time
            << "' = true estimates the two parts with their own orders."
            << std::endl;
      // What the pilots' orders do (estimate_of, add_parts): raise an
      // estimate that the row's own runs give, never make one.
      for (const auto &[name, known] : orders)
        out << name << ": the target's pilots measured the orders "
            << known.space << " in h and " << known.time << " in k; "
            << (std::abs(known.space - known.time) >= min_order_separation ?
                  "where the row's own runs give an estimate, it is raised "
                  "to the sum of a space and a time part with these orders "
                  "if that is larger." :
                  std::string("too close to tell the parts apart: not "
                              "used") +
                    (separate ? "; the space and the time part take the "
                                "orders of their own runs." :
                                "; one order, as for the other rows."))
            << std::endl;
      write_table(
        rows, parameters.dimension, sequence.size() - 1, exact, separate, out);
      const unsigned int coarsest      = 1u << (sequence.size() - 1);
      bool               has_worst_row = false;
      for (const EstimateRow &row : rows)
        if (std::isfinite(row.time))
          {
            has_worst_row              = true;
            const unsigned int n_steps = parameters.time.n_steps();
            const unsigned int factor  = n_steps % coarsest == 0 ? coarsest : 4;
            out << row.name << ": the largest over the times of the run "
                << "with " << factor << "h and " << factor
                << "k is at t = " << row.time
                << (exact ? "; its exact error: the largest over all steps" :
                            "")
                << "." << std::endl;
            if (factor < coarsest)
              out << "Note: " << row.name << ": without the run with "
                  << coarsest << "h, which shares the times of the others "
                  << "only for T/k a multiple of " << coarsest << " (here "
                  << n_steps << " steps): the estimate rests on one measured "
                  << "order at the other times." << std::endl;
          }
      if (has_worst_row && separate && parameters.geometry.fe_degree >= 2)
        out << "Note: " << worst_V_error << ": from the sequence's one order "
            << "(the separation splits the rows at T only); with degree "
            << parameters.geometry.fe_degree << " it may be too small."
            << std::endl;
      if (!has_worst_row && parameters.mesh_adaptation.interval > 0)
        out << worst_V_error << ": not estimated: the mesh changes during "
            << "the run, so its earlier states have no one mesh to be "
            << "compared on." << std::endl;
      else if (!has_worst_row)
        out << worst_V_error << ": not estimated: it needs T/k a multiple of "
            << std::min(coarsest, 4u) << " (here " << parameters.time.n_steps()
            << " steps), so that all runs share their times." << std::endl;
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
            << sequence[0].summary.final_errors.displacement_V
            << "; exact max V-error over the steps: "
            << sequence[0].summary.max_errors.displacement_V << std::endl;
      // The time steps are T / ceil(N / 2^l): for N not a multiple of 2^l
      // their ratios differ a little from 2^l.
      for (unsigned int level = 1; level < sequence.size(); ++level)
        {
          const double ratio =
            sequence[level].summary.time_step / sequence[0].summary.time_step;
          if (std::abs(ratio / (1u << level) - 1) > max_step_ratio_deviation)
            out << "Warning: the time step of the run with " << (1u << level)
                << "h is " << ratio << " times that of this run, not "
                << (1u << level) << " (choose N = T/k a multiple of "
                << coarsest << ")." << std::endl;
        }
      // A run adapted during itself: its coarse runs adapt the same way
      // towards 1/2^dim of the unknowns per level, which a mesh too coarse
      // to refine (a share of a few cells rounds to none) does not reach.
      if (parameters.mesh_adaptation.interval > 0)
        {
          out << "The runs adapt their meshes during the run, from the h "
              << "above";
          if (parameters.mesh_adaptation.target_unknowns > 0)
            out << " towards 1/" << (1u << parameters.dimension)
                << " of the unknowns per level";
          else
            out << " by the same fractions";
          out << " (unknowns at T:";
          for (const RunAtTimes &run : sequence)
            out << " " << run.summary.n_dofs;
          out << "); the differences are taken on this run's last mesh."
              << std::endl;
          for (unsigned int level = 1; level < sequence.size(); ++level)
            {
              const double ratio = double(sequence[level - 1].summary.n_dofs) /
                                   sequence[level].summary.n_dofs;
              const double nominal = 1u << parameters.dimension;
              if (ratio > 2 * nominal || ratio < nominal / 2)
                out << "Warning: the run with " << (1u << level) << "h has "
                    << number_text(ratio) << " times fewer "
                    << "unknowns than the run before it, not about "
                    << number_text(nominal)
                    << ": its mesh did not adapt as this run's "
                    << "did, and the estimate, which assumes it did, may be "
                    << "far off (start from a smaller '" << Entry::cell_size
                    << "')." << std::endl;
            }
        }
      // A row without an estimate gets no bound either: the bound that
      // assumes the finer runs to converge at order 0.5 or more lies below
      // the difference to an 8 or 16 times finer run in 17 of the 64 rows
      // of bench/error_estimate.md that are not asymptotic.
      for (const EstimateRow &row : rows)
        if (!row.estimate.reason.empty())
          out << (row.estimate.status.empty() ? "Note: " : "No estimate: ")
              << row.name << ": " << row.estimate.reason << "." << std::endl;
      // The slip zone's start is a node's coordinate and the slipping share
      // a count of nodes: they move in steps of a node, and an error below
      // that step is not resolved.
      for (const EstimateRow &row : rows)
        if (row.estimate.status.empty() &&
            (row.name == Quantity{Quantity::Kind::slip_zone_start}.name() ||
             row.name == Quantity{Quantity::Kind::slipping_share}.name()))
          out << "Note: " << row.name << ": it moves in steps of one node "
              << "of Gamma_3; an estimate near one step says only that the "
              << "error is at most about that step." << std::endl;
      return out.str();
    }
  } // namespace


  // @sect3{run_with_error_estimate}

  template <int dim>
  EstimatedRun run_with_error_estimate(const Parameters  &parameters,
                                       const KnownOrders &orders,
                                       const MeshPlan    &plan)
  {
    Timer timer;
    // The run itself first; it stays, since the other runs' displacements
    // are interpolated onto its mesh.
    const unsigned int coarsest = has_check_run(parameters) ? 8 : 4;
    // The largest V-error over time compares the runs at the times of the
    // coarsest run with a history: that of all runs where N = T/k is a
    // multiple of `coarsest`, else that of the run with 4h and 4k where N
    // is a multiple of 4.
    // A run whose mesh changes during it has no one mesh to compare its
    // earlier states on: only its state at T is compared.
    const unsigned int  n_steps      = parameters.time.n_steps();
    const bool          mesh_changes = parameters.mesh_adaptation.interval > 0;
    const unsigned int  history_factor = mesh_changes            ? 0 :
                                         n_steps % coarsest == 0 ? coarsest :
                                         n_steps % 4 == 0        ? 4 :
                                                                   0;
    ContactProblem<dim> fine(parameters);
    fine.adapt_mesh(plan);
    if (mesh_changes)
      adapt_during_run(fine, parameters.mesh_adaptation);
    EstimateRuns runs;
    runs.sequence.push_back(run_onto<dim>(fine, nullptr, history_factor));
    const ReferenceInterpolation<dim> interpolate(fine);
    for (unsigned int factor = 2; factor <= coarsest; factor *= 2)
      runs.sequence.push_back(
        run_coarse(parameters,
                   plan,
                   factor,
                   factor,
                   history_factor,
                   "coarse-" + std::to_string(runs.sequence.size()),
                   interpolate));
    if (parameters.accuracy.separate_space_and_time)
      for (unsigned int factor = 2; factor <= 4; factor *= 2)
        {
          const std::string level = std::to_string(factor / 2);
          runs.space.push_back(run_coarse(parameters,
                                          plan,
                                          factor,
                                          1,
                                          history_factor,
                                          "coarse-space-" + level,
                                          interpolate));
          runs.time.push_back(run_coarse(parameters,
                                         plan,
                                         1,
                                         factor,
                                         history_factor,
                                         "coarse-time-" + level,
                                         interpolate));
        }

    EstimatedRun      result{runs.sequence[0].summary,
                        estimate_rows(fine, runs, orders),
                        0};
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
                                    const unsigned int,                  \
                                    const std::string &);                \
  template EstimatedRun run_with_error_estimate<dim>(const Parameters &,   \
                                                     const KnownOrders &,  \
                                                     const MeshPlan &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
