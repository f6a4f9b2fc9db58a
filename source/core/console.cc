/* The console: a progress line every 'Output/Progress interval' steps,
   the state of Gamma_3 at the 'Output/Report times', and the summary of
   the iterations and the energy at the end. */

#include <deal.II/base/timer.h>

#include <boost/serialization/vector.hpp>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/postprocessor.h>
#include <core/geometry.h>
#include <core/slip_zone.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace Contact
{
  namespace
  {
    // @sect4{The entry 'Progress interval'}

    const std::string progress_entry = "Progress interval";

    const PartEntries own_entries{
      "Output",
      "Probe points",
      progress_entry,
      [](ParameterHandler &prm) {
        prm.declare_entry(progress_entry,
                          "1",
                          Patterns::Integer(0),
                          "Print a progress line every this many steps; 0: "
                          "none.");
      },
      [](ParameterHandler &prm, const Parameters &) -> std::any {
        return static_cast<unsigned int>(prm.get_integer(progress_entry));
      }};

    // A sum whose terms cancel (the friction force of a symmetric stick
    // state, the momentum of a body at rest, the friction dissipation of
    // a sticking body) is round-off or solver tolerance, whose digits
    // depend on the order of the sums, the BLAS kernel and the solver's
    // path: a value below `relative` times the size of its terms prints as
    // "below <bound>", an exact zero too (on another BLAS kernel it may be
    // round-off); only a sum without terms prints as 0.
    std::string resolved(const double value,
                         const double term_size,
                         const double relative = 1e-10)
    {
      std::ostringstream text;
      const double       bound = relative * term_size;
      if (bound > 0 && std::isfinite(bound) && std::abs(value) <= bound)
        text << "below " << std::setprecision(1) << std::scientific << bound;
      else
        text << std::setprecision(6) << value;
      return text.str();
    }

    template <int dim>
    std::string resolved(const Tensor<1, dim> &value,
                         const double          term_size,
                         const double          relative = 1e-10)
    {
      std::string text;
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? " " : "") + resolved(value[d], term_size, relative);
      return text;
    }
  } // namespace


  template <int dim>
  class Console : public Postprocessor<dim>
  {
  public:
    void mesh_event(const MeshEvent event) override
    {
      if (event == MeshEvent::initial)
        report_times = ReportTimes(this->parameters().output.report_times);
    }

    void start(const bool) override
    {
      loop_timer.restart();
    }

    void after_step(const StepStatistics &statistics,
                    const StepEnd         end) override
    {
      if (end != StepEnd::whole_step)
        return;
      totals.add_counts(statistics);
      ++steps_timed;
      print_progress(statistics);
      report_contact_state();
    }

    // The report times of a resumed run are this run's after the
    // checkpoint (ReportTimes::drop_met()), not the checkpointed run's.
    void checkpoint(CheckpointArchive &archive) override
    {
      serialize(archive);
      if (!archive.is_loading())
        return;
      report_times = ReportTimes(this->parameters().output.report_times);
      report_times.drop_met(this->state().step_number, this->time_step());
    }

    void finish(RunSummary &) override;

  private:
    void        print_progress(const StepStatistics &statistics) const;
    void        report_contact_state();
    std::string friction_force_text() const;
    std::string momentum_text() const;
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
      this->parameters().template part<unsigned int>("console");
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
    const bool     closed = this->problem().get_geometry().gamma3_is_closed();
    const SlipZone zone   = slip_zone(contact_nodes,
                                    this->friction_solver().state().node_state,
                                    closed);
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
        if (zone.n_slip > 0 && !closed)
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
        this->pcout() << "; friction force " << friction_force_text()
                      << ", momentum " << momentum_text() << std::endl;
      }
  }


  // The sum of the nodal forces: along the tangent in 2D, as a vector in
  // 3D. Its terms are at most the nodal bounds m_p g(0): where the forces
  // themselves are round-off (a body pressed but not pulled), their sum is
  // resolved against the bounds.
  template <int dim>
  std::string Console<dim>::friction_force_text() const
  {
    const std::vector<ContactNode<dim>> &contact_nodes =
      this->friction_solver().boundary().nodes;
    const Vector<double> &friction_force =
      this->friction_solver().state().friction_force;
    Tensor<1, dim> friction;
    double         nodal_forces = 0, nodal_bounds = 0;
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        const auto force =
          contact_nodes[p].tangential_vector(friction_force, p);
        friction += force;
        nodal_forces += force.norm();
        nodal_bounds += contact_nodes[p].weight;
      }
    nodal_bounds *= this->friction_law().bound(0.);
    const double force_terms = std::max(nodal_forces, nodal_bounds);
    // A scalar along the tangent where Gamma_3 is straight (all its
    // nodes share one tangent), the vector otherwise. (The slip zone
    // is given by its x range, which locates it on any open Gamma_3,
    // or on a closed one, a shell's, by its arc.)
    bool straight = (dim == 2 && !contact_nodes.empty());
    for (const ContactNode<dim> &node : contact_nodes)
      straight =
        straight &&
        (node.tangents[0] - contact_nodes[0].tangents[0]).norm() < 1e-12;
    return straight ?
             resolved(friction * contact_nodes[0].tangents[0], force_terms) :
             resolved(friction, force_terms);
  }


  // The momentum of the body. |sum_i a_i w_i| <= |a| |w| bounds the terms
  // of each component. A component that cancels is the solve's forward
  // error, which a body held by friction amplifies (tests/scenes/pure_stick:
  // 3e-10 of its terms with OpenBLAS's Sandy Bridge kernel): resolved
  // against 1e-8 of them, the self-checks' tolerance.
  template <int dim>
  std::string Console<dim>::momentum_text() const
  {
    const VectorType &velocity       = this->state().velocity;
    double            momentum_terms = 0;
    for (const VectorType &density : this->matrices().momentum_density)
      momentum_terms =
        std::max(momentum_terms, density.l2_norm() * velocity.l2_norm());
    return resolved(this->matrices().momentum(velocity), momentum_terms, 1e-8);
  }


  // @sect4{Console::finish}

  // The summary's lines of the run.
  template <int dim>
  void Console<dim>::finish(RunSummary &)
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
    // Also where Newton took no iteration (every step solved by its start)
    // but handed steps to the convexification.
    if (totals.newton_iterations > 0 || totals.newton_fallbacks > 0)
      this->pcout() << "Newton on the full friction law: "
                    << totals.newton_iterations << " iterations, "
                    << std::setprecision(3)
                    << static_cast<double>(totals.newton_iterations) / n_steps
                    << " per step; " << totals.beyond_convexity_limit
                    << " steps ended beyond the convexity limit (the "
                    << "curvature test decided)"
                    << (totals.saddle_exits > 0 ?
                          ", " + std::to_string(totals.saddle_exits) +
                            " saddles of the step energy left along their "
                            "negative curvature" :
                          std::string())
                    << "; the convexification took over in "
                    << totals.newton_fallbacks << " steps ("
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
    // The terms of the energy identity balance to the solvers' tolerance,
    // which the self-checks require to 1e-8 of the largest term: a
    // cancelling sum below that is not resolved (the friction dissipation
    // of a body that sticks throughout is such a sum: its digits depend on
    // the BLAS and the processor).
    const double terms[] = {energy.kinetic,
                            energy.elastic,
                            energy.external_work,
                            energy.viscous_dissipation,
                            energy.friction_dissipation,
                            energy.numerical_dissipation,
                            energy.mesh_transfer};
    double       largest = 0;
    for (const double value : terms)
      largest = std::max(largest, std::abs(value));
    // Only the sums whose terms cancel: the external work and the friction
    // and numerical dissipation. The energies and the viscous dissipation
    // are sums of quadratic forms, resolved however small (a body of
    // density 1e-6 at rest has a kinetic energy of 1e-8).
    const auto cancelling = [&](const double value) {
      return resolved(value, largest, 1e-8);
    };
    this->pcout() << "Energy at t = " << now << ": kinetic "
                  << std::setprecision(6) << energy.kinetic << ", elastic "
                  << energy.elastic << ", external work "
                  << cancelling(energy.external_work) << ", viscous "
                  << energy.viscous_dissipation << ", friction "
                  << cancelling(energy.friction_dissipation) << ", numerical "
                  << cancelling(energy.numerical_dissipation);
    if (this->problem().adapts_mesh_during_run())
      this->pcout() << ", mesh transfers " << cancelling(energy.mesh_transfer);
    this->pcout() << std::endl;
  }


  template <int dim>
  template <class Archive>
  void Console<dim>::serialize(Archive &archive)
  {
    archive &totals.convexification_iterations &totals.active_set_iterations;
    archive &totals.rejected_accelerations &totals.cycles_cured;
    archive &totals.step_cuts &totals.newton_iterations;
    archive &totals.beyond_convexity_limit &totals.newton_fallbacks;
    archive &totals.minima_not_certified &totals.saddle_exits;
    archive                              &totals.solves_with_K;
    archive &totals.cg_iterations &report_times;
  }


  namespace
  {
    const PostprocessorRegistration<Console>
      registration("console", 10, own_entries);
  }
} // namespace Contact
