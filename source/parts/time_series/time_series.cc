/* time_series.csv ('Output/Time series'): one row per step with what the
   step did, the energies, and the columns of the other postprocessors
   (self-checks, momenta, probes, errors). */

#include <core/csv_file.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>

#include <iomanip>

namespace Contact
{
  namespace
  {
    const ResultFiles series_files("time_series\\.csv(\\.tmp)?");

    // @sect4{The entry 'Time series'}

    const std::string series_entry = "Time series";

    const PartEntries own_entries{
      "Output",
      "VTU interval",
      series_entry,
      [](ParameterHandler &prm) {
        prm.declare_entry(series_entry,
                          "true",
                          Patterns::Bool(),
                          "Write time_series.csv, one row per time step.");
      },
      [](ParameterHandler &prm, const Parameters &) -> std::any {
        return prm.get_bool(series_entry);
      }};
  } // namespace


  template <int dim>
  class TimeSeries : public Postprocessor<dim>
  {
  public:
    void start(const bool resumed) override;

    void after_step(const StepStatistics &statistics,
                    const StepEnd         end) override
    {
      if (end == StepEnd::whole_step &&
          this->parameters().template part<bool>("time series"))
        write_row(columns(), statistics);
    }

  private:
    TimeSeriesRow columns() const;
    void write_row(const TimeSeriesRow &row, const StepStatistics &statistics);
    // The energy the transfers to adapted meshes changed is a column of
    // runs that adapt during the run alone.
    bool adapts_during_run() const
    {
      return this->problem().adapts_mesh_during_run();
    }

    CsvFile file;
  };


  // @sect4{TimeSeries::columns}

  // The other postprocessors' columns, in the order of their ranks
  // (collective: every process takes part, the first one writes).
  template <int dim>
  TimeSeriesRow TimeSeries<dim>::columns() const
  {
    TimeSeriesRow row;
    for (const auto &postprocessor : this->postprocessors())
      postprocessor->add_columns(row);
    return row;
  }


  // @sect4{TimeSeries::start}

  // A fresh run writes the header and the row of the initial state.
  template <int dim>
  void TimeSeries<dim>::start(const bool resumed)
  {
    if (!this->parameters().template part<bool>("time series"))
      return;
    const TimeSeriesRow row = columns();
    if (Utilities::MPI::this_mpi_process(this->mpi_communicator()) != 0)
      return;
    std::string header =
      "step,time,convexification_iterations,active_set_iterations,"
      "rejected_accelerations,active_set_cycles,step_cuts,"
      "newton_iterations,newton_fallbacks,solves_with_K,cg_iterations,"
      "n_stick,n_slip,max_slip_rate,friction_force,"
      "kinetic_energy,elastic_energy,external_work,viscous_dissipation,"
      "friction_dissipation,numerical_dissipation";
    if (adapts_during_run())
      header += ",mesh_transfer";
    for (const auto &[name, value] : row.columns)
      header += "," + name;
    file.open(this->parameters().output.directory + "/time_series.csv",
              header,
              resumed,
              this->state().step_number);
    if (!resumed)
      write_row(row, StepStatistics());
  }


  // @sect4{TimeSeries::write_row}

  // One row per step, flushed at once: if a later step fails, the file
  // describes exactly the steps that were computed.
  template <int dim>
  void TimeSeries<dim>::write_row(const TimeSeriesRow  &row,
                                  const StepStatistics &statistics)
  {
    if (!file.is_open())
      return;
    const StepState     &state  = this->state();
    const EnergyBalance &energy = state.energy;
    std::ofstream       &out    = file.stream();
    out << state.step_number << ',' << std::setprecision(12) << state.time
        << ',' << statistics.convexification_iterations << ','
        << statistics.active_set_iterations << ','
        << statistics.rejected_accelerations << ',' << statistics.cycles_cured
        << ',' << statistics.step_cuts << ',' << statistics.newton_iterations
        << ',' << statistics.newton_fallbacks << ',' << statistics.solves_with_K
        << ',' << statistics.cg_iterations << ',' << statistics.n_stick << ','
        << statistics.n_slip << ',' << statistics.max_slip_rate << ','
        << statistics.friction_force << ',' << energy.kinetic << ','
        << energy.elastic << ',' << energy.external_work << ','
        << energy.viscous_dissipation << ',' << energy.friction_dissipation
        << ',' << energy.numerical_dissipation;
    if (adapts_during_run())
      out << ',' << energy.mesh_transfer;
    for (const auto &[name, value] : row.columns)
      out << ',' << value;
    out << '\n';
    file.check();
  }


  namespace
  {
    const PostprocessorRegistration<TimeSeries>
      registration("time series", 80, own_entries);
  }
} // namespace Contact
