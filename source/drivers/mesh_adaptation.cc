/* ---------------------------------------------------------------------
 * A mesh adapted to the whole run ('Mesh adaptation/Cycles' > 0).
 *
 * Each cycle runs the scene (a pilot: quiet, in adaptation-cycle-c) on the
 * mesh of the cycles before, and gathers up to three indicators per cell
 * ('Mesh adaptation/Indicators') at 20 steps spread over the run:
 *   - Kelly's indicator of the displacement u_n: the V-norm of u at T is
 *     the error a user reads;
 *   - Kelly's indicator of the velocity w_n, the scheme's unknown, in which
 *     the waves and the slip front move;
 *   - at Gamma_3, the variation of the slip rate over the cell's face,
 *     times the square root of the face's size: the slip rate changes
 *     fastest at the slip front.
 * Each is the largest over the steps, not the sum: the error at T carries
 * the errors of every step, so a front that passes a cell once must refine
 * it as much as one that stays, and a sum would favour cells where
 * something happens long over cells where it happens briefly (and grow
 * with the number of steps). Each is then divided by its largest value
 * over the cells: the three have different units and are compared as
 * shares of their worst cell; a cell's indicator is the largest of its
 * shares. The default is Kelly's of u alone: on the paper's scene the
 * other two spent unknowns on the slip zone that did not lower the V-error
 * at T (bench/adapted_mesh.md).
 *
 * The cells with the largest indicators are refined (a fraction of the
 * cells, or as many as reach the target number of unknowns at the last
 * cycle by equal factors), those with the smallest coarsened, at most
 * 'Max levels' beyond the scene's coarsest cells and never coarser than
 * them. The scene then runs once more on the adapted mesh, with its own
 * output; K is factorised once, as on any mesh.
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/error_estimator.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>
#include <core/mesh_plan.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <drivers/error_estimate.h>
#include <drivers/mesh_adaptation.h>
#include <drivers/scene_variant.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>

namespace Contact
{
  namespace
  {
    // What an adaptation writes into its output directory: the cycles'
    // table, the adapted mesh's cycles, and the pilots' runs (kept by the
    // run on the adapted mesh).
    const ResultFiles
      adaptation_files("adaptation\\.txt|adaptation\\.csv|adapted_mesh\\.txt");
    const ResultDirectories cycle_runs("adaptation-cycle-[0-9]+", true);
    const ResultFiles indicator_files("indicators_[0-9]+(\\.[0-9]+)?\\.p?vtu");

    // The shares of the indicators are compared after rounding to this
    // resolution, which makes it unlikely that the cells chosen depend on
    // the round-off of the solves (which differs between one and several
    // processes): it decides only where a share lies within round-off of a
    // rounding boundary. What guarantees one mesh for every run of a plan
    // is the plan (adapted_mesh.txt), not the rounding.
    constexpr double share_resolution = 1e-6;

    // The indicators are evaluated at most at this many steps spread over a
    // pilot (every ceil(N / 20)-th, and the last): Kelly's estimator at every
    // step cost a pilot on the paper's scene more than the run on the adapted
    // mesh.
    constexpr unsigned int indicator_samples = 20;

    std::ostream &console()
    {
      static std::ofstream dropped;
      return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? std::cout :
                                                                     dropped;
    }


    // @sect3{The indicators}

    // The indicators of a mesh adaptation (the file's head) at the state of
    // one step, as shares, and the choice of cells from them. A pilot takes
    // them at many steps (PilotIndicators), a run that adapts during itself
    // at the step of each adaptation (AdaptationDuringRun).
    template <int dim>
    class MeshIndicators : public Postprocessor<dim>
    {
    public:
      MeshIndicators(const MeshAdaptationParameters &parameters,
                     unsigned int                   &coarsest_level)
        : adaptation(parameters)
        , base_level(coarsest_level)
      {}

      void initialize() override
      {
        index_friction_nodes();
        const Triangulation<dim> &mesh = *this->space().triangulation;
        unsigned int coarsest = std::numeric_limits<unsigned int>::max();
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            coarsest = std::min<unsigned int>(coarsest, cell->level());
        coarsest =
          Utilities::MPI::min(coarsest, this->space().mpi_communicator);
        // The first pilot, or a run adapting during itself, starts from the
        // scene's mesh.
        if (coarsest_is_scene_mesh())
          base_level = coarsest;
      }

    protected:
      virtual bool coarsest_is_scene_mesh() const = 0;

      void index_friction_nodes()
      {
        node_of_dof.clear();
        const auto &nodes = this->friction_solver().boundary().nodes;
        for (unsigned int p = 0; p < nodes.size(); ++p)
          node_of_dof[nodes[p].dofs[0]] = p;
      }

      // The chosen indicators of the state now, per active cell, into
      // `fields` as the largest of what they hold and the new values.
      void take_indicators(std::array<Vector<float>, 3> &fields) const
      {
        const DiscreteSpace<dim> &space = this->space();
        const std::map<types::boundary_id, const Function<dim> *> no_neumann;
        Vector<float>     estimate(space.triangulation->n_active_cells());
        const VectorType *state_fields[] = {&this->state().displacement,
                                            &this->state().velocity};
        for (unsigned int field = 0; field < 2; ++field)
          if (adaptation.indicators[field])
            {
              KellyErrorEstimator<dim>::estimate(*space.mapping,
                                                 space.dof_handler,
                                                 space.face_quadrature,
                                                 no_neumann,
                                                 space.ghosted(
                                                   *state_fields[field]),
                                                 estimate);
              keep_largest(estimate, fields[field]);
            }
        if (adaptation.indicators[2])
          {
            slip_rate_variation(estimate);
            keep_largest(estimate, fields[2]);
          }
      }

      static void keep_largest(const Vector<float> &estimate,
                               Vector<float>       &field)
      {
        for (unsigned int c = 0; c < field.size(); ++c)
          field[c] = std::max(field[c], estimate[c]);
      }

      // sqrt(size of the face) (max - min of the slip rates of its friction
      // nodes), on the cells with a face on Gamma_3; 0 elsewhere.
      void slip_rate_variation(Vector<float> &estimate) const
      {
        estimate                         = 0;
        const DiscreteSpace<dim> &space  = this->space();
        const FiniteElement<dim> &fe     = space.fe;
        const auto               &gamma3 = this->friction_solver().boundary();
        const Vector<double>     &slip_velocity =
          this->friction_solver().state().slip_velocity;
        const std::vector<types::boundary_id> &ids =
          this->parameters().boundary.contact_ids;
        const std::set<types::boundary_id> contact_ids(ids.begin(), ids.end());
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : space.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  contact_ids.count(cell->face(f)->boundary_id()) != 0)
                {
                  cell->get_dof_indices(dofs);
                  double lowest  = std::numeric_limits<double>::max();
                  double highest = -lowest;
                  for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
                    {
                      // Other components, hanging nodes and clamped nodes
                      // are no friction nodes.
                      const auto node =
                        node_of_dof.find(dofs[fe.face_to_cell_index(j, f)]);
                      if (node == node_of_dof.end())
                        continue;
                      const double rate =
                        gamma3.nodes[node->second]
                          .tangential_vector(slip_velocity, node->second)
                          .norm();
                      lowest  = std::min(lowest, rate);
                      highest = std::max(highest, rate);
                    }
                  if (highest >= lowest)
                    estimate[cell->active_cell_index()] =
                      std::max<float>(estimate[cell->active_cell_index()],
                                      std::sqrt(cell->face(f)->diameter()) *
                                        (highest - lowest));
                }
      }

      // Each indicator as a share of its largest value over the cells,
      // rounded to share_resolution; a cell's is the largest of its three.
      Vector<float> shares(const std::array<Vector<float>, 3> &fields) const
      {
        Vector<float> result(fields[0].size());
        for (const Vector<float> &field : fields)
          {
            // An indicator not chosen stays 0.
            const double worst =
              Utilities::MPI::max(static_cast<double>(field.linfty_norm()),
                                  this->space().mpi_communicator);
            if (!(worst > 0))
              continue;
            for (unsigned int c = 0; c < field.size(); ++c)
              result[c] = std::max<float>(result[c],
                                          std::round(field[c] / worst /
                                                     share_resolution) *
                                            share_resolution);
          }
        return result;
      }

      // Flags the cells with the largest and the smallest indicators,
      // within the levels allowed.
      void flag_cells(const Vector<float> &indicator,
                      const double         refine_fraction) const
      {
        Triangulation<dim> &mesh = *this->space().triangulation;
        auto               *distributed =
          dynamic_cast<parallel::distributed::Triangulation<dim> *>(&mesh);
        AssertThrow(distributed != nullptr,
                    ExcInternalError("Mesh adaptation needs p4est's mesh."));
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          *distributed,
          indicator,
          refine_fraction,
          adaptation.coarsen_fraction);
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              if (static_cast<unsigned int>(cell->level()) >=
                  base_level + adaptation.max_levels)
                cell->clear_refine_flag();
              if (static_cast<unsigned int>(cell->level()) <= base_level)
                cell->clear_coarsen_flag();
            }
      }

      // The indicators, their shares and the cells chosen (1 refined, -1
      // coarsened), as indicators_<number>.pvtu.
      void write_indicators(const std::array<Vector<float>, 3> &fields,
                            const Vector<float>                &indicator,
                            const unsigned int                  number,
                            const unsigned int n_digits = 5) const
      {
        const DiscreteSpace<dim> &space = this->space();
        Vector<float>             chosen(indicator.size());
        for (const auto &cell : space.triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            chosen[cell->active_cell_index()] = cell->refine_flag_set()  ? 1 :
                                                cell->coarsen_flag_set() ? -1 :
                                                                           0;
        DataOut<dim> data_out;
        data_out.attach_dof_handler(space.dof_handler);
        const char *names[] = {"kelly_displacement",
                               "kelly_velocity",
                               "slip_rate_variation"};
        for (unsigned int i = 0; i < 3; ++i)
          data_out.add_data_vector(fields[i],
                                   names[i],
                                   DataOut<dim>::type_cell_data);
        data_out.add_data_vector(indicator,
                                 "indicator",
                                 DataOut<dim>::type_cell_data);
        data_out.add_data_vector(chosen,
                                 "refine_1_coarsen_minus_1",
                                 DataOut<dim>::type_cell_data);
        data_out.build_patches(*space.mapping);
        data_out.write_vtu_with_pvtu_record(
          this->parameters().output.directory + "/",
          "indicators",
          number,
          space.mpi_communicator,
          n_digits);
      }

      const MeshAdaptationParameters                 &adaptation;
      unsigned int                                   &base_level;
      std::map<types::global_dof_index, unsigned int> node_of_dof;
    };


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

      void initialize() override
      {
        MeshIndicators<dim>::initialize();
        for (Vector<float> &field : largest)
          field.reinit(this->space().triangulation->n_active_cells());
      }

      // At indicator_samples steps spread over the run and at its last.
      void after_step(const StepStatistics &) override
      {
        const unsigned int step = this->state().step_number,
                           n    = this->n_time_steps();
        const unsigned int stride =
          (n + indicator_samples - 1) / indicator_samples;
        if (step % stride == 0 || step == n)
          this->take_indicators(largest);
      }

      void end() override
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


    // @sect3{Adapting during the run}

    // 'Mesh adaptation/Interval' > 0: at each adaptation the indicators of
    // the step alone choose the cells (the mesh follows the solution, so
    // what happened before on the old mesh does not count), the problem
    // moves to the new mesh (ContactProblem::transfer_to_adapted_mesh()),
    // and this postprocessor writes indicators_<step>.pvtu, a row of
    // adaptation.csv (the step, the mesh, and the kinetic plus elastic
    // energy before and after the transfer) and adapted_mesh.txt (the
    // mesh's cycles so far; a checkpoint stores them too).
    template <int dim>
    class AdaptationDuringRun : public MeshIndicators<dim>
    {
    public:
      explicit AdaptationDuringRun(const MeshAdaptationParameters &parameters)
        : MeshIndicators<dim>(parameters, scene_coarsest_level)
      {}

      // A resumed run has the rows up to its checkpoint (its state).
      void start(const bool) override
      {
        write_files();
      }

      // The cells of the next mesh (the flags on the mesh now), with the
      // step's indicators written out.
      void choose_cells()
      {
        std::array<Vector<float>, 3> fields;
        for (Vector<float> &field : fields)
          field.reinit(this->space().triangulation->n_active_cells());
        this->take_indicators(fields);
        const Vector<float> indicator = this->shares(fields);
        this->flag_cells(indicator, refine_fraction());
        // With the VTU output, whose interval the user chose for files.
        if (this->parameters().output.template entry<unsigned int>(
              "VTU interval") > 0)
          this->write_indicators(fields, indicator, this->state().step_number);
      }

      void before_mesh_change() override
      {
        energy_before =
          this->state().energy.kinetic + this->state().energy.elastic;
      }

      void mesh_changed() override
      {
        this->index_friction_nodes();
        const StepState   &state = this->state();
        std::ostringstream row;
        row << state.step_number << ',' << std::setprecision(12) << state.time
            << ',' << this->space().triangulation->n_global_active_cells()
            << ',' << this->space().dof_handler.n_dofs() << ',' << energy_before
            << ',' << state.energy.kinetic + state.energy.elastic;
        rows.push_back(row.str());
        write_files();
      }

      // The scene's coarsest level and the table's rows are part of the
      // run's state.
      void save(boost::archive::binary_oarchive &archive) override
      {
        archive &this->base_level &rows;
      }

      void load(boost::archive::binary_iarchive &archive) override
      {
        archive &this->base_level &rows;
      }

    private:
      bool coarsest_is_scene_mesh() const override
      {
        return true;
      }

      // The entry's fraction, or with a target number of unknowns at most
      // as many cells as bring the mesh to the target's share of cells:
      // refining a share r of N cells adds (2^dim - 1) r N cells,
      // coarsening a share c removes about (2^dim - 1) / 2^dim c N, so at
      // the target r = c / 2^dim keeps the size while the cells still move
      // with the solution (deal.II's cap on the cells would refine none
      // there, and the mesh would stop following it).
      double refine_fraction() const
      {
        const MeshAdaptationParameters &settings = this->adaptation;
        if (settings.target_unknowns == 0)
          return settings.refine_fraction;
        const double cells = static_cast<double>(
          this->space().triangulation->n_global_active_cells());
        const double target_cells =
          settings.target_unknowns * cells /
          static_cast<double>(this->space().dof_handler.n_dofs());
        const double children = (1 << dim);
        const double share =
          (target_cells - cells +
           settings.coarsen_fraction * cells * (children - 1) / children) /
          ((children - 1) * cells);
        return std::clamp(share, 0., settings.refine_fraction);
      }

      // Written whole: the table has a row per adaptation, not per step.
      void write_files() const
      {
        if (Utilities::MPI::this_mpi_process(this->space().mpi_communicator) !=
            0)
          return;
        const std::string &directory = this->parameters().output.directory;
        std::ofstream(directory + "/adapted_mesh.txt")
          << this->problem().get_mesh_plan().text();
        std::ofstream table(directory + "/adaptation.csv");
        table << "after_step,time,cells,unknowns,energy_before,energy_after\n";
        for (const std::string &row : rows)
          table << row << '\n';
      }

      // The coarsest level of the scene's mesh (a resumed run has it from
      // its checkpoint).
      unsigned int             scene_coarsest_level = 0;
      std::vector<std::string> rows;
      double                   energy_before = 0;
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
        if (resumed || Utilities::MPI::this_mpi_process(
                         this->space().mpi_communicator) != 0)
          return;
        const std::string &directory = this->parameters().output.directory;
        std::ofstream(directory + "/adapted_mesh.txt") << plan.text();
        std::ofstream(directory + "/adaptation.txt") << table;
      }

    private:
      const MeshPlan    plan;
      const std::string table;
    };
  } // namespace


  // @sect3{adapt_mesh_by_pilots}

  template <int dim>
  MeshPlan adapt_mesh_by_pilots(const Parameters &scene, std::string &table)
  {
    const MeshAdaptationParameters &adaptation = scene.mesh_adaptation;
    const std::string              &directory  = scene.output.directory;
    MeshPlan                        plan;
    TableHandler                    cycles;
    unsigned int                    base_level = 0;
    for (unsigned int cycle = 0; cycle < adaptation.cycles; ++cycle)
      {
        const std::string   name = "adaptation-cycle-" + std::to_string(cycle);
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
        console() << "Mesh adaptation: cycle " << cycle << ": " << cells
                  << " cells, " << sub_run_line(summary, log) << "; refines "
                  << plan.refined.back().size() << " cells, coarsens "
                  << plan.coarsened.back().size() << std::endl;
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


  // @sect3{adapt_during_run}

  template <int dim>
  void adapt_during_run(ContactProblem<dim>            &problem,
                        const MeshAdaptationParameters &adaptation)
  {
    auto chooser = std::make_unique<AdaptationDuringRun<dim>>(adaptation);
    AdaptationDuringRun<dim> &cells = *chooser;
    problem.add_postprocessor(std::move(chooser));
    problem.adapt_mesh_during_run(adaptation.interval,
                                  [&cells]() { cells.choose_cells(); });
  }


  // @sect3{run_with_mesh_adaptation}

  template <int dim>
  void run_with_mesh_adaptation(const Parameters &scene)
  {
    if (scene.mesh_adaptation.interval > 0)
      {
        if (scene.accuracy.estimate_error)
          {
            run_with_error_estimate<dim>(scene, {}, MeshPlan());
            return;
          }
        ContactProblem<dim> problem(scene);
        adapt_during_run(problem, scene.mesh_adaptation);
        problem.run();
        return;
      }
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

    // The run on the adapted mesh keeps the pilots in its directory.
    Parameters adapted   = scene;
    adapted.keeps_pilots = true;
    if (scene.accuracy.estimate_error)
      {
        // The estimate's runs clear the directory first: the files of the
        // adaptation are written after them.
        run_with_error_estimate<dim>(adapted, {}, plan);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          {
            std::ofstream(scene.output.directory + "/adapted_mesh.txt")
              << plan.text();
            std::ofstream(scene.output.directory + "/adaptation.txt") << table;
          }
        return;
      }
    ContactProblem<dim> problem(adapted);
    problem.adapt_mesh(plan);
    problem.add_postprocessor(
      std::make_unique<AdaptationFiles<dim>>(plan, table));
    problem.run();
  }


#define INSTANTIATE(dim)                                               \
  template MeshPlan adapt_mesh_by_pilots<dim>(const Parameters &,      \
                                              std::string &);          \
  template void     run_with_mesh_adaptation<dim>(const Parameters &); \
  template void     adapt_during_run<dim>(ContactProblem<dim> &,       \
                                      const MeshAdaptationParameters &);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
