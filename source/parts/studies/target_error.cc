/* ---------------------------------------------------------------------
 * A run to a target error ('Accuracy/Target error').
 *
 * The error of the scheme at T behaves as e(h, k) = E_h h^p + E_k k^q
 * (Corollary 5.3, (5.26): p = q = 1 for smooth solutions and linear
 * elements, p = 2 with quadratic ones; lower orders near singularities).
 * Pilot runs (target_error_pilots.cc) measure the two terms separately on
 * the scene as given (h = H, k = K), each for every element degree the
 * scene allows, and the cost of a run: a + b * unknowns * steps per
 * degree. The program then chooses the degree, h = H / 2^m and k = T / N
 * that minimise the predicted cost of the run with its error estimate,
 * subject to a predicted error of half the target (the model is
 * extrapolated from coarse runs), and runs it with its own estimate (the
 * study that app/ gives the target), which says whether the target was
 * met.
 *
 * A scene that adapts its mesh during the run adds a second family of
 * candidates: pilots that start from H, 2H and 4H and adapt as the scene
 * says give it its own space part, order and cost; the time part is the
 * uniform pilots'. The cheapest candidate of both families runs.
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <base/dimensions.h>
#include <parts/studies/scene_variant.h>
#include <core/output_directory.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/target_error.h>
#include <parts/studies/target_error_pilots.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace Contact
{
  namespace
  {
    using namespace TargetPilots;

    // What a target writes into its output directory: its table (the
    // pilots' runs: target_error_pilots.cc).
    const ResultFiles target_table("target\\.txt");

    // The chosen run is predicted to have this fraction of the target: the
    // model extrapolates from coarse runs (on the manufactured solution it
    // predicted 0.7 times the largest error over time of a run with 14
    // times the pilots' unknowns and 7.5 times their steps, whose worst
    // time came earlier than the pilots could see).
    constexpr double target_safety = 0.5;
    // The finest run considered: h = H / 2^max_halvings.
    constexpr unsigned int max_halvings = 6;
    // A time step above 4K would extrapolate the time model beyond the
    // pilots.
    constexpr unsigned int max_time_factor = 4;

    // @sect3{The candidates}

    struct Candidate
    {
      unsigned int            degree;
      bool                    adapted;
      unsigned int            halvings;
      unsigned int            n_steps;
      types::global_dof_index n_dofs;
      double                  predicted_error;
      double                  predicted_cost;
    };

    // For h = H / 2^m the largest k = T / N (N a multiple of 8, so that the
    // estimate's runs with N / 2, N / 4 and N / 8 steps share their times)
    // whose predicted error stays within the allowed one; the cost is that
    // of the run and of its estimate's coarse runs.
    std::optional<Candidate> candidate(const DegreeModel  &model,
                                       const PilotResults &results,
                                       const Parameters   &parameters,
                                       const unsigned int  m,
                                       const double        allowed)
    {
      const DirectionFit &time     = results.time;
      const double        cosine   = results.cosine;
      const unsigned int  dim      = parameters.dimension;
      const double        end_time = parameters.time.end_time;
      const double        K        = end_time / parameters.time.n_steps();
      // (A direction without error has no order.)
      const double space_error =
        model.space.error == 0 ?
          0. :
          model.space.error * std::pow(2., -model.space.order * m);
      if (!(space_error < allowed) || !std::isfinite(time.error))
        return std::nullopt;
      // The time error E_k that makes |e_h + e_k| = allowed:
      // E_k^2 + 2 cosine E_h E_k + E_h^2 - allowed^2 = 0.
      const double time_error_allowed =
        -cosine * space_error +
        std::sqrt(cosine * cosine * space_error * space_error +
                  allowed * allowed - space_error * space_error);
      double k = K * max_time_factor;
      if (time.error > 0)
        k = std::min(k,
                     K * std::pow(time_error_allowed / time.error,
                                  1. / time.order));
      const double steps = 8 * std::ceil(end_time / k / 8 - 1e-9);
      if (!(steps <= parameters.time.max_steps))
        return std::nullopt;
      const unsigned int n_steps =
        std::max(static_cast<unsigned int>(steps), 8u);
      const double n_dofs = double(model.n_dofs) * std::pow(2., dim * m);
      // The run and its estimate's runs with 2h, 4h, 8h, and with the
      // separation those with 2h, 4h at k and 2k, 4k at h.
      double       work   = 0;
      unsigned int n_runs = 0;
      const auto   add    = [&](const double space, const double in_time) {
        work += n_dofs * std::pow(1. / space, dim) * n_steps / in_time;
        ++n_runs;
      };
      for (const double factor : {1., 2., 4., 8.})
        add(factor, factor);
      if (AccuracyParameters::of(parameters).separate_space_and_time)
        for (const double factor : {2., 4.})
          add(factor, 1.), add(1., factor);
      const double time_error =
        time.error == 0 ?
          0. :
          time.error * std::pow(end_time / n_steps / K, time.order);
      return Candidate{model.degree,
                       model.adapted,
                       m,
                       n_steps,
                       static_cast<types::global_dof_index>(n_dofs),
                       combined_error(space_error, time_error, cosine),
                       n_runs * model.a + model.b * work};
    }


    // @sect3{The report}

    std::string pilot_table(const std::vector<Pilot> &pilots,
                            const std::string        &quantity,
                            const bool                timings)
    {
      const std::string shown = quantity == worst_V_error ? V_norm : quantity;
      TableHandler      table;
      for (const Pilot &pilot : pilots)
        {
          const RunSummary &run = pilot.run.summary;
          table.add_value("pilot", pilot.name);
          table.add_value("degree", pilot.degree);
          table.add_value("h", run.cell_size);
          table.add_value("k", run.time_step);
          table.add_value("unknowns", run.n_dofs);
          table.add_value("steps", run.n_steps);
          table.add_value(V_norm + " at T", run.displacement_V_norm);
          if (shown != V_norm)
            table.add_value(shown + " at T", quantity_of(run, shown));
          if (timings)
            table.add_value("wall time [s]", run.wall_time);
        }
      for (const std::string &column : std::vector<std::string>{
             "h", "k", V_norm + " at T", shown + " at T"})
        {
          table.set_scientific(column, true);
          table.set_precision(column, 4);
        }
      if (timings)
        table.set_precision("wall time [s]", 4);
      std::ostringstream out;
      table.write_text(out, TableHandler::TextOutputFormat::org_mode_table);
      return out.str();
    }

    // A number with 3 digits and its unit, or "none" for NaN (nothing
    // measured or predicted).
    std::string number_or_none(const double value, const std::string &unit)
    {
      if (std::isnan(value))
        return "none";
      std::ostringstream out;
      out << std::setprecision(3) << value << unit;
      return out.str();
    }

    // `unit`: of the error, with its leading space; `at_unit`: of h or k.
    std::string fit_text(const std::string  &what,
                         const DirectionFit &fit,
                         const double        at,
                         const std::string  &unit,
                         const std::string  &at_unit)
    {
      std::ostringstream out;
      out << what << " " << number_or_none(fit.error, unit) << " at "
          << std::setprecision(3) << at << " " << at_unit << ", order "
          << number_or_none(fit.order, "");
      if (!fit.note.empty())
        out << " (" << fit.note << ")";
      return out.str();
    }


    // " m" after an error of the target quantity; nothing for a share.
    std::string unit_of_target(const Parameters &parameters)
    {
      const std::string unit = AccuracyParameters::of(parameters)
                                 .target_quantity.unit(parameters.dimension);
      return unit == "1" ? std::string() : " " + unit;
    }


    // @sect3{The choice}

    // Per degree the cheapest candidate, with a line on what its pilots
    // say; the cheapest of them.
    std::optional<Candidate> choose(const PilotResults &results,
                                    const Parameters   &parameters,
                                    const double        target,
                                    std::ostream       &out)
    {
      const bool measured = AccuracyParameters::of(parameters).cost_model ==
                            AccuracyParameters::CostModel::measured;
      const bool               timings = parameters.output.print_timings;
      const double             allowed = target_safety * target;
      const std::string        unit    = unit_of_target(parameters);
      std::optional<Candidate> chosen;
      for (const DegreeModel &model : results.models)
        {
          std::optional<Candidate> best;
          for (unsigned int m = 0; m <= max_halvings; ++m)
            if (const auto c =
                  candidate(model, results, parameters, m, allowed))
              if (!best || c->predicted_cost < best->predicted_cost)
                best = c;
          out << "Degree " << model.degree
              << (model.adapted ? ", adapted during the run" : "") << ": "
              << fit_text("space error E_h",
                          model.space,
                          results.pilots.front().run.summary.cell_size,
                          unit,
                          "m");
          if (measured && timings)
            out << "; cost " << model.a << " s + " << model.b
                << " s * unknowns * steps";
          if (best)
            {
              out << "; cheapest run predicted within " << allowed << unit
                  << ": h = H/" << (1u << best->halvings) << ", k = T/"
                  << best->n_steps << ", about " << best->n_dofs
                  << (best->adapted ? " unknowns at T" : " unknowns")
                  << ", predicted error " << best->predicted_error << unit;
              if (!measured)
                out << ", " << best->predicted_cost << " unknowns * steps";
              else if (timings)
                out << ", predicted " << best->predicted_cost << " s";
            }
          else
            out << "; no run up to h = H/" << (1u << max_halvings)
                << " is predicted within " << allowed << unit;
          out << std::endl;
          if (best &&
              (!chosen || best->predicted_cost < chosen->predicted_cost))
            chosen = best;
        }
      return chosen;
    }


    // @sect3{The report}

    // The adapted pilots' unknowns at T should fall by about 2^dim from
    // each to the next, as the coarse runs of an estimate
    // (error_estimate.cc); where a pilot could not adapt that far, its
    // family's order is measured on other sizes than it assumes.
    std::string adapted_sizes_warning(const PilotResults &results,
                                      const unsigned int  dim)
    {
      std::ostringstream out;
      for (const DegreeModel &model : results.models)
        {
          if (!model.adapted)
            continue;
          std::vector<types::global_dof_index> sizes;
          std::string                          unchanged;
          for (const Pilot &pilot : results.pilots)
            if (pilot.adapted && pilot.degree == model.degree)
              {
                sizes.push_back(pilot.run.summary.n_dofs);
                if (pilot.mesh_changes == 0)
                  unchanged += " " + pilot.name;
              }
          if (!unchanged.empty() && std::isfinite(model.space.error))
            out << "Warning: the meshes of the adapted pilots" << unchanged
                << " did not change during the run: their family's order "
                << "mixes adapted and uniform meshes." << std::endl;
          bool off = false;
          for (std::size_t i = 1; i < sizes.size(); ++i)
            {
              const double ratio = double(sizes[i - 1]) / sizes[i];
              off = off || ratio < (1u << dim) / 2. || ratio > 2. * (1u << dim);
            }
          if (!off)
            continue;
          out << "Warning: the unknowns at T of the adapted Q" << model.degree
              << " pilots (";
          for (std::size_t i = 0; i < sizes.size(); ++i)
            out << (i > 0 ? " " : "") << sizes[i];
          out << ") do not fall by about " << (1u << dim)
              << " from each to the next, as their order assumes: a mesh "
              << "this coarse may not adapt as far. Start from a smaller '"
              << Entry::cell_size << "' or a larger '" << Entry::target_unknowns
              << "'." << std::endl;
        }
      return out.str();
    }

    std::string pilots_report(const PilotResults &results,
                              const Parameters   &parameters,
                              const double        target)
    {
      const auto       &accuracy = AccuracyParameters::of(parameters);
      const std::string quantity = accuracy.target_quantity.name();
      const double K = parameters.time.end_time / parameters.time.n_steps();
      const std::string  unit = unit_of_target(parameters);
      std::ostringstream out;
      out << std::setprecision(3) << "Target error: " << quantity << " within "
          << target << unit;
      if ((accuracy.target_error_type ==
           AccuracyParameters::TargetErrorType::relative))
        out << " (" << accuracy.target_error << " times its size "
            << results.size << unit << ")";
      out << "; pilots on H = " << results.pilots.front().run.summary.cell_size
          << ", K = " << K << ":" << std::endl
          << pilot_table(results.pilots,
                         quantity,
                         parameters.output.print_timings)
          << "Time error: " << fit_text("E_k", results.time, K, unit, "s");
      if (results.cosine < 1)
        out << "; space and time errors combine as |e_h + e_k|^2 = E_h^2 + "
            << "E_k^2 + 2 c E_h E_k with c = " << results.cosine;
      out << std::endl;
      const MeshAdaptationParameters &adaptation =
        MeshAdaptationParameters::of(parameters);
      if (has_adapted_family(parameters))
        {
          out << "The adapted pilots adapt their meshes every "
              << adaptation.interval << " steps";
          if (adaptation.target_unknowns > 0)
            {
              out << " towards";
              for (const DegreeModel &model : results.models)
                if (model.adapted)
                  out << " "
                      << MeshAdaptationParameters::of(
                           scene_of(parameters, results, model.degree, true))
                           .target_unknowns
                      << " (Q" << model.degree << ")";
              out << " unknowns from H, and 1/" << (1u << parameters.dimension)
                  << " and 1/" << (1u << (2 * parameters.dimension))
                  << " of that from 2H and 4H";
            }
          out << " (their unknowns above: at T); E_k, its order and c "
              << "above come from the uniform pilots and hold for both "
              << "families." << std::endl;
          out << adapted_sizes_warning(results, parameters.dimension);
        }
      else if (adaptation.interval > 0)
        out << "Meshes adapted during the run are no candidates for "
            << quantity << ": a mesh that changes during the run holds no "
            << "states of earlier times to compare (for every other "
            << "'Target quantity' the target compares both families)."
            << std::endl;
      return out.str();
    }

    std::string chosen_report(const Parameters &parameters,
                              const Candidate  &chosen,
                              const RunResult  &result,
                              const double      target)
    {
      const std::string quantity =
        AccuracyParameters::of(parameters).target_quantity.name();
      double estimated = nan;
      for (const EstimateRow &row : result.rows)
        if (row.name == quantity)
          estimated = row.estimate.error;
      const RunSummary  &run  = result.summary;
      const std::string  unit = unit_of_target(parameters);
      std::ostringstream out;
      out << std::setprecision(3) << "Target error " << target << unit
          << " for " << quantity << ": chosen degree " << chosen.degree
          << (chosen.adapted ? " on a mesh adapted during the run" : "")
          << ", h = " << run.cell_size << " m"
          << (chosen.adapted ? " at the start" : "")
          << ", k = " << run.time_step << " s (" << run.n_dofs << " unknowns, "
          << run.n_steps << " steps); predicted error "
          << chosen.predicted_error << unit << ", estimated error "
          << number_or_none(estimated, unit) << " (error_estimate.txt)"
          << std::endl;
      if (std::isnan(estimated))
        out << "Warning: the runs of the chosen run's estimate give no "
            << "estimate of " << quantity << " (error_estimate.txt says "
            << "why)." << std::endl;
      else if (!(estimated <= target))
        out << "Warning: the estimated error of the chosen run is above the "
            << "target: the pilots were not in the asymptotic range (see the "
            << "warnings of the estimate); run with a smaller '"
            << Entry::cell_size << "' and '" << Entry::time_step << "'."
            << std::endl;
      if (parameters.verification.manufactured())
        out << std::setprecision(4) << "Exact max V-error of the chosen run: "
            << run.max_errors.displacement_V
            << " (at T: " << run.final_errors.displacement_V << ")"
            << std::endl;
      return out.str();
    }

    // The target as an absolute error: a relative one times the size of
    // the quantity on the first pilot, which must be defined.
    double target_of(const AccuracyParameters &accuracy,
                     const PilotResults       &pilots)
    {
      AssertThrow(std::isfinite(pilots.size),
                  ExcMessage("Entry '" + Entry::target_quantity + "' = '" +
                             accuracy.target_quantity.name() +
                             "' is not defined on the pilots (e.g. no slip "
                             "zone, or no node on Gamma_3): choose a quantity "
                             "that this scene has."));
      const bool relative = (accuracy.target_error_type ==
                             AccuracyParameters::TargetErrorType::relative);
      AssertThrow(pilots.size > 0 || !relative,
                  ExcMessage("Entry '" + Entry::target_error_type +
                             "' = relative: the size of '" +
                             accuracy.target_quantity.name() +
                             "' is 0 on the pilots; give an absolute target."));
      return relative ? accuracy.target_error * pilots.size :
                        accuracy.target_error;
    }

    // The orders that the pilots of `degree` measured, with which the
    // estimate of the chosen run extrapolates.
    KnownOrders known_orders(const PilotResults &pilots,
                             const Candidate    &chosen,
                             const std::string  &quantity)
    {
      KnownOrders orders;
      for (const DegreeModel &model : pilots.models)
        if (model.degree == chosen.degree && model.adapted == chosen.adapted)
          {
            orders[quantity] = {model.space.order,
                                pilots.time.order,
                                quantity == worst_V_error ? pilots.cosine : 1.};
            orders[V_norm]   = {model.space_V.order,
                                pilots.time_V.order,
                                pilots.cosine};
          }
      return orders;
    }


    // @sect3{The pilots, the choice and the chosen run}

    // Stops the target where the pilots predict nothing, or nothing within
    // the finest run considered.
    void require_choice(const Parameters               &parameters,
                        const PilotResults             &pilots,
                        const std::optional<Candidate> &chosen)
    {
      const AccuracyParameters &accuracy = AccuracyParameters::of(parameters);
      bool                      some_degree_predicts = false;
      for (const DegreeModel &model : pilots.models)
        some_degree_predicts =
          some_degree_predicts || std::isfinite(model.space.error);
      const bool predicts =
        std::isfinite(pilots.time.error) && some_degree_predicts;
      AssertThrow(chosen || predicts,
                  ExcMessage("Entry '" + Entry::target_error +
                             "' = " + number_text(accuracy.target_error) +
                             ": the pilots are not in the asymptotic range for "
                             "'" +
                             accuracy.target_quantity.name() +
                             "' (see the lines above: an order below " +
                             number_text(min_plausible_order) +
                             " or differences that change sign), so they "
                             "predict nothing. Start from a smaller '" +
                             Entry::cell_size + "' and '" + Entry::time_step +
                             "', or choose another '" + Entry::target_quantity +
                             "'."));
      AssertThrow(chosen,
                  ExcMessage("Entry '" + Entry::target_error +
                             "' = " + number_text(accuracy.target_error) +
                             ": the pilots predict an error above the target "
                             "for every degree up to h = H/" +
                             std::to_string(1u << max_halvings) + " and '" +
                             Entry::max_steps + "' = " +
                             std::to_string(parameters.time.max_steps) +
                             " steps (see the lines above). Ask for a larger "
                             "target, or start from a smaller '" +
                             Entry::cell_size + "' and '" + Entry::time_step +
                             "' if the pilots are not yet in the asymptotic "
                             "range."));
    }

    // The line that announces the chosen run; stops the target where its
    // predicted wall time is above the limit.
    void announce_choice(const Parameters &parameters,
                         const Candidate  &chosen,
                         const std::function<void(const std::string &)> &print)
    {
      const bool measured = AccuracyParameters::of(parameters).cost_model ==
                            AccuracyParameters::CostModel::measured;
      std::ostringstream choice_line;
      choice_line << std::setprecision(3)
                  << "Target error: the chosen run, degree " << chosen.degree
                  << ", h = H/" << (1u << chosen.halvings)
                  << (chosen.adapted ? " adapted during the run" : "")
                  << ", k = T/" << chosen.n_steps << ", predicted error "
                  << chosen.predicted_error << unit_of_target(parameters);
      if (measured && parameters.output.print_timings)
        choice_line << ", predicted wall time " << chosen.predicted_cost
                    << " s";
      choice_line << ", with its error estimate" << std::endl;
      print(choice_line.str());
      const double limit =
        AccuracyParameters::of(parameters).max_predicted_time;
      AssertThrow(limit == 0 || !measured || chosen.predicted_cost <= limit,
                  ExcMessage("Entry '" + Entry::max_predicted_time +
                             "' = " + number_text(limit) +
                             " s: the run chosen above is predicted to take " +
                             (parameters.output.print_timings ?
                                number_text(chosen.predicted_cost) + " s" :
                                std::string("longer")) +
                             " with its estimate; it was not run. Raise the "
                             "limit, or ask for a larger '" +
                             Entry::target_error + "'."));
    }

    // The pilots, the choice and the chosen run with its estimate.
    template <int dim>
    RunResult
    choose_and_run(const Parameters                               &parameters,
                   const Timer                                    &timer,
                   Study<dim>                                     &chosen_run,
                   const Equipment<dim>                           &equipment,
                   const std::function<void(const std::string &)> &print)
    {
      const PilotResults pilots =
        run_pilots<dim>(parameters, equipment, [&](const std::string &line) {
          print(line + "\n");
        });
      const double target =
        target_of(AccuracyParameters::of(parameters), pilots);
      print("\n" + pilots_report(pilots, parameters, target));
      std::ostringstream choice;
      choice << std::setprecision(3);
      const std::optional<Candidate> chosen =
        choose(pilots, parameters, target, choice);
      print(choice.str());
      require_choice(parameters, pilots, chosen);
      announce_choice(parameters, *chosen, print);
      const Timer      chosen_timer;
      const Parameters chosen_scene = parameters_of(
        scene_of(parameters, pilots, chosen->degree, chosen->adapted),
        {static_cast<int>(chosen->halvings),
         chosen->n_steps,
         chosen->degree,
         parameters.output.directory,
         false,
         chosen->adapted});
      const RunResult result =
        chosen_run.run(chosen_scene,
                       {MeshPlan(),
                        known_orders(pilots,
                                     *chosen,
                                     AccuracyParameters::of(parameters)
                                       .target_quantity.name()),
                        {}});
      print("\n" + chosen_report(parameters, *chosen, result, target));
      if (parameters.output.print_timings)
        {
          std::ostringstream times;
          times << std::setprecision(3) << "Wall time: pilots "
                << pilots.wall_time << " s, the chosen run with its estimate "
                << chosen_timer.wall_time() << " s, total " << timer.wall_time()
                << " s" << std::endl;
          print(times.str());
        }
      return result;
    }
  } // namespace


  // @sect3{The study}

  template <int dim>
  TargetError<dim>::TargetError(std::unique_ptr<Study<dim>> run_with_estimate,
                                const Equipment<dim>       &equipment)
    : chosen_run(std::move(run_with_estimate))
    , equip(equipment)
  {}


  template <int dim>
  RunResult TargetError<dim>::run(const Parameters &parameters,
                                  const StudyInput<dim> &)
  {
    Timer              timer;
    const std::string &directory = parameters.output.directory;
    std::ostringstream text;
    const auto         print = [&](const std::string &lines) {
      text << lines;
      study_console() << lines << std::flush;
    };
    // The lock of the whole target run; the chosen run shares it.
    const auto lock = lock_output_directory(directory, MPI_COMM_WORLD);
    // Nothing of an earlier run stays next to the pilots: if no run
    // reaches the target, the directory holds the pilots only.
    remove_results(directory, false, MPI_COMM_WORLD);

    // What the target prints also goes to target.txt, however the target
    // ends: a target stopped by an error records why.
    const auto write_record = [&]() {
      write_study_file(directory + "/target.txt", text.str());
    };
    RunResult result;
    try
      {
        result =
          choose_and_run<dim>(parameters, timer, *chosen_run, equip, print);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream reason;
        exc.print_info(reason);
        text << "\nStopped: " << Utilities::trim(reason.str()) << std::endl;
        write_record();
        throw;
      }
    write_record();
    return result;
  }


#define INSTANTIATE(dim) template class TargetError<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
