/* ---------------------------------------------------------------------
 * The pilots of a target error (include/parts/studies/target_error_pilots.h).
 *
 * The error of the scheme at T behaves as e(h, k) = E_h h^p + E_k k^q
 * (Corollary 5.3, (5.26)). The pilots measure the two terms separately on
 * the scene as given (h = H, k = K): the runs with H, 2H and 4H at K give
 * the space part and its order by Richardson extrapolation
 * (richardson.h), the runs with K, 2K and 4K at H the time part and its
 * order, each for every element degree the scene allows (the time part
 * once: it does not depend on the degree to leading order). Their wall
 * times fit a cost model a + b * unknowns * steps per degree.
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <base/dimensions.h>
#include <parts/studies/scene_variant.h>
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <parts/studies/reference_interpolation.h>
#include <parts/studies/richardson.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/target_error_pilots.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <list>
#include <memory>

namespace Contact
{
  namespace TargetPilots
  {
    namespace
    {
      // The pilots' runs in a target's output directory (kept by the run
      // the target chose).
      const ResultDirectories pilot_runs("pilot-q[12]-(adapted-)?[24]?h-[24]?k",
                                         true);


      // @sect3{The fit of a direction}

      // The DirectionFit of the three pilots f, m and c for `quantity`, with
      // the order at most `max_order`.
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
        const double order =
          !field && d_fine * d_coarse < 0 ? nan : estimate.measured_orders[0];
        // No error seen in this direction: it limits nothing, and has no
        // order.
        if (d_fine == 0 && d_coarse == 0)
          return {0., nan, "the same on the three pilots"};
        // An order below what the scheme shows in the asymptotic range (or
        // none) is never raised: it would make the predicted error fall
        // faster than measured. This direction predicts nothing.
        if (!(order >= min_plausible_order))
          return {nan,
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
                    number_text(max_order) +
                    " (the scheme gives at most that)"};
        return {estimate.error, order, ""};
      }

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


      // @sect3{Running the pilots}

      // The pilots of one degree and mesh family as they run, from `first`
      // on in `pilots`: each keeps its state at each of its steps on the
      // mesh of the first (N0 is a multiple of 4, parameters.cc), whose
      // problem stays for the comparisons.
      template <int dim>
      struct PilotFamily
      {
        void run(const unsigned int space_factor,
                 const unsigned int time_factor)
        {
          const std::string name =
            "pilot-q" + std::to_string(degree) + "-" +
            (adapted ? "adapted-" : "") +
            (space_factor > 1 ? std::to_string(space_factor) : "") + "h-" +
            (time_factor > 1 ? std::to_string(time_factor) : "") + "k";
          const std::string directory =
            parameters.output.directory + "/" + name;
          const Parameters &own = own_parameters.emplace_back(
            parameters_of(parameters,
                          {-static_cast<int>(space_factor / 2),
                           parameters.time.n_steps() / time_factor,
                           degree,
                           directory,
                           true,
                           adapted}));
          auto problem = std::make_unique<ContactProblem<dim>>(own);
          equip(*problem, own);
          pilots.push_back({name,
                            degree,
                            adapted,
                            run_onto(*problem,
                                     interpolate.get(),
                                     adapted ? 0 : 1,
                                     directory + "/console.log")});
          pilots.back().mesh_changes = problem->get_mesh_plan().n_cycles();
          print("Target error: pilot " + name + ": " +
                sub_run_line(pilots.back().run.summary,
                             directory + "/console.log"));
          // The cost model, and so the choice, must be the same on every
          // process.
          double &wall_time = pilots.back().run.summary.wall_time;
          wall_time         = Utilities::MPI::max(wall_time, MPI_COMM_WORLD);
          if (!base)
            {
              base = std::move(problem);
              interpolate =
                std::make_unique<ReferenceInterpolation<dim>>(*base);
            }
        }

        // The fit of the family's first pilot and its `medium` and
        // `coarse` ones (counted from the first).
        DirectionFit fit(const std::size_t  medium,
                         const std::size_t  coarse,
                         const std::string &quantity,
                         const double       max_order) const
        {
          return fit_direction(*base,
                               pilots[first],
                               pilots[first + medium],
                               pilots[first + coarse],
                               quantity,
                               max_order);
        }

        // From the pilots of the first degree (H at K, 2H, 4H, 2K and 4K):
        // the size of the quantity on the first (the scale of a relative
        // target), and how the space and the time error of the V-norm
        // combine, from the angle between what doubling h and what doubling
        // k changes. A quantity's two errors add (they may cancel on the
        // pilots and not later).
        void measure_size_and_cosine(const std::string &quantity,
                                     PilotResults      &results) const
        {
          const RunAtTimes &own = pilots[first].run;
          results.size          = std::abs(quantity_of(own.summary, quantity));
          if (quantity == worst_V_error)
            {
              results.size = own.summary.displacement_V_norm;
              for (const VectorType &u : own.history)
                results.size = std::max(results.size, base->strain_norm(u));
            }
          const auto norm = [&](const std::size_t a, const std::size_t b) {
            return strain_distance(*base,
                                   pilots[first + a].run.displacement,
                                   pilots[first + b].run.displacement);
          };
          const double s = norm(0, 1), t = norm(0, 3), across = norm(3, 1);
          if ((quantity == V_norm || quantity == worst_V_error) && s > 0 &&
              t > 0)
            results.cosine =
              std::clamp((s * s + t * t - across * across) / (2 * s * t),
                         0.,
                         1.);
        }

        // Whether a pilot's mesh changed during its run.
        bool some_mesh_changed() const
        {
          bool changed = false;
          for (std::size_t i = first; i < pilots.size(); ++i)
            changed = changed || pilots[i].mesh_changes > 0;
          return changed;
        }

        const Parameters                               &parameters;
        const unsigned int                              degree;
        const bool                                      adapted;
        const Equipment<dim>                           &equip;
        std::vector<Pilot>                             &pilots;
        const std::function<void(const std::string &)> &print;
        const std::size_t                               first;
        // The pilots' parameters outlive the problems, whose adaptation
        // keeps a reference to them.
        std::list<Parameters> own_parameters = {};
        // The first pilot's run, onto whose mesh the others' states are
        // interpolated.
        std::unique_ptr<ContactProblem<dim>>         base        = nullptr;
        std::unique_ptr<ReferenceInterpolation<dim>> interpolate = nullptr;
      };


      // The pilots of one degree and mesh family: H, 2H, 4H at K, and for
      // the first degree on uniform meshes also 2K and 4K at H (the time
      // part, shared by the degrees and by both families: to leading order
      // it does not depend on the mesh). The adapted family starts from the
      // same meshes and adapts them during the run towards 'Target unknowns'
      // times 1, 1/2^dim and 1/4^dim; its runs keep no states over time (no
      // one mesh holds them).
      template <int dim>
      void run_pilots_of_degree(
        const Parameters                               &parameters,
        const unsigned int                              degree,
        const bool                                      adapted,
        const bool                                      with_time,
        const Equipment<dim>                           &equip,
        PilotResults                                   &results,
        const std::function<void(const std::string &)> &print)
      {
        const std::string quantity =
          AccuracyParameters::of(parameters).target_quantity.name();
        PilotFamily<dim> family{parameters,
                                degree,
                                adapted,
                                equip,
                                results.pilots,
                                print,
                                results.pilots.size()};
        family.run(1, 1);
        family.run(2, 1);
        family.run(4, 1);
        // The V-norm converges with order `degree` in h at best, a value at a
        // point or an integral with one more; the scheme is of first order in
        // time ((5.26)).
        const bool field = quantity == V_norm || quantity == worst_V_error;
        results.models.push_back(
          {degree,
           adapted,
           family.fit(1, 2, V_norm, degree),
           family.fit(1, 2, quantity, degree + (field ? 0 : 1)),
           results.pilots[family.first].run.summary.n_dofs});
        // Pilots whose meshes never changed are uniform ones: no family of
        // their own (a 'Target unknowns' below the start mesh's, or a
        // 'Refine fraction' of 0, refines nothing).
        if (adapted && !family.some_mesh_changed())
          for (DirectionFit *space_fit :
               {&results.models.back().space_V, &results.models.back().space})
            *space_fit = {
              nan,
              nan,
              "its pilots' meshes did not change during the run, no cell met '" +
                Entry::refine_fraction + "' towards '" +
                Entry::target_unknowns + "': no adapted family, no prediction"};
        if (!with_time)
          return;
        family.run(1, 2);
        family.run(1, 4);
        results.time_V = family.fit(3, 4, V_norm, 1.);
        results.time   = family.fit(3, 4, quantity, 1.);
        family.measure_size_and_cosine(quantity, results);
      }
    } // namespace


    // A scene that adapts its mesh during the run has two families of
    // candidates, uniform and adapted meshes, unless the target quantity
    // needs the states over time on one mesh.
    bool has_adapted_family(const Parameters &parameters)
    {
      return MeshAdaptationParameters::of(parameters).interval > 0 &&
             AccuracyParameters::of(parameters).target_quantity.name() !=
               worst_V_error;
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
      if (!adapted || MeshAdaptationParameters::of(scene).target_unknowns == 0)
        return own;
      types::global_dof_index pilot_degree = 0, of_scene_degree = 0;
      for (const DegreeModel &model : results.models)
        if (!model.adapted)
          {
            if (model.degree == degree)
              pilot_degree = model.n_dofs;
            if (model.degree == scene.geometry.fe_degree)
              of_scene_degree = model.n_dofs;
          }
      Assert(pilot_degree > 0 && of_scene_degree > 0, ExcInternalError());
      MeshAdaptationParameters::of(own).target_unknowns =
        static_cast<unsigned int>(std::lround(
          double(MeshAdaptationParameters::of(scene).target_unknowns) *
          pilot_degree / of_scene_degree));
      return own;
    }

    template <int dim>
    PilotResults
    run_pilots(const Parameters                               &parameters,
               const Equipment<dim>                           &equipment,
               const std::function<void(const std::string &)> &print)
    {
      Timer timer;
      // Quadratic elements on tetrahedra have no nodal friction weights
      // (scene_parameters.cc): there only degree 1.
      std::vector<unsigned int> degrees = {2, 1};
      if (dim == 3 &&
          (parameters.geometry.cell_shape ==
           GeometryParameters::CellShape::simplex) &&
          !parameters.friction.law->is_frictionless())
        degrees = {1};
      PilotResults results;
      for (const unsigned int degree : degrees)
        run_pilots_of_degree<dim>(parameters,
                                  degree,
                                  false,
                                  degree == degrees.front(),
                                  equipment,
                                  results,
                                  print);
      if (has_adapted_family(parameters))
        for (const unsigned int degree : degrees)
          run_pilots_of_degree<dim>(scene_of(parameters, results, degree, true),
                                    degree,
                                    true,
                                    false,
                                    equipment,
                                    results,
                                    print);
      for (DegreeModel &model : results.models)
        fit_cost(model,
                 results.pilots,
                 AccuracyParameters::of(parameters).cost_model ==
                   AccuracyParameters::CostModel::measured);
      results.wall_time = timer.wall_time();
      return results;
    }


#define INSTANTIATE(dim)                 \
  template PilotResults run_pilots<dim>( \
    const Parameters &,                  \
    const Equipment<dim> &,              \
    const std::function<void(const std::string &)> &);
    CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace TargetPilots
} // namespace Contact
