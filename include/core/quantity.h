/**
 * The scalars of a run that an error estimate compares between runs of
 * different h and k (the rows of its table) and that a target error
 * chooses from (a study's entry). The code that computes a quantity (the
 * postprocessors) names it by name() and the entry is read by parse():
 * both spell the names of this one table.
 */
#ifndef contact_quantity_h
#define contact_quantity_h

#include <string>
#include <vector>

namespace Contact
{
  struct Quantity
  {
    enum class Kind
    {
      /** The largest V-error ||eps(u - u_h)|| over the times of an
       *  estimate's coarsest run. */
      worst_V_error,
      /** ||eps(u_h(T))||. */
      V_norm,
      friction_dissipation,
      /** The share of Gamma_3's nodes that slip at T. */
      slipping_share,
      /** The smallest x of the slipping nodes at T (an open Gamma_3). */
      slip_zone_start,
      first_slip_time,
      /** A component of the displacement at a probe point at T. */
      probe_displacement
    };

    Kind kind;
    /** probe_displacement: the probe (from 0, in the order of 'Output/Probe
     *  points') and the component. */
    unsigned int probe     = 0;
    unsigned int component = 0;

    /** As the estimate's table and the .prm file spell it. */
    std::string name() const;

    /** Its SI unit in `dim` dimensions ("1" for a share); in 2D the
     *  integrals are per metre of thickness (plane strain). */
    std::string unit(const unsigned int dim) const;

    /** The quantity called `text`; an error names the entry `entry`
     *  ("Subsection/Entry") that gave it and the allowed names. */
    static Quantity parse(const std::string &text, const std::string &entry);

    /** Every quantity of a scene with `n_probes` probe points in `dim`
     *  dimensions. */
    static std::vector<Quantity> of_scene(const unsigned int n_probes,
                                          const unsigned int dim);
  };

  /** The names of Quantity::Kind::V_norm and worst_V_error. */
  inline const std::string V_norm = Quantity{Quantity::Kind::V_norm}.name();
  inline const std::string worst_V_error =
    Quantity{Quantity::Kind::worst_V_error}.name();
} // namespace Contact

#endif
