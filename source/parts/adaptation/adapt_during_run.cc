/* ---------------------------------------------------------------------
 * A mesh adapted during the run ('Mesh adaptation/Interval' > 0;
 * include/parts/adaptation/adapt_during_run.h).
 *
 * After every Interval-th step the indicators of that step
 * (mesh_indicators.h) choose the cells to refine and to coarsen, at most
 * 'Max levels' beyond the scene's coarsest cells and never coarser than
 * them, and the problem moves its state to the new mesh
 * (ContactProblem::transfer_to_adapted_mesh()).
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>

#include <base/dimensions.h>
#include <core/output_directory.h>
#include <parts/adaptation/adapt_during_run.h>
#include <parts/adaptation/mesh_indicators.h>
#include <parts/adaptation/mesh_adaptation_parameters.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace Contact
{
  namespace
  {
    // What a run adapting during itself writes into its output directory.
    const ResultFiles adaptation_files("adaptation\\.csv|adapted_mesh\\.txt");


    // @sect3{The indicators during the run}

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
        if (this->parameters().template part<unsigned int>("VTU output") > 0)
          this->write_indicators(fields, indicator, this->state().step_number);
      }

      void mesh_event(const MeshEvent event) override
      {
        MeshIndicators<dim>::mesh_event(event);
        if (event == MeshEvent::before_change)
          energy_before =
            this->state().energy.kinetic + this->state().energy.elastic;
        else if (event == MeshEvent::after_change)
          add_row();
      }

      // The scene's coarsest level and the table's rows are part of the
      // run's state.
      void checkpoint(CheckpointArchive &archive) override
      {
        archive &this->base_level &rows;
      }

    private:
      bool coarsest_is_scene_mesh() const override
      {
        return true;
      }

      // The row of adaptation.csv of the change of the mesh just made.
      void add_row()
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
  } // namespace


  // @sect3{adapt_during_run}

  template <int dim>
  void adapt_during_run(ContactProblem<dim> &problem,
                        const Parameters    &parameters)
  {
    const MeshAdaptationParameters &adaptation =
      MeshAdaptationParameters::of(parameters);
    if (adaptation.interval == 0)
      return;
    auto chooser = std::make_unique<AdaptationDuringRun<dim>>(adaptation);
    AdaptationDuringRun<dim> &cells = *chooser;
    problem.add_postprocessor(std::move(chooser));
    problem.adapt_mesh_during_run(adaptation.interval,
                                  [&cells]() { cells.choose_cells(); });
  }


#define INSTANTIATE(dim)                                     \
  template void adapt_during_run<dim>(ContactProblem<dim> &, \
                                      const Parameters &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
