/**
 * Postprocessor<dim>: what observes a run of ContactProblem<dim> without
 * changing it (the split of ASPECT's Postprocess::Interface). The core
 * solves; everything a user sees of a run (the VTU/PVD output, the time
 * series, the Gamma_3 history, the probes, the console reports, the
 * self-checks, the slip diagnostics, the errors against a manufactured
 * solution) is a postprocessor that owns its state, saves it with a
 * checkpoint, and reads the problem through the accessors of this base
 * class.
 *
 * A run calls, in the order of the postprocessors' ranks:
 *   initialize()      at the end of the set-up of the space, Gamma_3, the
 *                     loads and the matrices M, A_h and B_h, before the
 *                     initial values are set and K is factorised (a
 *                     postprocessor may refuse its entries here, before
 *                     the mesh is reported),
 *   load()            on --resume, with the checkpoint's state,
 *   start(resumed)    before the first step: files are opened (a resumed
 *                     run cuts them back to its step), a fresh run's
 *                     initial state is written,
 *   after_substep()   after each solved linear system of a step (both
 *                     halves of a cut step); a step that fails never gets
 *                     here, so no postprocessor has state to roll back,
 *   after_step()      after each step t_n,
 *   before_mesh_change() and
 *   mesh_changed()    before and after the mesh is adapted during the run
 *                     ('Mesh adaptation/Interval'): u_n and w_n are on the
 *                     new mesh, the matrices assembled and the friction
 *                     solver set up; what a postprocessor keeps of the
 *                     mesh is built again here,
 *   save()            for a checkpoint,
 *   end()             after the last step (output still pending is
 *                     completed),
 *   print_summary(), add_to_summary(), and last require_success(): a
 *   postprocessor that found the results wrong (a self-check) ends the run
 *   with an error.
 *
 * A postprocessor is registered once for all dimensions with a rank
 * (PostprocessorRegistration); ranks order the summary's lines and the
 * columns of time_series.csv. An entry that one postprocessor alone reads
 * is declared, parsed and checked in its file
 * (OutputParameters::register_entry(), base/parameters.h). Tests and
 * drivers that observe a run add their own with
 * ContactProblem::add_postprocessor().
 */
#ifndef contact_postprocessor_h
#define contact_postprocessor_h

#include <deal.II/base/conditional_ostream.h>

#include <base/dimensions.h>
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


  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    virtual void initialize()
    {}
    virtual void start(const bool /*resumed*/)
    {}
    virtual void after_substep()
    {}
    virtual void after_step(const StepStatistics & /*statistics*/)
    {}
    virtual void before_mesh_change()
    {}
    virtual void mesh_changed()
    {}
    /** Its columns of the step's row of time_series.csv (collective). */
    virtual void add_columns(TimeSeriesRow & /*row*/) const
    {}
    virtual void save(boost::archive::binary_oarchive & /*archive*/)
    {}
    virtual void load(boost::archive::binary_iarchive & /*archive*/)
    {}
    virtual void end()
    {}
    virtual void print_summary() const
    {}
    /** Its part of what a driver gets of the run (collective). */
    virtual void add_to_summary(RunSummary & /*summary*/) const
    {}
    virtual void require_success() const
    {}

  protected:
    // The problem observed, set by ContactProblem when it takes the
    // postprocessor; and read access to it (a friend of the problem).
    const ContactProblem<dim> &problem() const
    {
      return *observed;
    }
    const Parameters &parameters() const
    {
      return observed->parameters;
    }
    const StepState &state() const
    {
      return observed->state;
    }
    double time_step() const
    {
      return observed->state.time_step;
    }
    unsigned int n_time_steps() const
    {
      return observed->parameters.time.n_steps();
    }
    const FrictionLaw &friction_law() const
    {
      return observed->friction_solver->law();
    }
    const FrictionSolver<dim> &friction_solver() const
    {
      return *observed->friction_solver;
    }
    const DiscreteSpace<dim> &space() const
    {
      return observed->space;
    }
    const SystemMatrices<dim> &matrices() const
    {
      return observed->matrices;
    }
    const Loads<dim> &loads() const
    {
      return *observed->loads;
    }
    const ManufacturedSolution<dim> *exact_solution() const
    {
      return observed->loads->exact_solution();
    }
    const ConditionalOStream &pcout() const
    {
      return observed->pcout;
    }
    TimerOutput &computing_timer() const
    {
      return observed->computing_timer;
    }
    MPI_Comm mpi_communicator() const
    {
      return observed->space.mpi_communicator;
    }
    /** All postprocessors of the run, this one among them. */
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &
    postprocessors() const
    {
      return observed->postprocessors;
    }

  private:
    const ContactProblem<dim> *observed = nullptr;
    friend class ContactProblem<dim>;
  };


  /** A postprocessor of a lambda called after every step: what a test or a
   *  driver uses to collect or perturb the solutions of a run. */
  template <int dim>
  class StepObserver : public Postprocessor<dim>
  {
  public:
    explicit StepObserver(
      const std::function<void(const ContactProblem<dim> &)> &observer)
      : observe(observer)
    {}

    void after_step(const StepStatistics &) override
    {
      observe(this->problem());
    }

  private:
    const std::function<void(const ContactProblem<dim> &)> observe;
  };


  /**
   * The postprocessors of every run, by rank: a postprocessor's file
   * registers it for every compiled dimension with a static
   *   const PostprocessorRegistration<Class> registration(rank);
   * and ContactProblem::run() creates one of each (a class that is not
   * wanted by the parameters is created all the same and does nothing).
   */
  template <int dim>
  using PostprocessorFactory =
    std::function<std::unique_ptr<Postprocessor<dim>>()>;

  template <int dim>
  std::multimap<unsigned int, PostprocessorFactory<dim>> &
  postprocessor_registry()
  {
    static std::multimap<unsigned int, PostprocessorFactory<dim>> registry;
    return registry;
  }

  template <template <int> class Class>
  struct PostprocessorRegistration
  {
    explicit PostprocessorRegistration(const unsigned int rank)
    {
#define INSTANTIATE(dim)                             \
  postprocessor_registry<dim>().emplace(rank, []() { \
    return std::make_unique<Class<dim>>();           \
  });
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    }
  };
} // namespace Contact

#endif
