/* What a contact engineer reads of a run's slip: the time of the first
   slip, and the quantities at T that an error estimate compares between
   runs (the friction dissipation, the slipping share of Gamma_3, where the
   slip zone starts, the first slip). */

#include <boost/serialization/vector.hpp>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/postprocessor.h>
#include <core/quantity.h>
#include <core/geometry.h>
#include <core/slip_zone.h>

#include <cmath>
#include <iomanip>
#include <limits>

namespace Contact
{
  /**
   * The first slip of a run: its time (NaN while every node sticks), its
   * step, how the time was found, and the friction's utilisation
   * max_p |eta_p| / (m_p S mu(0)) of the last two steps in which every
   * node stuck, from which it is extrapolated.
   */
  struct SlipOnset
  {
    enum class Estimate : unsigned int
    {
      extrapolated, // within the step, from the utilisation
      beyond_step,  // the extrapolation passes t_n: t_n
      not_rising,   // the utilisation did not rise: t_{n-1}
      too_few_steps // fewer than two all-stick steps before: t_{n-1}
    };

    double       time        = std::numeric_limits<double>::quiet_NaN();
    unsigned int step        = 0;
    Estimate     estimate    = Estimate::too_few_steps;
    double       utilisation = 0;
    double       previous_utilisation = 0;
    unsigned int stick_steps          = 0;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &time &step &estimate &utilisation &previous_utilisation
        &stick_steps;
    }
  };


  template <int dim>
  class SlipDiagnostics : public Postprocessor<dim>
  {
  public:
    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end == StepEnd::whole_step)
        track_slip_onset();
    }

    void checkpoint(CheckpointArchive &archive) override
    {
      archive &slip_onset;
    }

    void finish(RunSummary &summary) override
    {
      print_summary();
      add_to_summary(summary);
    }

  private:
    void print_summary() const;
    void add_to_summary(RunSummary &summary) const;
    void track_slip_onset();

    SlipOnset slip_onset;
  };


  // @sect4{SlipDiagnostics::track_slip_onset}

  // The time of the first slip. The first step with a slipping node, t_n,
  // alone would move in jumps of k as h changes; instead the friction's
  // utilisation max_p |eta_p| / (m_p S mu(0)) of the last two steps in
  // which every node stuck is extrapolated linearly to 1 (not before
  // t_{n-1}). So the onset converges in h at a fixed k where the
  // utilisation rises smoothly. Where it cannot be extrapolated the step's
  // end or start is taken, and the summary says which
  // (SlipOnset::Estimate): such a time moves in jumps of k. (A node that
  // slips in the first half of a cut step and sticks again in the second
  // is not seen: the state is that at the end of the step.)
  template <int dim>
  void SlipDiagnostics<dim>::track_slip_onset()
  {
    const FrictionLaw &law = this->friction_law();
    if (!std::isnan(slip_onset.time) || law.is_frictionless())
      return;
    const std::vector<ContactNode<dim>> &nodes =
      this->friction_solver().boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      this->friction_solver().state();
    const double       time = this->state().time, k = this->time_step();
    const unsigned int step_number = this->state().step_number;
    double             utilisation = 0;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (node_state[p] != NodeState::stick)
        {
          using Estimate        = SlipOnset::Estimate;
          const double previous = time - k;
          const double rise =
            (slip_onset.utilisation - slip_onset.previous_utilisation) / k;
          slip_onset.step = step_number;
          slip_onset.time = previous;
          if (slip_onset.stick_steps < 2)
            slip_onset.estimate = Estimate::too_few_steps;
          else if (!(rise > 0))
            slip_onset.estimate = Estimate::not_rising;
          else if (previous + (1 - slip_onset.utilisation) / rise > time)
            {
              slip_onset.estimate = Estimate::beyond_step;
              slip_onset.time     = time;
            }
          else
            {
              slip_onset.estimate = Estimate::extrapolated;
              slip_onset.time =
                std::max(previous,
                         previous + (1 - slip_onset.utilisation) / rise);
            }
          return;
        }
      else if (nodes[p].weight > 0)
        utilisation =
          std::max(utilisation,
                   nodes[p].tangential_vector(friction_force, p).norm() /
                     (nodes[p].weight * law.bound(0.)));
    slip_onset.previous_utilisation = slip_onset.utilisation;
    slip_onset.utilisation          = utilisation;
    ++slip_onset.stick_steps;
  }


  // @sect4{SlipDiagnostics::print_summary}

  // The summary's line of the first slip, with how its time was found.
  template <int dim>
  void SlipDiagnostics<dim>::print_summary() const
  {
    using Estimate = SlipOnset::Estimate;
    if (std::isnan(slip_onset.time))
      return;
    this->pcout() << "First slip at t = " << std::setprecision(8)
                  << slip_onset.time << " (in step " << slip_onset.step << ", ";
    switch (slip_onset.estimate)
      {
        case Estimate::extrapolated:
          this->pcout()
            << "extrapolated from the friction's utilisation at the two "
               "steps before";
          break;
        case Estimate::beyond_step:
          this->pcout()
            << "its end: the friction's utilisation at the two steps "
               "before extrapolates to later";
          break;
        case Estimate::not_rising:
          this->pcout()
            << "its start: the friction's utilisation did not rise over "
               "the two steps before";
          break;
        case Estimate::too_few_steps:
          this->pcout()
            << "its start: fewer than two steps before it in which every "
               "node stuck, to extrapolate from";
          break;
      }
    this->pcout() << ")" << std::endl;
  }


  // @sect4{SlipDiagnostics::add_to_summary}

  // The quantities at T that an error estimate compares between runs of
  // different h and k.
  template <int dim>
  void SlipDiagnostics<dim>::add_to_summary(RunSummary &summary) const
  {
    using Kind       = Quantity::Kind;
    auto &quantities = summary.final_quantities;
    quantities.emplace_back(Quantity{Kind::friction_dissipation}.name(),
                            this->state().energy.friction_dissipation);
    const bool     closed = this->problem().get_geometry().gamma3_is_closed();
    const SlipZone zone   = slip_zone(this->friction_solver().boundary().nodes,
                                    this->friction_solver().state().node_state,
                                    closed);
    const unsigned int n_nodes = zone.n_stick + zone.n_slip;
    if (n_nodes > 0)
      quantities.emplace_back(Quantity{Kind::slipping_share}.name(),
                              double(zone.n_slip) / n_nodes);
    if (!closed)
      quantities.emplace_back(Quantity{Kind::slip_zone_start}.name(),
                              zone.n_slip > 0 ?
                                zone.from :
                                std::numeric_limits<double>::quiet_NaN());
    quantities.emplace_back(Quantity{Kind::first_slip_time}.name(),
                            slip_onset.time);
  }


  namespace
  {
    const PostprocessorRegistration<SlipDiagnostics>
      registration("slip diagnostics", 20);
  }
} // namespace Contact
