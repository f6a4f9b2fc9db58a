/* ---------------------------------------------------------------------
 * The error estimate of a run ('Accuracy/Estimate error').
 *
 * The scheme converges as O(h^p + k^q) (Corollary 5.3, (5.26): p = q = 1
 * for smooth solutions and linear elements; less where the solution is
 * singular, about 2/3 on the paper's scene). Running the scene also with h
 * and k doubled, quadrupled and multiplied by 8 gives, for any quantity Q
 * at T, the differences of consecutive runs, from which Richardson
 * extrapolation (richardson.cc) estimates the error of the finest run
 * with the order p measured, not assumed. Each quantity is judged on its own
 * differences: an estimate is given only where they have one sign, shrink
 * at a plausible order, and the two orders agree (the run with 8h checks
 * the order that the three finer runs show); otherwise the row says why
 * there is none. Of two plausible orders the smaller is used, which gives
 * the larger estimate. The formulas are in richardson.cc, the report in
 * error_estimate_report.cc.
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>

#include <base/dimensions.h>
#include <core/geometry_base.h>
#include <core/quantity.h>
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <parts/studies/error_estimate.h>
#include <parts/studies/reference_interpolation.h>
#include <parts/studies/scene_variant.h>
#include <parts/studies/study_parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
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


    // @sect3{The estimate of a row}

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
      // estimate, which errs on the large side (richardson.cc).
      if (!field && differences.size() < 3 && estimate.status.empty())
        {
          estimate.status = "order not checked";
          estimate.reason = "one measured order, " +
                            orders_text(estimate.measured_orders) +
                            ", which no run with 8h checks";
          estimate.error = nan;
          estimate.order = nan;
        }
      if (!known || !estimate.status.empty())
        return estimate;
      const double error =
        two_order_error_estimate(differences[0], differences[1], *known, field);
      if (error > estimate.error)
        {
          estimate.error = error;
          estimate.order = nan;
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
          worst.estimate.error  = nan;
          worst.estimate.order  = nan;
          worst.estimate.status = "not asymptotic";
          worst.estimate.reason = without_estimate;
        }
      return worst;
    }


    // @sect3{The coarse runs}

    // The coarse runs of one estimate: what they share (the scene, the mesh
    // plan of the run, how far the histories go, the interpolation onto the
    // run's mesh, and what equips each run).
    template <int dim>
    struct CoarseRuns
    {
      const Parameters                  &base;
      const MeshPlan                    &plan;
      const unsigned int                 history_factor;
      const ReferenceInterpolation<dim> &interpolate;
      const Equipment<dim>              &equip;

      // The scene with h and k times the factors, its state at T and, for
      // equal factors up to `history_factor` (0: none), at the times of
      // the run with that factor, on the given run's mesh.
      RunAtTimes run(const unsigned int space_factor,
                     const unsigned int time_factor,
                     const std::string &name) const
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
        equip(coarse, parameters);
        study_console() << "Error estimate: the scene with h times "
                        << space_factor << " and k times " << time_factor
                        << " (" << name << "): " << std::flush;
        const std::string log_file =
          base.output.directory + "/" + name + "/console.log";
        RunAtTimes run = run_onto(coarse,
                                  &interpolate,
                                  // Only the sequence's runs keep histories.
                                  space_factor == time_factor &&
                                      time_factor <= history_factor ?
                                    history_factor / time_factor :
                                    0,
                                  log_file);
        study_console() << sub_run_line(run.summary, log_file) << std::endl;
        return run;
      }
    };


    // @sect3{The estimates}

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

    // A row at T from the `difference`s of consecutive runs. With the
    // separation, its estimate is the larger of the sequence's and
    // |space part| + |time part| (the sum where the parts may add, which is
    // what the sequence cannot tell).
    template <typename Difference>
    EstimateRow row_at_T(const std::string  &name,
                         const double        value,
                         const EstimateRuns &runs,
                         const Difference   &difference,
                         const bool          field,
                         const TwoOrders    *known)
    {
      const std::vector<RunAtTimes> &sequence = runs.sequence;
      EstimateRow                    row{name, value, {}, {}};
      for (unsigned int r = 0; r + 1 < sequence.size(); ++r)
        row.differences.push_back(difference(sequence[r], sequence[r + 1]));
      row.estimate = estimate_of(row.differences, field, known);
      if (runs.space.empty())
        return row;
      const bool apart =
        known && std::abs(known->space - known->time) >= min_order_separation;
      std::tie(row.space_part, row.space_order) = part_of_error(
        difference, sequence[0], runs.space, field, apart ? known->space : nan);
      std::tie(row.time_part, row.time_order) = part_of_error(
        difference, sequence[0], runs.time, field, apart ? known->time : nan);
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
      return row;
    }

    // The largest V-error over the times that the runs with histories
    // share, where at least three runs kept them; `at_T` is the V-norm's
    // row.
    template <int dim>
    std::optional<EstimateRow> worst_row(const ContactProblem<dim> &fine,
                                         const EstimateRuns        &runs,
                                         const EstimateRow         &at_T,
                                         const TwoOrders           *known)
    {
      const std::vector<RunAtTimes> &sequence = runs.sequence;
      // The runs that kept their states at shared times: all of them, or
      // without the one with 8h where N is a multiple of 4 but not of 8.
      std::vector<RunAtTimes> with_history;
      for (const RunAtTimes &run : sequence)
        if (!run.history.empty())
          with_history.push_back(run);
      if (with_history.size() < 3)
        return std::nullopt;
      EstimateRow worst = worst_time_row(fine,
                                         with_history,
                                         with_history.back().summary.time_step,
                                         known);
      // T is one of the times, and there all runs are compared: without
      // the run with 8h the largest over time takes the row at T (its
      // differences with the sequence's order, never the separation's
      // parts, which split the rows at T only) where that has no estimate
      // or a larger one.
      const RichardsonEstimate at_T_own =
        estimate_of(at_T.differences, true, known);
      if (with_history.size() < sequence.size() &&
          (!at_T_own.status.empty() || (worst.estimate.status.empty() &&
                                        at_T_own.error > worst.estimate.error)))
        {
          const double exact_error = worst.exact_error;
          worst = {worst_V_error, at_T.value, at_T.differences, at_T_own};
          worst.exact_error = exact_error;
          worst.time =
            sequence[0].summary.n_steps * sequence[0].summary.time_step;
          if (!worst.estimate.reason.empty())
            worst.estimate.reason = "at T: " + worst.estimate.reason;
        }
      return worst;
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
      // The V-norm at T: its differences are the norms of the differences
      // of the displacements, on the run's mesh.
      const RunSummary        &run = runs.sequence[0].summary;
      std::vector<EstimateRow> rows{row_at_T(
        V_norm,
        run.displacement_V_norm,
        runs,
        [&](const RunAtTimes &a, const RunAtTimes &b) {
          return strain_distance(fine, a.displacement, b.displacement);
        },
        true,
        known(V_norm))};
      rows[0].exact_error = run.final_errors.displacement_V;
      if (const std::optional<EstimateRow> worst =
            worst_row(fine, runs, rows.front(), known(worst_V_error)))
        rows.push_back(*worst);
      // A quantity at T, from its values on the runs.
      for (const auto &quantity : run.final_quantities)
        rows.push_back(row_at_T(
          quantity.first,
          quantity.second,
          runs,
          [&](const RunAtTimes &a, const RunAtTimes &b) {
            return quantity_of(a.summary, quantity.first) -
                   quantity_of(b.summary, quantity.first);
          },
          false,
          known(quantity.first)));
      return rows;
    }
  } // namespace


  // @sect3{The study}

  template <int dim>
  ErrorEstimate<dim>::ErrorEstimate(const Equipment<dim> &equipment)
    : equip(equipment)
  {}


  template <int dim>
  RunResult ErrorEstimate<dim>::run(const Parameters      &parameters,
                                    const StudyInput<dim> &input)
  {
    // The run with 8h, where the mesh allows it, checks the order that the
    // finer runs show.
    const unsigned int coarsest =
      create_geometry(parameters)->coarsening_obstacle(3).empty() ? 8 : 4;
    // The largest V-error over time compares the runs at the times of the
    // coarsest run with a history: that of all runs where N = T/k is a
    // multiple of `coarsest`, else that of the run with 4h and 4k where N
    // is a multiple of 4.
    // A run whose mesh changes during it has no one mesh to compare its
    // earlier states on: only its state at T is compared.
    const unsigned int n_steps = parameters.time.n_steps();
    const bool         mesh_changes =
      MeshAdaptationParameters::of(parameters).interval > 0;
    const unsigned int history_factor = mesh_changes            ? 0 :
                                        n_steps % coarsest == 0 ? coarsest :
                                        n_steps % 4 == 0        ? 4 :
                                                                  0;
    // The run itself first; it stays, since the other runs' displacements
    // are interpolated onto its mesh.
    ContactProblem<dim> fine(parameters);
    fine.adapt_mesh(input.plan);
    equip(fine, parameters);
    if (input.equip_scene_run)
      input.equip_scene_run(fine, parameters);
    EstimateRuns runs;
    runs.sequence.push_back(run_onto<dim>(fine, nullptr, history_factor));
    const ReferenceInterpolation<dim> interpolate(fine);
    const CoarseRuns<dim>             coarse{
      parameters, input.plan, history_factor, interpolate, equip};
    for (unsigned int factor = 2; factor <= coarsest; factor *= 2)
      runs.sequence.push_back(coarse.run(
        factor, factor, "coarse-" + std::to_string(runs.sequence.size())));
    if (AccuracyParameters::of(parameters).separate_space_and_time)
      for (unsigned int factor = 2; factor <= 4; factor *= 2)
        {
          const std::string level = std::to_string(factor / 2);
          runs.space.push_back(coarse.run(factor, 1, "coarse-space-" + level));
          runs.time.push_back(coarse.run(1, factor, "coarse-time-" + level));
        }

    RunResult         result{runs.sequence[0].summary,
                     estimate_rows(fine, runs, input.orders)};
    const std::string text =
      estimate_report(parameters, runs, result.rows, input.orders);
    study_console() << std::endl << text;
    write_study_file(parameters.output.directory + "/error_estimate.txt", text);
    return result;
  }


#define INSTANTIATE(dim) template class ErrorEstimate<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
