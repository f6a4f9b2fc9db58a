/* An output added from outside the program, as doc/tutorial.md's checklist
   "Adding an output" describes: a postprocessor defined in this file alone,
   registered as a part with an entry of its own, with no file of base/,
   core/ or parts/ changed. It keeps the peak of the velocity's
   Euclidean norm over the run ('Output/Velocity peak = true'), puts the peak so
   far into each row of time_series.csv, stores it with a checkpoint and prints
   it when the run ends.

   Checked: its entry is declared in Output right after 'Gamma3 history'
   (the last entry of another part, the place it asked for) and a value
   outside its pattern is refused naming the entry; with the entry true,
   its hooks are called once per step, its peak is the largest norm
   that an independent observer of the same run sees, its column is in
   time_series.csv and its line in the summary; with the entry false, it does
   nothing. */

#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/contact_problem.h>
#include <core/postprocessor.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace Contact;

namespace
{
  const std::string peak_entry = "Velocity peak";

  const PartEntries peak_entries{
    "Output",
    "Gamma3 history",
    peak_entry,
    [](ParameterHandler &prm) {
      prm.declare_entry(peak_entry,
                        "false",
                        Patterns::Bool(),
                        "Print the step of the largest Euclidean norm of the "
                        "nodal velocities.");
    },
    [](ParameterHandler &prm, const Parameters &) -> std::any {
      return prm.get_bool(peak_entry);
    }};

  // What the test reads back of the last run's postprocessor.
  unsigned int whole_steps_seen = 0;
  double       last_peak        = 0;

  template <int dim>
  class VelocityPeak : public Postprocessor<dim>
  {
  public:
    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end != StepEnd::whole_step || !wanted())
        return;
      ++whole_steps_seen;
      if (this->state().velocity.l2_norm() > peak)
        {
          peak      = this->state().velocity.l2_norm();
          peak_step = this->state().step_number;
        }
    }

    void add_columns(TimeSeriesRow &row) const override
    {
      if (wanted())
        row.add("velocity_peak", peak);
    }

    void checkpoint(CheckpointArchive &archive) override
    {
      archive &peak &peak_step;
    }

    void finish(RunSummary &) override
    {
      last_peak = peak;
      if (wanted())
        this->pcout() << "velocity peak at step " << peak_step << std::endl;
    }

    double       peak      = 0;
    unsigned int peak_step = 0;

  private:
    bool wanted() const
    {
      return this->parameters().template part<bool>("velocity peak");
    }
  };

  const PostprocessorRegistration<VelocityPeak>
    registration("velocity peak", 90, peak_entries);


  // The name of the entry declared right after `entry` in Output.
  std::string entry_after(const std::string &entry)
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    std::ostringstream printed;
    prm.print_parameters(printed,
                         ParameterHandler::ShortPRM |
                           ParameterHandler::KeepDeclarationOrder);
    std::istringstream lines(printed.str());
    bool               in_output = false, found = false;
    for (std::string line; std::getline(lines, line);)
      {
        line = Utilities::trim(line);
        if (line == "subsection Output")
          in_output = true;
        else if (in_output && found && line.rfind("set ", 0) == 0)
          return Utilities::trim(line.substr(4, line.find('=') - 4));
        else if (in_output && line.rfind("set " + entry + " ", 0) == 0)
          found = true;
      }
    return "(none)";
  }


  // Runs the coarse scene with the entry set to `wanted`; returns the
  // console's text, and the largest norm an observer saw.
  std::string run_scene(const bool wanted, double &observed_peak)
  {
    const Parameters parameters =
      read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm",
                      {"Geometry/Cell size=0.125",
                       "Time/Time step=0.0625",
                       "Output/VTU interval=0",
                       "Output/Progress interval=0",
                       "Output/Print timings=false",
                       "Output/Report times=",
                       "Output/" + peak_entry + "=" +
                         (wanted ? "true" : "false"),
                       "Output/Output directory=run"});
    ContactProblem<2> problem(parameters);
    observed_peak = 0;
    problem.add_postprocessor(std::make_unique<StepObserver<2>>(
      [&observed_peak](const ContactProblem<2> &observed) {
        observed_peak =
          std::max(observed_peak, observed.get_velocity().l2_norm());
      }));
    whole_steps_seen = 0;
    std::ostringstream console;
    auto *const        saved = std::cout.rdbuf(console.rdbuf());
    problem.run();
    std::cout.rdbuf(saved);
    return console.str();
  }


  std::string line_with(const std::string &text, const std::string &word)
  {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.find(word) != std::string::npos)
        return line;
    return "(none)";
  }
} // namespace


int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::cout << "entry after 'Gamma3 history': " << entry_after("Gamma3 history")
            << std::endl;
  try
    {
      read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm",
                      {"Output/" + peak_entry + "=maybe"});
      std::cout << "'maybe' accepted (wrong)" << std::endl;
    }
  catch (const ExceptionBase &error)
    {
      const std::string what = error.what();
      std::cout << "'maybe' refused, the message names the entry: "
                << (what.find(peak_entry) != std::string::npos ? "yes" : "no")
                << std::endl;
    }

  double            observed_peak = 0;
  const std::string console       = run_scene(true, observed_peak);
  std::cout << "wanted: " << whole_steps_seen << " whole steps seen; "
            << line_with(console, "velocity peak") << std::endl
            << "the peak is the largest norm an observer saw: "
            << (last_peak == observed_peak && observed_peak > 0 ? "yes" : "no")
            << std::endl;

  std::ifstream series("run/time_series.csv");
  std::string   header;
  std::getline(series, header);
  std::cout << "time_series.csv has its column: "
            << (header.find("velocity_peak") != std::string::npos ? "yes" :
                                                                    "no")
            << std::endl;

  const std::string quiet = run_scene(false, observed_peak);
  std::cout << "not wanted: " << whole_steps_seen << " whole steps seen; "
            << line_with(quiet, "velocity peak") << std::endl;
}
