/* ---------------------------------------------------------------------
 * A mesh adapted to the whole run ('Mesh adaptation/Cycles' > 0).
 *
 * Each cycle runs the scene (a pilot: quiet, in adaptation-cycle-c) on the
 * mesh of the cycles before, and gathers up to three indicators per cell
 * ('Mesh adaptation/Indicators', mesh_indicators.h) at 20 steps spread
 * over the run, each the largest over the steps.
 *
 * The cells with the largest indicators are refined (a fraction of the
 * cells, or as many as reach the target number of unknowns at the last
 * cycle by equal factors), those with the smallest coarsened, at most
 * 'Max levels' beyond the scene's coarsest cells and never coarser than
 * them. The scene then runs once more on the adapted mesh, with its own
 * output, by the study that this one wraps; K is factorised once, as on
 * any mesh.
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>
#include <core/mesh_plan.h>
#include <core/output_directory.h>
#include <parts/studies/mesh_adaptation.h>
#include <parts/adaptation/mesh_indicators.h>
#include <parts/studies/scene_variant.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/sub_run.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace Contact
{
  namespace
  {
    // What an adaptation by pilots writes into its output directory: the
    // cycles' table, the adapted mesh's cycles, and the pilots' runs (kept
    // by the run on the adapted mesh).
    const ResultFiles adaptation_files("adaptation\\.txt|adapted_mesh\\.txt");
    const ResultDirectories cycle_runs("adaptation-cycle-[0-9]+", true);

    // The indicators are evaluated at most at this many steps spread over a
    // pilot (every ceil(N / 20)-th, and the last): Kelly's estimator at every
    // step cost a pilot on the paper's scene more than the run on the adapted
    // mesh.
    constexpr unsigned int indicator_samples = 20;


    // @sect3{The indicators of a pilot}

    // Gathers the indicators over the pilot's steps and, at its end,
    // chooses the cells of the next cycle, adds them to the plan and writes
    // the indicators (indicators_0.pvtu). It sets the refinement flags of
    // the pilot's mesh to choose, reads them back and clears them: the
    // pilot's results are not touched.
    template <int dim>
    class PilotIndicators : public MeshIndicators<dim>
    {
    public:
      PilotIndicators(const MeshAdaptationParameters &parameters,
                      const unsigned int              n_cycles_left,
                      unsigned int                   &coarsest_level,
                      MeshPlan                       &adapted_mesh)
        : MeshIndicators<dim>(parameters, coarsest_level)
        , cycles_left(n_cycles_left)
        , plan(adapted_mesh)
      {}

      void mesh_event(const MeshEvent event) override
      {
        MeshIndicators<dim>::mesh_event(event);
        if (event == MeshEvent::initial)
          for (Vector<float> &field : largest)
            field.reinit(this->space().triangulation->n_active_cells());
      }

      // At indicator_samples steps spread over the run and at its last.
      void after_step(const StepStatistics &, const StepEnd end) override
      {
        if (end != StepEnd::whole_step)
          return;
        const unsigned int step = this->state().step_number,
                           n    = this->n_time_steps();
        const unsigned int stride =
          (n + indicator_samples - 1) / indicator_samples;
        if (step % stride == 0 || step == n)
          this->take_indicators(largest);
      }

      void finish(RunSummary &) override
      {
        Triangulation<dim> &mesh      = *this->space().triangulation;
        const Vector<float> indicator = this->shares(largest);
        this->flag_cells(indicator, refine_fraction());
        plan.add_cycle_from_flags(mesh);
        this->write_indicators(largest, indicator, 0, 1);
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->clear_refine_flag();
              cell->clear_coarsen_flag();
            }
      }

    private:
      bool coarsest_is_scene_mesh() const override
      {
        return plan.n_cycles() == 0;
      }

      // The fraction of the cells to refine: the entry's, or with a target
      // number of unknowns the share that multiplies them by
      // (target / now)^(1 / cycles left), each refined cell adding
      // 2^dim - 1 cells and unknowns growing like cells.
      double refine_fraction() const
      {
        const MeshAdaptationParameters &settings = this->adaptation;
        if (settings.target_unknowns == 0)
          return settings.refine_fraction;
        const double now =
          static_cast<double>(this->space().dof_handler.n_dofs());
        const double factor =
          std::pow(settings.target_unknowns / now, 1. / cycles_left);
        return std::clamp((factor - 1.) / ((1 << dim) - 1),
                          0.,
                          1. - settings.coarsen_fraction);
      }

      const unsigned int cycles_left;
      MeshPlan          &plan;
      // Kelly of u, Kelly of w, the slip rate's variation: the largest
      // over the steps so far, per active cell.
      std::array<Vector<float>, 3> largest;
    };


    // @sect3{The files of the run on the adapted mesh}

    // Written when the run on the adapted mesh starts (after it has
    // cleared its directory): the cycles of the mesh and their table. A
    // resumed run keeps those of the run it continues.
    template <int dim>
    class AdaptationFiles : public Postprocessor<dim>
    {
    public:
      AdaptationFiles(const MeshPlan &adapted_mesh, const std::string &cycles)
        : plan(adapted_mesh)
        , table(cycles)
      {}

      void start(const bool resumed) override
      {
        if (resumed)
          return;
        const std::string &directory = this->parameters().output.directory;
        write_study_file(directory + "/adapted_mesh.txt", plan.text());
        write_study_file(directory + "/adaptation.txt", table);
      }

    private:
      const MeshPlan    plan;
      const std::string table;
    };


    // @sect3{adapt_mesh_by_pilots}

    // Runs the pilots (each in its own subdirectory adaptation-cycle-c) and
    // returns the adapted mesh's cycles, and the table of the cycles as
    // text.
    template <int dim>
    MeshPlan adapt_mesh_by_pilots(const Parameters &scene, std::string &table)
    {
      const MeshAdaptationParameters &adaptation =
        MeshAdaptationParameters::of(scene);
      const std::string &directory = scene.output.directory;
      MeshPlan           plan;
      TableHandler       cycles;
      unsigned int       base_level = 0;
      for (unsigned int cycle = 0; cycle < adaptation.cycles; ++cycle)
        {
          const std::string name = "adaptation-cycle-" + std::to_string(cycle);
          ContactProblem<dim> pilot(parameters_of(scene,
                                                  {0,
                                                   scene.time.n_steps(),
                                                   scene.geometry.fe_degree,
                                                   directory + "/" + name,
                                                   true}));
          pilot.adapt_mesh(plan);
          pilot.add_postprocessor(std::make_unique<PilotIndicators<dim>>(
            adaptation, adaptation.cycles - cycle, base_level, plan));
          const std::string log = directory + "/" + name + "/console.log";
          const RunSummary  summary =
            run_onto<dim>(pilot, nullptr, 0, log).summary;
          const auto cells =
            pilot.get_dof_handler().get_triangulation().n_global_active_cells();
          study_console() << "Mesh adaptation: cycle " << cycle << ": " << cells
                          << " cells, " << sub_run_line(summary, log)
                          << "; refines " << plan.refined.back().size()
                          << " cells, coarsens " << plan.coarsened.back().size()
                          << std::endl;
          cycles.add_value("cycle", cycle);
          cycles.add_value("cells", static_cast<unsigned long long>(cells));
          cycles.add_value("unknowns",
                           static_cast<unsigned long long>(summary.n_dofs));
          cycles.add_value("wall time [s]", summary.wall_time);
          cycles.set_precision("wall time [s]", 2);
          cycles.add_value("refined", plan.refined.back().size());
          cycles.add_value("coarsened", plan.coarsened.back().size());
        }
      std::ostringstream text;
      cycles.write_text(text, TableHandler::org_mode_table);
      table = text.str();
      return plan;
    }
  } // namespace


  // @sect3{The study}

  template <int dim>
  PilotAdaptation<dim>::PilotAdaptation(
    std::unique_ptr<Study<dim>> run_on_adapted_mesh)
    : adapted_run(std::move(run_on_adapted_mesh))
  {}


  template <int dim>
  RunResult PilotAdaptation<dim>::run(const Parameters      &scene,
                                      const StudyInput<dim> &input)
  {
    // A resumed run is built on the mesh its checkpoint stores: the pilots
    // do not run again.
    MeshPlan    plan;
    std::string table;
    if (!scene.output.resume)
      {
        // The earlier results go before the pilots run (a run killed among
        // them must leave nothing that --resume would take for its own),
        // and the directory is locked while they run; the run on the
        // adapted mesh locks it again.
        const std::shared_ptr<const int> lock =
          lock_output_directory(scene.output.directory, MPI_COMM_WORLD);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          remove_results(scene.output.directory, false, MPI_COMM_WORLD);
        plan = adapt_mesh_by_pilots<dim>(scene, table);
      }

    // The run on the adapted mesh keeps the pilots in its directory, and
    // writes the files of the adaptation once it has cleared it.
    Parameters adapted   = scene;
    adapted.keeps_pilots = true;
    return adapted_run->run(
      adapted,
      {plan,
       input.orders,
       [plan, table](ContactProblem<dim> &problem, const Parameters &) {
         problem.add_postprocessor(
           std::make_unique<AdaptationFiles<dim>>(plan, table));
       }});
  }


#define INSTANTIATE(dim) template class PilotAdaptation<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
