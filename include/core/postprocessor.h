/**
 * Postprocessor<dim>: what observes a run of ContactProblem<dim> without
 * changing it (the split of ASPECT's Postprocess::Interface). The core
 * solves; everything a user sees of a run (the VTU/PVD output, the time
 * series, the Gamma_3 history, the probes, the console reports, the
 * self-checks, the slip diagnostics, the errors against an exact
 * solution) is a postprocessor that owns its state, stores it with a
 * checkpoint, and reads the problem through the accessors of this base
 * class: the const view of the run (RunView, contact_problem.h) that the
 * problem hands to each postprocessor it takes.
 *
 * A run calls, in the order of the postprocessors' ranks:
 *   mesh_event(initial)        at the end of the set-up of the space,
 *                              Gamma_3, the loads and the matrices M, A_h
 *                              and B_h, before the initial values are set
 *                              and K is factorised (a postprocessor may
 *                              refuse its entries here, before the mesh is
 *                              reported),
 *   checkpoint() loading       on --resume, with the checkpoint's state,
 *   start(resumed)             before the first step: files are opened (a
 *                              resumed run cuts them back to its step), a
 *                              fresh run's initial state is written,
 *   after_step(solve)          after each solved linear system of a step:
 *                              the one of a step that is not cut, each half
 *                              of a cut step; a step that fails never gets
 *                              here, so no postprocessor has state to roll
 *                              back,
 *   after_step(whole_step)     after each step t_n (its statistics summed
 *                              over its halves),
 *   mesh_event(before_change)
 *   and mesh_event(after_change) before and after the mesh is adapted
 *                              during the run (adapt_mesh_during_run()):
 *                              u_n and w_n are on the new mesh, the matrices
 *                              assembled and the friction solver set up;
 *                              what a postprocessor keeps of the mesh is
 *                              built again here,
 *   checkpoint() saving        for a checkpoint,
 *   finish(summary)            after the last step: output still pending is
 *                              completed, the summary's lines printed and
 *                              the postprocessor's part of what a driver
 *                              gets of the run added (collective),
 *   require_success()          last, after the run's timings: a
 *                              postprocessor that found the results wrong
 *                              (a self-check) ends the run with an error.
 *
 * A postprocessor is a part (base/parts.h), registered once for all
 * dimensions with a name and a rank (PostprocessorRegistration); ranks
 * order the summary's lines and the columns of time_series.csv. The
 * entries that one postprocessor alone reads are its own: declared,
 * parsed and checked in its file (PartEntries). Tests and
 * drivers that observe a run add their own with
 * ContactProblem::add_postprocessor().
 */
#ifndef contact_postprocessor_h
#define contact_postprocessor_h

#include <deal.II/base/conditional_ostream.h>

#include <base/dimensions.h>
#include <base/parts.h>
#include <core/contact_problem.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

// The archives of a checkpoint (checkpoint.cc); a postprocessor with a
// state includes them.
namespace boost
{
  namespace archive
  {
    class binary_iarchive;
    class binary_oarchive;
  } // namespace archive
} // namespace boost

namespace Contact
{
  /** The columns of one row of time_series.csv, by name, in the order the
   *  postprocessors add them. */
  struct TimeSeriesRow
  {
    std::vector<std::pair<std::string, double>> columns;

    void add(const std::string &name, const double value)
    {
      columns.emplace_back(name, value);
    }
  };


  /** What changes the mesh of a run: its set-up at the start, and the
   *  moments before and after an adaptation during the run. */
  enum class MeshEvent
  {
    initial,
    before_change,
    after_change
  };


  /** Where after_step() is called: after a solve of the step's linear
   *  system (the one of a step that is not cut, or each half of a cut
   *  step), or once the whole step t_n is done. */
  enum class StepEnd
  {
    solve,
    whole_step
  };


  /**
   * A postprocessor's part of a checkpoint: the archive that is written
   * (Checkpoint::save()) or read (Checkpoint::load()), so that one
   * function lists what is stored, in one order for both. `archive & x`
   * writes or reads x as the archive held would; a postprocessor that
   * stores something includes <boost/archive/binary_iarchive.hpp> and
   * <boost/archive/binary_oarchive.hpp>.
   */
  class CheckpointArchive
  {
  public:
    explicit CheckpointArchive(boost::archive::binary_oarchive &archive)
      : output(&archive)
    {}

    explicit CheckpointArchive(boost::archive::binary_iarchive &archive)
      : input(&archive)
    {}

    /** Whether the checkpoint is read (--resume) rather than written. */
    bool is_loading() const
    {
      return input != nullptr;
    }

    template <typename T>
    CheckpointArchive &operator&(T &value)
    {
      if (input)
        *input &value;
      else
        *output &value;
      return *this;
    }

  private:
    boost::archive::binary_oarchive *output = nullptr;
    boost::archive::binary_iarchive *input  = nullptr;
  };


  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Called by the problem that takes the postprocessor, with what it
     *  may read of the run. */
    void observe(const RunView<dim> &run_view)
    {
      run = &run_view;
    }

    virtual void mesh_event(const MeshEvent /*event*/)
    {}
    virtual void start(const bool /*resumed*/)
    {}
    virtual void after_step(const StepStatistics & /*statistics*/,
                            const StepEnd /*end*/)
    {}
    /** Its columns of the step's row of time_series.csv (collective). */
    virtual void add_columns(TimeSeriesRow & /*row*/) const
    {}
    /** Its state, written to or read from a checkpoint. */
    virtual void checkpoint(CheckpointArchive & /*archive*/)
    {}
    /** After the last step: what is pending completed, its lines of the
     *  summary printed, and its part of what a driver gets of the run
     *  (collective). */
    virtual void finish(RunSummary & /*summary*/)
    {}
    virtual void require_success() const
    {}

  protected:
    // Read access to the problem observed.
    const ContactProblem<dim> &problem() const
    {
      return run->problem;
    }
    const Parameters &parameters() const
    {
      return run->parameters;
    }
    const StepState &state() const
    {
      return run->state;
    }
    double time_step() const
    {
      return run->state.time_step;
    }
    unsigned int n_time_steps() const
    {
      return run->parameters.time.n_steps();
    }
    const FrictionLaw &friction_law() const
    {
      return run->friction_solver->law();
    }
    const FrictionSolver<dim> &friction_solver() const
    {
      return *run->friction_solver;
    }
    const DiscreteSpace<dim> &space() const
    {
      return run->space;
    }
    const SystemMatrices<dim> &matrices() const
    {
      return run->matrices;
    }
    const Loads<dim> &loads() const
    {
      return *run->loads;
    }
    /** The run's exact solution (ExactSolution, loads.h), or nullptr. */
    const ExactSolution<dim> *exact_solution() const
    {
      return run->loads->exact_solution();
    }
    const ConditionalOStream &pcout() const
    {
      return run->pcout;
    }
    TimerOutput &computing_timer() const
    {
      return run->computing_timer;
    }
    MPI_Comm mpi_communicator() const
    {
      return run->space.mpi_communicator;
    }
    /** All postprocessors of the run, this one among them. */
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &
    postprocessors() const
    {
      return run->postprocessors;
    }

  private:
    const RunView<dim> *run = nullptr;
  };


  /** A postprocessor of a lambda called after every step: what a test or a
   *  driver uses to collect or perturb the solutions of a run. */
  template <int dim>
  class StepObserver : public Postprocessor<dim>
  {
  public:
    explicit StepObserver(
      const std::function<void(const ContactProblem<dim> &)> &observer)
      : observe_step(observer)
    {}

    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end == StepEnd::whole_step)
        observe_step(this->problem());
    }

  private:
    const std::function<void(const ContactProblem<dim> &)> observe_step;
  };


  /**
   * The postprocessors of every run, by rank (base/parts.h): a
   * postprocessor's file registers it for every compiled dimension with a
   * static
   *   const PostprocessorRegistration<Class> registration(name, rank,
   *                                                       entries);
   * and ContactProblem's constructor creates one of each (a class that is
   * not wanted by the parameters is created all the same and does
   * nothing). `entries` are the postprocessor's own entries of Output, if
   * it has any; it reads their value as parameters().part<Value>(name).
   */
  template <int dim>
  using PostprocessorParts = PartRegistry<Postprocessor<dim>>;

  template <template <int> class Class>
  struct PostprocessorRegistration
  {
    PostprocessorRegistration(const std::string &name,
                              const unsigned int rank,
                              const PartEntries &entries = {})
    {
#define INSTANTIATE(dim)                                                 \
  PostprocessorParts<dim>::add({name, "", rank, entries, []() {          \
                                  return std::make_unique<Class<dim>>(); \
                                }});
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    }
  };
} // namespace Contact

#endif
