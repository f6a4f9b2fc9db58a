/**
 * Where Gamma_3 slips (slip_zone.cc): what the console's reports and the
 * final quantities of a run say of the stick/slip state.
 */
#ifndef contact_slip_zone_h
#define contact_slip_zone_h

#include <core/friction_solver.h>

#include <vector>

namespace Contact
{
  /** The stick/slip state of Gamma_3: its counts, and the x range of the
   *  slipping nodes (empty without slip). */
  struct SlipZone
  {
    unsigned int n_stick = 0;
    unsigned int n_slip  = 0;
    double       from    = 0;
    double       to      = 0;
    // On a closed Gamma_3: the sticking nodes on the arc from `from` to
    // `to`.
    unsigned int n_stick_inside = 0;
  };

  /** The slipping nodes of Gamma_3 and where they are: the range of their
   *  x on an open Gamma_3, or on one closed around the z-axis (`closed`,
   *  GeometryBase::gamma3_is_closed()) the arc about the axis that holds
   *  them. */
  template <int dim>
  SlipZone slip_zone(const std::vector<ContactNode<dim>> &nodes,
                     const std::vector<NodeState>        &node_state,
                     const bool                           closed);


  /**
   * The 'Output/Report times' not met yet. They are not moved onto the time
   * grid: a time is met at the step nearest to it, and one after
   * 'Time/End time' at the last step.
   */
  class ReportTimes
  {
  public:
    explicit ReportTimes(const std::vector<double> &times = {})
      : pending(times)
    {}

    /** The report times met at t_n = `time` (step size `time_step`, the
     *  last step if `last`), which are then no longer pending. */
    std::vector<double>
    take_due(const double time, const double time_step, const bool last);

    /** Drops the times met by the steps up to `step` (of size `time_step`)
     *  of a run that goes on past it: a resumed run's pending times are
     *  its own entry's times after its checkpoint, so that a run extended
     *  to a later 'End time' reports the times that its predecessor met at
     *  its last step only because they lay beyond its end. */
    void drop_met(const unsigned int step, const double time_step);

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &pending;
    }

  private:
    std::vector<double> pending;
  };
} // namespace Contact

#endif
