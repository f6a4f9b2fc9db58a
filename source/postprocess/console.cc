/* The console: a progress line every 'Output/Progress interval' steps,
   the state of Gamma_3 at the 'Output/Report times', and the summary of
   the iterations and the energy at the end. */

#include <deal.II/base/timer.h>

#include <boost/serialization/vector.hpp>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/postprocessor.h>
#include <postprocess/slip_zone.h>

#include <iomanip>

namespace Contact
{
  namespace
  {
    // @sect4{The entry 'Progress interval'}

    const std::string progress_entry = "Progress interval";

    [[maybe_unused]] const bool registered = OutputParameters::register_entry(
      {progress_entry,
       "Probe points",
       [](ParameterHandler &prm) {
         prm.declare_entry(progress_entry,
                           "1",
                           Patterns::Integer(0),
                           "Print a progress line every this many steps; 0: "
                           "none.");
       },
       [](ParameterHandler &prm, const Parameters &) -> std::any {
         return static_cast<unsigned int>(prm.get_integer(progress_entry));
       }});
  } // namespace


  template <int dim>
  class Console : public Postprocessor<dim>
  {
  public:
    void initialize() override
    {
      report_times = ReportTimes(this->parameters().output.report_times);
    }

    void start(const bool) override
    {
      loop_timer.restart();
    }

    void after_step(const StepStatistics &statistics) override
    {
      totals.add_counts(statistics);
      ++steps_timed;
      print_progress(statistics);
      report_contact_state();
    }

    void save(boost::archive::binary_oarchive &archive) override
    {
      serialize(archive);
    }

    void load(boost::archive::binary_iarchive &archive) override
    {
      serialize(archive);
    }

    void print_summary() const override;

  private:
    void print_progress(const StepStatistics &statistics) const;
    void report_contact_state();
    template <class Archive>
    void serialize(Archive &archive);

    // The counts of all steps so far, and the report times not met yet
    // (both checkpointed).
    StepStatistics totals;
    ReportTimes    report_times;
    // Wall time since the problem was made (the run starts with it) and
    // since its time loop did (the time left in the progress line is from
    // the steps of this run alone: the set-up before the first step,
    // factorisation and Delassus operator, would make the first estimates
    // several times too large).
    Timer        run_timer;
    Timer        loop_timer;
    unsigned int steps_timed = 0;
  };


  // @sect4{Console::print_progress}

  template <int dim>
  void Console<dim>::print_progress(const StepStatistics &statistics) const
  {
    const unsigned int step    = this->state().step_number,
                       n_steps = this->n_time_steps();
    const double       now     = this->state().time;
    const unsigned int interval =
      this->parameters().output.template entry<unsigned int>(progress_entry);
    if (interval == 0 || (step % interval != 0 && step != n_steps))
      return;
    const double elapsed = run_timer.wall_time();
    const double left =
      loop_timer.wall_time() / std::max(steps_timed, 1u) * (n_steps - step);
    this->pcout()
      << "Step " << std::setw(5) << step << '/' << n_steps
      << "  t = " << std::setw(9) << std::setprecision(5) << now
      << "  iterations "
      << (statistics.newton_iterations > 0 ?
            std::to_string(statistics.newton_iterations) + " Newton" +
              (statistics.newton_fallbacks > 0 ? " + " : "") :
            std::string())
      << (statistics.newton_iterations == 0 || statistics.newton_fallbacks > 0 ?
            std::to_string(statistics.convexification_iterations) + '/' +
              std::to_string(statistics.active_set_iterations) :
            std::string())
      << "  solves " << statistics.solves_with_K << "  stick "
      << statistics.n_stick << "  slip " << statistics.n_slip
      << "  max slip rate " << std::setprecision(3) << statistics.max_slip_rate
      << "  [" << std::setprecision(3) << elapsed << " s, " << left
      << " s left]" << std::endl;
  }



  // @sect4{Console::report_contact_state}

  // At the step nearest to each of the 'Output/Report times': how many
  // nodes of Gamma_3 stick and slip, where the slip zone is, the friction
  // force and the momentum.
  template <int dim>
  void Console<dim>::report_contact_state()
  {
    const StepState          &state = this->state();
    const unsigned int        step  = state.step_number;
    const double              now = state.time, k = this->time_step();
    const std::vector<double> due =
      report_times.take_due(now, k, step == this->n_time_steps());
    if (due.empty())
      return;
    const std::vector<ContactNode<dim>> &contact_nodes =
      this->friction_solver().boundary().nodes;
    const Vector<double> &friction_force =
      this->friction_solver().state().friction_force;
    const bool shell =
      this->parameters().geometry.domain == GeometryParameters::Domain::shell;
    const SlipZone zone = slip_zone(contact_nodes,
                                    this->friction_solver().state().node_state,
                                    shell);
    for (const double t : due)
      {
        this->pcout() << "Report t = " << std::setprecision(6) << t << " (step "
                      << step << ", t_n = " << now
                      << (t - now > 0.5 * k * (1 + 1e-12) ?
                            ", the last step: the report time is after "
                            "'" +
                              Entry::end_time + "'" :
                            "")
                      << "): " << zone.n_stick << " stick, " << zone.n_slip
                      << " slip";
        if (zone.n_slip > 0 && !shell)
          this->pcout() << ", slip zone x in [" << zone.from << ", " << zone.to
                        << "]";
        else if (zone.n_slip > 0 && zone.n_stick > 0)
          {
            this->pcout() << ", slip on the arc from " << zone.from << " to "
                          << zone.to << " degrees (counterclockwise)";
            if (zone.n_stick_inside > 0)
              this->pcout() << ", which holds " << zone.n_stick_inside
                            << " sticking nodes too";
          }
        // The sum of the nodal forces: along the tangent in 2D, as a
        // vector in 3D.
        Tensor<1, dim> friction;
        for (unsigned int p = 0; p < contact_nodes.size(); ++p)
          friction += contact_nodes[p].tangential_vector(friction_force, p);
        // A scalar along the tangent where Gamma_3 is straight (all its
        // nodes share one tangent), the vector otherwise. (The slip zone
        // is given by its x range, which locates it on any open Gamma_3,
        // or on a shell's closed one by its arc.)
        bool straight = (dim == 2 && !contact_nodes.empty());
        for (const ContactNode<dim> &node : contact_nodes)
          straight =
            straight &&
            (node.tangents[0] - contact_nodes[0].tangents[0]).norm() < 1e-12;
        this->pcout() << "; friction force ";
        if (straight)
          this->pcout() << friction * contact_nodes[0].tangents[0];
        else
          this->pcout() << friction;
        this->pcout() << ", momentum "
                      << this->matrices().momentum(state.velocity) << std::endl;
      }
  }


  // @sect4{Console::print_summary}

  template <int dim>
  void Console<dim>::print_summary() const
  {
    const unsigned int   n_steps = this->n_time_steps();
    const double         k       = this->time_step();
    const double         now     = this->state().time;
    const EnergyBalance &energy  = this->state().energy;
    this->pcout() << "Done: " << n_steps
                  << " steps of k = " << std::setprecision(8) << k << ", "
                  << totals.convexification_iterations
                  << " convexification iterations, "
                  << totals.active_set_iterations << " active set iterations, "
                  << totals.rejected_accelerations << " rejected accelerations."
                  << std::endl;
    if (totals.newton_iterations > 0)
      this->pcout() << "Newton on the full friction law: "
                    << totals.newton_iterations << " iterations, "
                    << std::setprecision(3)
                    << static_cast<double>(totals.newton_iterations) / n_steps
                    << " per step; " << totals.beyond_convexity_limit
                    << " steps ended beyond the convexity limit (the "
                    << "curvature test decided); the convexification took "
                    << "over in " << totals.newton_fallbacks << " steps ("
                    << totals.minima_not_certified
                    << " not certified a local minimum)." << std::endl;
    this->pcout() << "Solves with K per step: " << std::setprecision(3)
                  << static_cast<double>(totals.solves_with_K) / n_steps
                  << std::endl;
    if (totals.cg_iterations > 0)
      // Rounded: the count moves by a few tenths with the round-off of the
      // AMG coarse solve (the BLAS in use).
      this->pcout() << "CG iterations per step: "
                    << std::lround(static_cast<double>(totals.cg_iterations) /
                                   n_steps)
                    << std::endl;
    this->pcout() << "Energy at t = " << now << ": kinetic "
                  << std::setprecision(6) << energy.kinetic << ", elastic "
                  << energy.elastic << ", external work "
                  << energy.external_work << ", viscous "
                  << energy.viscous_dissipation << ", friction "
                  << energy.friction_dissipation << ", numerical "
                  << energy.numerical_dissipation << std::endl;
  }


  template <int dim>
  template <class Archive>
  void Console<dim>::serialize(Archive &archive)
  {
    archive &totals.convexification_iterations &totals.active_set_iterations;
    archive &totals.rejected_accelerations &totals.cycles_cured;
    archive &totals.step_cuts &totals.newton_iterations;
    archive &totals.beyond_convexity_limit &totals.newton_fallbacks;
    archive &totals.minima_not_certified &totals.solves_with_K;
    archive &totals.cg_iterations &report_times;
  }


  namespace
  {
    const PostprocessorRegistration<Console> registration(10);
  }
} // namespace Contact
