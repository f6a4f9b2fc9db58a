/* ---------------------------------------------------------------------
 * A run to a target error ('Accuracy/Target error').
 *
 * The error of the scheme at T behaves as e(h, k) = E_h h^p + E_k k^q
 * (Corollary 5.3, (5.26): p = q = 1 for smooth solutions and linear
 * elements, p = 2 with quadratic ones; lower orders near singularities).
 * Pilot runs measure the two terms separately on the scene as given (h =
 * H, k = K): the runs with H, 2H and 4H at K give the space part and its
 * order by Richardson extrapolation (error_estimate.cc), the runs with K,
 * 2K and 4K at H the time part and its order, each for every element
 * degree the scene allows (the time part once: it does not depend on the
 * degree to leading order). The pilots' wall times fit a cost model
 * a + b * unknowns * steps per degree. The program then chooses the degree,
 * h = H / 2^m and k = T / N that minimise the predicted cost of the run
 * with its error estimate, subject to a predicted error of half the
 * target (the model is extrapolated from coarse runs), and runs it with
 * its own estimate, which says whether the target was met.
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
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <drivers/error_estimate.h>
#include <drivers/mesh_adaptation.h>
#include <drivers/reference_interpolation.h>
#include <drivers/scene_variant.h>
#include <drivers/target_error.h>

#include <cmath>
#include <functional>
#include <memory>
#include <fstream>
#include <iomanip>
#include <limits>
#include <list>
#include <optional>
#include <sstream>

namespace Contact
{
  namespace
  {
    // What a target writes into its output directory: its table, and the
    // pilots' runs (kept by the run the target chose).
    const ResultFiles       target_table("target\\.txt");
    const ResultDirectories pilot_runs("pilot-q[12]-(adapted-)?[24]?h-[24]?k",
                                       true);
  } // namespace


  namespace
  {
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

    // @sect3{Pilots}

    // A pilot, with its displacement at each of its steps on the mesh of
    // the pilot with h = H and k = K of its degree.
    struct Pilot
    {
      std::string  name;
      unsigned int degree;
      // Of the family of meshes adapted during the run (scene_variant.cc),
      // with the number of adaptations that changed its mesh.
      bool         adapted;
      RunAtTimes   run;
      unsigned int mesh_changes = 0;
    };

    double quantity_of(const RunSummary &summary, const std::string &name)
    {
      if (name == V_norm)
        return summary.displacement_V_norm;
      for (const auto &[quantity, value] : summary.final_quantities)
        if (quantity == name)
          return value;
      return std::numeric_limits<double>::quiet_NaN();
    }

    // The error of one direction (h or k) at the pilots' H or K, with the
    // order used to extrapolate it, from the three pilots f (H), m (2H)
    // and c (4H) (or K, 2K, 4K): the estimate of error_estimate.cc for the
    // target quantity, with the order lowered to what the scheme can give
    // (`max_order`), never raised: below min_plausible_order the direction
    // predicts nothing (error NaN; a note says why).
    struct DirectionFit
    {
      double      error = 0;
      double      order = 0;
      std::string note;
    };

    template <int dim>
    DirectionFit fit_direction(const ContactProblem<dim> &base,
                               const Pilot               &f,
                               const Pilot               &m,
                               const Pilot               &c,
                               const std::string         &quantity,
                               const double               max_order)
    {
      const auto difference = [&](const VectorType &a, const VectorType &b) {
        return strain_distance(base, a, b);
      };
      // The largest error over time: the error at T, times the largest
      // ratio of the difference at a time that both runs share to that at T
      // (the orders at earlier times come from fewer steps).
      if (quantity == worst_V_error)
        {
          DirectionFit fit = fit_direction(base, f, m, c, V_norm, max_order);
          const double at_T =
            difference(f.run.displacement, m.run.displacement);
          const auto ratio = static_cast<std::size_t>(
            std::lround(m.run.summary.time_step / f.run.summary.time_step));
          double largest = at_T;
          for (std::size_t i = 0; i < m.run.history.size() &&
                                  (i + 1) * ratio <= f.run.history.size();
               ++i)
            largest = std::max(largest,
                               difference(f.run.history[(i + 1) * ratio - 1],
                                          m.run.history[i]));
          if (at_T > 0)
            fit.error *= largest / at_T;
          return fit;
        }
      const auto value = [&](const Pilot &pilot) {
        return quantity_of(pilot.run.summary, quantity);
      };
      const bool   field = quantity == V_norm;
      const double d_fine =
        field ? difference(f.run.displacement, m.run.displacement) :
                value(f) - value(m);
      const double d_coarse =
        field ? difference(m.run.displacement, c.run.displacement) :
                value(m) - value(c);
      const RichardsonEstimate estimate =
        richardson_estimate({d_fine, d_coarse}, !field);
      // The order measured, never another quantity's (none where the
      // differences change sign).
      const double order = !field && d_fine * d_coarse < 0 ?
                             std::numeric_limits<double>::quiet_NaN() :
                             estimate.measured_orders[0];
      // No error seen in this direction: it limits nothing, and has no
      // order.
      if (d_fine == 0 && d_coarse == 0)
        return {0.,
                std::numeric_limits<double>::quiet_NaN(),
                "the same on the three pilots"};
      // An order below what the scheme shows in the asymptotic range (or
      // none) is never raised: it would make the predicted error fall
      // faster than measured. This direction predicts nothing.
      if (!(order >= min_plausible_order))
        return {std::numeric_limits<double>::quiet_NaN(),
                order,
                (std::isnan(order) ?
                   estimate.reason :
                   "measured order " + number_text(order) + ", below " +
                     number_text(min_plausible_order)) +
                  ": the pilots are not in the asymptotic range, no "
                  "prediction"};
      if (order > max_order)
        return {std::abs(d_fine) / (std::pow(2., max_order) - 1),
                max_order,
                "measured order " + number_text(order) + " taken as " +
                  number_text(max_order) + " (the scheme gives at most that)"};
      return {estimate.error, order, ""};
    }

    // What a degree's pilots say, of uniform meshes or of meshes adapted
    // during the run: the space part of the V-norm and of the target
    // quantity, and the fit a + b x of their wall times against x =
    // unknowns * steps (unknowns at T).
    struct DegreeModel
    {
      unsigned int            degree;
      bool                    adapted;
      DirectionFit            space_V;
      DirectionFit            space;
      types::global_dof_index n_dofs = 0;
      double                  a = 0, b = 1;
    };

    // Everything the pilots measured.
    struct PilotResults
    {
      std::vector<Pilot>       pilots;
      std::vector<DegreeModel> models;
      DirectionFit             time_V;
      DirectionFit             time;
      // |quantity| on the first pilot, the scale of a relative target.
      double size = 0;
      // The cosine of the angle between the space and the time error
      // (run_pilots_of_degree).
      double cosine    = 1;
      double wall_time = 0;
    };

    void fit_cost(DegreeModel              &model,
                  const std::vector<Pilot> &pilots,
                  const bool                measured)
    {
      if (!measured)
        return;
      // The first run of the process also loads what the libraries bind
      // lazily: not a cost of its size.
      double n = 0, sx = 0, st = 0, sxx = 0, sxt = 0;
      for (const Pilot &pilot : pilots)
        if (pilot.degree == model.degree && pilot.adapted == model.adapted &&
            &pilot != &pilots.front())
          {
            const RunSummary &run = pilot.run.summary;
            const double      x   = double(run.n_dofs) * run.n_steps;
            const double      t   = run.wall_time;
            n += 1, sx += x, st += t, sxx += x * x, sxt += x * t;
          }
      const double denominator = n * sxx - sx * sx;
      model.b = denominator > 0 ? (n * sxt - sx * st) / denominator : 0;
      model.a = (st - model.b * sx) / n;
      // A fit that is not a fixed plus a proportional cost: proportional
      // only, by least squares.
      if (!(model.b > 0) || model.a < 0)
        {
          model.a = 0;
          model.b = sxt / sxx;
        }
    }


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
                                       const DirectionFit &time,
                                       const double        cosine,
                                       const unsigned int  m,
                                       const unsigned int  dim,
                                       const double        end_time,
                                       const double        K,
                                       const double        allowed,
                                       const unsigned int  max_steps,
                                       const bool          separate)
    {
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
      if (!(steps <= max_steps))
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
      if (separate)
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


    // @sect3{Running the pilots}

    // From the pilots of the first degree (H at K, 2H, 4H, 2K and 4K, from
    // `first` on): the size of the quantity on the first (the scale of a
    // relative target), and how the space and the time error of the V-norm
    // combine, from the angle between what doubling h and what doubling k
    // changes. A quantity's two errors add (they may cancel on the pilots
    // and not later).
    template <int dim>
    void measure_size_and_cosine(const ContactProblem<dim> &base,
                                 const std::vector<Pilot>  &pilots,
                                 const std::size_t          first,
                                 const std::string         &quantity,
                                 PilotResults              &results)
    {
      const RunAtTimes &own = pilots[first].run;
      results.size          = std::abs(quantity_of(own.summary, quantity));
      if (quantity == worst_V_error)
        {
          results.size = own.summary.displacement_V_norm;
          for (const VectorType &u : own.history)
            results.size = std::max(results.size, base.strain_norm(u));
        }
      const auto norm = [&](const std::size_t a, const std::size_t b) {
        return strain_distance(base,
                               pilots[first + a].run.displacement,
                               pilots[first + b].run.displacement);
      };
      const double s = norm(0, 1), t = norm(0, 3), across = norm(3, 1);
      if ((quantity == V_norm || quantity == worst_V_error) && s > 0 && t > 0)
        results.cosine =
          std::clamp((s * s + t * t - across * across) / (2 * s * t), 0., 1.);
    }

    // The pilots of one degree and mesh family: H, 2H, 4H at K, and for
    // the first degree on uniform meshes also 2K and 4K at H (the time
    // part, shared by the degrees and by both families: to leading order
    // it does not depend on the mesh). The adapted family starts from the
    // same meshes and adapts them during the run towards 'Target unknowns'
    // times 1, 1/2^dim and 1/4^dim; its runs keep no states over time (no
    // one mesh holds them).
    template <int dim>
    void
    run_pilots_of_degree(const Parameters  &parameters,
                         const unsigned int degree,
                         const bool         adapted,
                         const bool         with_time,
                         PilotResults      &results,
                         const std::function<void(const std::string &)> &print)
    {
      const std::string   quantity = parameters.accuracy.target_quantity.name();
      const unsigned int  N0       = parameters.time.n_steps();
      std::vector<Pilot> &pilots   = results.pilots;
      const std::size_t   first    = pilots.size();
      // The pilots' parameters outlive the problems, whose adaptation
      // keeps a reference to them.
      std::list<Parameters>                        own_parameters;
      std::unique_ptr<ContactProblem<dim>>         base;
      std::unique_ptr<ReferenceInterpolation<dim>> interpolate;
      // Every pilot keeps its state at each of its steps on the mesh of the
      // first (N0 is a multiple of 4, parameters.cc).
      const auto run = [&](const unsigned int space_factor,
                           const unsigned int time_factor) {
        const std::string name =
          "pilot-q" + std::to_string(degree) + "-" +
          (adapted ? "adapted-" : "") +
          (space_factor > 1 ? std::to_string(space_factor) : "") + "h-" +
          (time_factor > 1 ? std::to_string(time_factor) : "") + "k";
        const std::string directory = parameters.output.directory + "/" + name;
        const Parameters &own       = own_parameters.emplace_back(
          parameters_of(parameters,
                        {-static_cast<int>(space_factor / 2),
                               N0 / time_factor,
                               degree,
                               directory,
                               true,
                               adapted}));
        auto problem = std::make_unique<ContactProblem<dim>>(own);
        if (own.mesh_adaptation.interval > 0)
          adapt_during_run(*problem, own.mesh_adaptation);
        pilots.push_back({name,
                          degree,
                          adapted,
                          run_onto(*problem,
                                   interpolate.get(),
                                   adapted ? 0 : 1,
                                   directory + "/console.log")});
        pilots.back().mesh_changes = problem->get_mesh_plan().n_cycles();
        print(
          "Target error: pilot " + name + ": " +
          sub_run_line(pilots.back().run.summary, directory + "/console.log"));
        // The cost model, and so the choice, must be the same on every
        // process.
        double &wall_time = pilots.back().run.summary.wall_time;
        wall_time         = Utilities::MPI::max(wall_time, MPI_COMM_WORLD);
        if (!base)
          {
            base        = std::move(problem);
            interpolate = std::make_unique<ReferenceInterpolation<dim>>(*base);
          }
      };
      run(1, 1);
      run(2, 1);
      run(4, 1);
      const auto fit = [&](const std::size_t  medium,
                           const std::size_t  coarse,
                           const std::string &name,
                           const double       max_order) {
        return fit_direction(*base,
                             pilots[first],
                             pilots[first + medium],
                             pilots[first + coarse],
                             name,
                             max_order);
      };
      // The V-norm converges with order `degree` in h at best, a value at a
      // point or an integral with one more; the scheme is of first order in
      // time ((5.26)).
      const bool field = quantity == V_norm || quantity == worst_V_error;
      results.models.push_back({degree,
                                adapted,
                                fit(1, 2, V_norm, degree),
                                fit(1, 2, quantity, degree + (field ? 0 : 1)),
                                pilots[first].run.summary.n_dofs});
      // Pilots whose meshes never changed are uniform ones: no family of
      // their own (a 'Target unknowns' below the start mesh's, or a
      // 'Refine fraction' of 0, refines nothing).
      bool changed = false;
      for (std::size_t i = first; i < pilots.size(); ++i)
        changed = changed || pilots[i].mesh_changes > 0;
      if (adapted && !changed)
        for (DirectionFit *space_fit :
             {&results.models.back().space_V, &results.models.back().space})
          *space_fit = {
            std::numeric_limits<double>::quiet_NaN(),
            std::numeric_limits<double>::quiet_NaN(),
            "its pilots' meshes did not change during the run, no cell met '" +
              Entry::refine_fraction + "' towards '" + Entry::target_unknowns +
              "': no adapted family, no prediction"};
      if (!with_time)
        return;
      run(1, 2);
      run(1, 4);
      results.time_V = fit(3, 4, V_norm, 1.);
      results.time   = fit(3, 4, quantity, 1.);
      measure_size_and_cosine(*base, pilots, first, quantity, results);
    }

    // A scene that adapts its mesh during the run has two families of
    // candidates, uniform and adapted meshes, unless the target quantity
    // needs the states over time on one mesh.
    bool has_adapted_family(const Parameters &parameters)
    {
      return parameters.mesh_adaptation.interval > 0 &&
             parameters.accuracy.target_quantity.name() != worst_V_error;
    }

    // The scene as the candidates of a degree and family run it. Meshes
    // adapted during the run refine their start mesh by as much as the
    // scene's degree would: 'Target unknowns' times the ratio of the
    // degree's unknowns on the uniform mesh H to those of the scene's
    // degree (from the uniform pilots, which run first).
    Parameters scene_of(const Parameters   &scene,
                        const PilotResults &results,
                        const unsigned int  degree,
                        const bool          adapted)
    {
      Parameters own = scene;
      if (!adapted || scene.mesh_adaptation.target_unknowns == 0)
        return own;
      types::global_dof_index of_degree = 0, of_scene_degree = 0;
      for (const DegreeModel &model : results.models)
        if (!model.adapted)
          {
            if (model.degree == degree)
              of_degree = model.n_dofs;
            if (model.degree == scene.geometry.fe_degree)
              of_scene_degree = model.n_dofs;
          }
      Assert(of_degree > 0 && of_scene_degree > 0, ExcInternalError());
      own.mesh_adaptation.target_unknowns = static_cast<unsigned int>(
        std::lround(double(scene.mesh_adaptation.target_unknowns) * of_degree /
                    of_scene_degree));
      return own;
    }

    template <int dim>
    PilotResults
    run_pilots(const Parameters                               &parameters,
               const std::function<void(const std::string &)> &print)
    {
      Timer timer;
      // Quadratic elements on tetrahedra have no nodal friction weights
      // (parameters.cc): there only degree 1.
      std::vector<unsigned int> degrees = {2, 1};
      if (dim == 3 &&
          (parameters.geometry.cell_shape ==
           GeometryParameters::CellShape::simplex) &&
          !parameters.friction.law->is_frictionless())
        degrees = {1};
      PilotResults results;
      for (const unsigned int degree : degrees)
        run_pilots_of_degree<dim>(
          parameters, degree, false, degree == degrees.front(), results, print);
      if (has_adapted_family(parameters))
        for (const unsigned int degree : degrees)
          run_pilots_of_degree<dim>(scene_of(parameters, results, degree, true),
                                    degree,
                                    true,
                                    false,
                                    results,
                                    print);
      for (DegreeModel &model : results.models)
        fit_cost(model,
                 results.pilots,
                 parameters.accuracy.cost_model ==
                   AccuracyParameters::CostModel::measured);
      results.wall_time = timer.wall_time();
      return results;
    }


    // " m" after an error of the target quantity; nothing for a share.
    std::string unit_of_target(const Parameters &parameters)
    {
      const std::string unit =
        parameters.accuracy.target_quantity.unit(parameters.dimension);
      return unit == "1" ? std::string() : " " + unit;
    }


    // @sect3{The choice}

    // Per degree the cheapest candidate, with a line on what its pilots
    // say; the cheapest of them.
    std::optional<Candidate> choose(const PilotResults &results,
                                    const Parameters   &parameters,
                                    const unsigned int  dim,
                                    const double        target,
                                    std::ostream       &out)
    {
      const bool measured = parameters.accuracy.cost_model ==
                            AccuracyParameters::CostModel::measured;
      const bool   timings = parameters.output.print_timings;
      const double K = parameters.time.end_time / parameters.time.n_steps();
      const double allowed          = target_safety * target;
      const std::string        unit = unit_of_target(parameters);
      std::optional<Candidate> chosen;
      for (const DegreeModel &model : results.models)
        {
          std::optional<Candidate> best;
          for (unsigned int m = 0; m <= max_halvings; ++m)
            if (const auto c =
                  candidate(model,
                            results.time,
                            results.cosine,
                            m,
                            dim,
                            parameters.time.end_time,
                            K,
                            allowed,
                            parameters.time.max_steps,
                            parameters.accuracy.separate_space_and_time))
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
      const auto       &accuracy = parameters.accuracy;
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
      const MeshAdaptationParameters &adaptation = parameters.mesh_adaptation;
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
                      << scene_of(parameters, results, model.degree, true)
                           .mesh_adaptation.target_unknowns
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

    std::string chosen_report(const Parameters   &parameters,
                              const Candidate    &chosen,
                              const EstimatedRun &result,
                              const double        target)
    {
      const std::string quantity  = parameters.accuracy.target_quantity.name();
      double            estimated = std::numeric_limits<double>::quiet_NaN();
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

    // The pilots, the choice and the chosen run with its estimate.
    template <int dim>
    void choose_and_run(const Parameters &parameters,
                        const Timer      &timer,
                        const std::function<void(const std::string &)> &print)
    {
      const std::string &directory = parameters.output.directory;
      const PilotResults pilots =
        run_pilots<dim>(parameters,
                        [&](const std::string &line) { print(line + "\n"); });
      const double target = target_of(parameters.accuracy, pilots);
      print("\n" + pilots_report(pilots, parameters, target));
      std::ostringstream choice;
      choice << std::setprecision(3);
      const std::optional<Candidate> chosen =
        choose(pilots, parameters, dim, target, choice);
      print(choice.str());
      bool some_degree_predicts = false;
      for (const DegreeModel &model : pilots.models)
        some_degree_predicts =
          some_degree_predicts || std::isfinite(model.space.error);
      const bool predicts =
        std::isfinite(pilots.time.error) && some_degree_predicts;
      AssertThrow(chosen || predicts,
                  ExcMessage(
                    "Entry '" + Entry::target_error +
                    "' = " + number_text(parameters.accuracy.target_error) +
                    ": the pilots are not in the asymptotic range for "
                    "'" +
                    parameters.accuracy.target_quantity.name() +
                    "' (see the lines above: an order below " +
                    number_text(min_plausible_order) +
                    " or differences that change sign), so they "
                    "predict nothing. Start from a smaller '" +
                    Entry::cell_size + "' and '" + Entry::time_step +
                    "', or choose another '" + Entry::target_quantity + "'."));
      AssertThrow(chosen,
                  ExcMessage("Entry '" + Entry::target_error + "' = " +
                             number_text(parameters.accuracy.target_error) +
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

      const bool measured = parameters.accuracy.cost_model ==
                            AccuracyParameters::CostModel::measured;
      std::ostringstream choice_line;
      choice_line << std::setprecision(3)
                  << "Target error: the chosen run, degree " << chosen->degree
                  << ", h = H/" << (1u << chosen->halvings)
                  << (chosen->adapted ? " adapted during the run" : "")
                  << ", k = T/" << chosen->n_steps << ", predicted error "
                  << chosen->predicted_error << unit_of_target(parameters);
      if (measured && parameters.output.print_timings)
        choice_line << ", predicted wall time " << chosen->predicted_cost
                    << " s";
      choice_line << ", with its error estimate" << std::endl;
      print(choice_line.str());
      const double limit = parameters.accuracy.max_predicted_time;
      AssertThrow(limit == 0 || !measured || chosen->predicted_cost <= limit,
                  ExcMessage("Entry '" + Entry::max_predicted_time +
                             "' = " + number_text(limit) +
                             " s: the run chosen above is predicted to take " +
                             (parameters.output.print_timings ?
                                number_text(chosen->predicted_cost) + " s" :
                                std::string("longer")) +
                             " with its estimate; it was not run. Raise the "
                             "limit, or ask for a larger '" +
                             Entry::target_error + "'."));
      const Timer        chosen_timer;
      const EstimatedRun result = run_with_error_estimate<dim>(
        parameters_of(
          scene_of(parameters, pilots, chosen->degree, chosen->adapted),
          {static_cast<int>(chosen->halvings),
           chosen->n_steps,
           chosen->degree,
           directory,
           false,
           chosen->adapted}),
        known_orders(pilots,
                     *chosen,
                     parameters.accuracy.target_quantity.name()));
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
    }
  } // namespace


  // @sect3{run_to_target}

  template <int dim>
  void run_to_target(const Parameters &parameters)
  {
    Timer              timer;
    const std::string &directory = parameters.output.directory;
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    std::ostringstream text;
    const auto         print = [&](const std::string &lines) {
      text << lines;
      if (root)
        std::cout << lines << std::flush;
    };
    // The lock of the whole target run; the chosen run shares it.
    const auto lock = lock_output_directory(directory, MPI_COMM_WORLD);
    // Nothing of an earlier run stays next to the pilots: if no run
    // reaches the target, the directory holds the pilots only.
    remove_results(directory, false, MPI_COMM_WORLD);

    // What the target prints also goes to target.txt, however the target
    // ends: a target stopped by an error records why.
    const auto write_record = [&]() {
      if (!root)
        return;
      std::ofstream file(directory + "/target.txt");
      file << text.str();
      AssertThrow(file.good(),
                  ExcMessage("Cannot write '" + directory + "/target.txt'."));
    };
    try
      {
        choose_and_run<dim>(parameters, timer, print);
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
  }


#define INSTANTIATE(dim) template void run_to_target<dim>(const Parameters &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
