/* Where Gamma_3 slips, and the report times. */

#include <deal.II/base/numbers.h>

#include <base/dimensions.h>
#include <core/slip_zone.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  // @sect4{slip_zone}

  // The slipping nodes of Gamma_3 and where they are: the range of their x
  // on an open Gamma_3; on one closed around the z-axis (a shell's), the
  // smallest arc about the axis that holds them all, from `from` to `to`
  // counterclockwise in degrees: the complement of the widest gap between
  // slipping nodes.
  template <int dim>
  SlipZone slip_zone(const std::vector<ContactNode<dim>> &contact_nodes,
                     const std::vector<NodeState>        &node_state,
                     const bool                           closed)
  {
    SlipZone            zone;
    std::vector<double> angles, stick_angles;
    const auto          angle = [](const Point<dim> &x) {
      return std::atan2(x[1], x[0]) * 180 / numbers::PI;
    };
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      if (node_state[p] == NodeState::stick)
        {
          stick_angles.push_back(angle(contact_nodes[p].location));
          ++zone.n_stick;
        }
      else
        {
          const Point<dim> &x = contact_nodes[p].location;
          zone.from = (zone.n_slip == 0 ? x[0] : std::min(zone.from, x[0]));
          zone.to   = (zone.n_slip == 0 ? x[0] : std::max(zone.to, x[0]));
          angles.push_back(angle(x));
          ++zone.n_slip;
        }
    if (closed && !angles.empty())
      {
        std::sort(angles.begin(), angles.end());
        const unsigned int n = angles.size();
        // From slipping node i to the next one counterclockwise.
        const auto gap = [&](const unsigned int i) {
          return i + 1 < n ? angles[i + 1] - angles[i] :
                             angles[0] + 360 - angles[i];
        };
        unsigned int widest = n - 1;
        for (unsigned int i = 0; i < n; ++i)
          if (gap(i) > gap(widest))
            widest = i;
        zone.from = angles[(widest + 1) % n];
        zone.to   = angles[widest];
        // Counterclockwise from `from`, in [0, 360).
        const auto turn = [&](const double a) {
          return std::fmod(a - zone.from + 720, 360.);
        };
        for (const double a : stick_angles)
          if (turn(a) < turn(zone.to))
            ++zone.n_stick_inside;
      }
    return zone;
  }



  // Whether t_n is the step nearest to t.
  namespace
  {
    bool is_nearest_step(const double t,
                         const double time,
                         const double time_step,
                         const bool   last)
    {
      return std::abs(time - t) <= 0.5 * time_step * (1 + 1e-12) ||
             (last && t > time);
    }
  } // namespace


  std::vector<double> ReportTimes::take_due(const double time,
                                            const double time_step,
                                            const bool   last)
  {
    std::vector<double> due;
    for (auto t = pending.begin(); t != pending.end();)
      if (is_nearest_step(*t, time, time_step, last))
        {
          due.push_back(*t);
          t = pending.erase(t);
        }
      else
        ++t;
    return due;
  }


  void ReportTimes::drop_met(const unsigned int step, const double time_step)
  {
    pending.erase(std::remove_if(pending.begin(),
                                 pending.end(),
                                 [&](const double t) {
                                   return t <= (step + 0.5) * time_step *
                                                 (1 + 1e-12);
                                 }),
                  pending.end());
  }


#define INSTANTIATE(dim)                                             \
  template SlipZone slip_zone(const std::vector<ContactNode<dim>> &, \
                              const std::vector<NodeState> &,        \
                              const bool);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
