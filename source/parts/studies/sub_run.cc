/* Runs inside a study: their console output in a log file, and their
 * displacements kept for comparison (include/parts/studies/sub_run.h). */

#include <deal.II/base/mpi.h>

#include <base/dimensions.h>
#include <core/quantity.h>
#include <core/postprocessor.h>
#include <parts/studies/reference_interpolation.h>
#include <parts/studies/sub_run.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace Contact
{
  // @sect3{The log of a sub-run}

  namespace
  {
    // The console output of a sub-run, kept while it runs and written to
    // its log file when it ends, however it ends (the directory exists by
    // then, since the run made it).
    class ConsoleToFile
    {
    public:
      explicit ConsoleToFile(const std::string &file)
        : log_file(file)
        , console(file.empty() ? nullptr : std::cout.rdbuf(captured.rdbuf()))
      {}
      ~ConsoleToFile()
      {
        if (!console)
          return;
        std::cout.rdbuf(console);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::ofstream(log_file) << captured.str();
      }
      ConsoleToFile(const ConsoleToFile &)            = delete;
      ConsoleToFile &operator=(const ConsoleToFile &) = delete;

    private:
      const std::string  log_file;
      std::ostringstream captured;
      std::streambuf    *console;
    };
  } // namespace


  // @sect3{What a study reads of a run}

  double quantity_of(const RunSummary &summary, const std::string &name)
  {
    if (name == V_norm)
      return summary.displacement_V_norm;
    for (const auto &[quantity, value] : summary.final_quantities)
      if (quantity == name)
        return value;
    return std::numeric_limits<double>::quiet_NaN();
  }


  std::string sub_run_line(const RunSummary  &summary,
                           const std::string &log_file)
  {
    std::ostringstream line;
    line << summary.n_dofs << " unknowns, " << summary.n_steps
         << " steps; log in " << log_file;
    return line.str();
  }


  std::ostream &study_console()
  {
    static std::ofstream dropped;
    return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? std::cout :
                                                                   dropped;
  }


  void write_study_file(const std::string &file, const std::string &text)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream stream(file);
    stream << text << std::flush;
    AssertThrow(stream.good(), ExcMessage("Cannot write '" + file + "'."));
  }


  template <int dim>
  RunAtTimes run_onto(ContactProblem<dim>               &problem,
                      const ReferenceInterpolation<dim> *onto,
                      const unsigned int                 stride,
                      const std::string                 &log_file)
  {
    const ConsoleToFile log(log_file);
    using NodesInCells =
      std::vector<typename ReferenceInterpolation<dim>::NodeInCell>;
    RunAtTimes                  result;
    std::optional<NodesInCells> located;
    const auto                  carry = [&](const ContactProblem<dim> &run) {
      if (!onto)
        return run.get_displacement();
      // The mesh exists once the run has started.
      if (!located)
        located = onto->locate(run);
      return (*onto)(*located, run, run.get_displacement());
    };
    // (A problem runs once: the observer is not called after run().)
    if (stride > 0)
      problem.add_postprocessor(std::make_unique<StepObserver<dim>>(
        [&](const ContactProblem<dim> &run) {
          if (run.get_step_number() % stride == 0)
            result.history.push_back(carry(run));
        }));
    result.summary      = problem.run();
    result.displacement = carry(problem);
    return result;
  }


#define INSTANTIATE(dim)                                                 \
  template RunAtTimes run_onto<dim>(ContactProblem<dim> &,               \
                                    const ReferenceInterpolation<dim> *, \
                                    const unsigned int,                  \
                                    const std::string &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
