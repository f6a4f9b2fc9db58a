/* ---------------------------------------------------------------------
 * The report of an error estimate (include/parts/studies/error_estimate.h):
 * what the runs compare and how, the table of the estimates, and the notes and
 * warnings that say where an estimate rests on less than it seems to.
 * --------------------------------------------------------------------- */

#include <deal.II/base/table_handler.h>

#include <core/quantity.h>
#include <parts/studies/error_estimate.h>
#include <parts/studies/study_parameters.h>
#include <core/geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace Contact
{
  namespace
  {
    // The coarse runs take ceil(N / 2^l) steps; a ratio of their time step
    // to the run's that differs from 2^l by more than this (relative) gets a
    // warning.
    constexpr double max_step_ratio_deviation = 0.05;

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
          table.add_value(
            "unit",
            Quantity::parse(row.name, Entry::target_quantity).unit(dim));
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

    // What the estimate compares: the runs, the orders and the formula;
    // where the mesh allows no run with 8h, what is not checked.
    void describe_runs(const Parameters   &parameters,
                       const EstimateRuns &runs,
                       std::ostream       &out)
    {
      const bool exact    = parameters.verification.manufactured();
      const bool separate = !runs.space.empty();
      const std::vector<RunAtTimes> &sequence = runs.sequence;
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
    }


    // With quadratic elements and one order, and with the orders that a
    // target's pilots measured: what the estimate can and cannot tell.
    void notes_on_orders(const Parameters  &parameters,
                         const bool         separate,
                         const KnownOrders &orders,
                         std::ostream      &out)
    {
      if (!separate && orders.empty() && parameters.geometry.fe_degree >= 2)
        out << "Note: with degree " << parameters.geometry.fe_degree
            << " elements the space error may fall faster than the time "
            << "error (h^2 against k), and one order cannot describe their "
            << "sum: where both matter these estimates are too small (0.64 "
            << "of the exact V-error on the manufactured solution at h = k = "
            << "1/16). '" << Entry::separate_space_and_time
            << "' = true estimates the two parts with their own orders."
            << std::endl;
      // What the pilots' orders do (estimate_of, row_at_T): raise an
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
    }


    // The largest V-error over time (where and from which runs), the rows
    // whose space and time parts cancel, and the exact errors.
    void notes_on_worst_row(const Parameters               &parameters,
                            const EstimateRuns             &runs,
                            const std::vector<EstimateRow> &rows,
                            std::ostream                   &out)
    {
      const bool exact    = parameters.verification.manufactured();
      const bool separate = !runs.space.empty();
      const std::vector<RunAtTimes> &sequence = runs.sequence;
      const unsigned int             coarsest = 1u << (sequence.size() - 1);
      bool                           has_worst_row = false;
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
      if (!has_worst_row &&
          MeshAdaptationParameters::of(parameters).interval > 0)
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
    }


    // Coarse runs that are not what the estimate assumes: time steps off
    // their ratio 2^l, meshes adapted during the run that did not shrink by
    // about 2^dim per level.
    void warnings_on_coarse_runs(const Parameters              &parameters,
                                 const std::vector<RunAtTimes> &sequence,
                                 std::ostream                  &out)
    {
      const unsigned int coarsest = 1u << (sequence.size() - 1);
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
      if (MeshAdaptationParameters::of(parameters).interval > 0)
        {
          out << "The runs adapt their meshes during the run, from the h "
              << "above";
          if (MeshAdaptationParameters::of(parameters).target_unknowns > 0)
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
    }


    // Why a row has no estimate, and the rows that move in steps of a node.
    void notes_on_rows(const std::vector<EstimateRow> &rows, std::ostream &out)
    {
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
    }
  } // namespace


  std::string estimate_report(const Parameters               &parameters,
                              const EstimateRuns             &runs,
                              const std::vector<EstimateRow> &rows,
                              const KnownOrders              &orders)
  {
    std::ostringstream out;
    describe_runs(parameters, runs, out);
    notes_on_orders(parameters, !runs.space.empty(), orders, out);
    write_table(rows,
                parameters.dimension,
                runs.sequence.size() - 1,
                parameters.verification.manufactured(),
                !runs.space.empty(),
                out);
    notes_on_worst_row(parameters, runs, rows, out);
    warnings_on_coarse_runs(parameters, runs.sequence, out);
    notes_on_rows(rows, out);
    return out.str();
  }
} // namespace Contact
