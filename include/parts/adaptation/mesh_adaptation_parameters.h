/**
 * The entries of the mesh adaptation, the subsection Mesh adaptation of the
 * .prm file (mesh_adaptation_parameters.cc): of the pilot runs that adapt
 * the mesh to the whole run (parts/studies/mesh_adaptation.h) and of the
 * adaptation during the run (adapt_during_run.h). The studies register the
 * subsection after their own (parts/studies/study_parameters.h) and check
 * it against them.
 */
#ifndef contact_mesh_adaptation_parameters_h
#define contact_mesh_adaptation_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <core/parameters.h>

#include <array>
#include <string>

namespace Contact
{
  using namespace dealii;

  /**
   * The entries of the mesh adaptation that code outside
   * mesh_adaptation_parameters.cc names, as "Subsection/Entry".
   * unit/entry_paths checks that every one of them is declared.
   */
  namespace Entry
  {
    inline const std::string adaptation_cycles   = "Mesh adaptation/Cycles";
    inline const std::string adaptation_interval = "Mesh adaptation/Interval";
    inline const std::string refine_fraction =
      "Mesh adaptation/Refine fraction";
    inline const std::string coarsen_fraction =
      "Mesh adaptation/Coarsen fraction";
    inline const std::string target_unknowns =
      "Mesh adaptation/Target unknowns";
    inline const std::string max_levels = "Mesh adaptation/Max levels";
    inline const std::string indicators = "Mesh adaptation/Indicators";
  } // namespace Entry


  /** The subsection Mesh adaptation: pilot runs that adapt the mesh to
   *  the whole run (parts/studies/mesh_adaptation.h), or the adaptation during
   *  the run (parts/adaptation/adapt_during_run.h). */
  struct MeshAdaptationParameters
  {
    /** 0: off; else the number of pilot runs, each on the mesh its
     *  predecessor adapted. */
    unsigned int cycles;
    /** 0: not during the run; else the mesh is adapted after every
     *  this many steps (ContactProblem::adapt_mesh_during_run()). */
    unsigned int interval;
    /** The shares of the cells refined and coarsened per cycle. */
    double refine_fraction;
    double coarsen_fraction;
    /** 0: refine by the fraction; else refine towards this many unknowns
     *  at the last cycle. */
    unsigned int target_unknowns;
    /** The finest cells: this many levels below the scene's coarsest. */
    unsigned int max_levels;
    /** Which indicators choose the cells: Kelly's of the displacement, of
     *  the velocity, the variation of the slip rate on Gamma_3. */
    std::array<bool, 3>                      indicators;
    static const std::array<std::string, 3> &indicator_names();

    /** The values of the scene's entries; the non-const one for a driver
     *  that changes them in its own copy of the scene (a target's adapted
     *  pilots). */
    static const MeshAdaptationParameters &of(const Parameters &parameters);
    static MeshAdaptationParameters       &of(Parameters &parameters);

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
    /** "Entry '...' = n adapts the mesh: ", naming the entry that makes
     *  the mesh adapt, the start of the messages that refuse what cannot
     *  be combined with it; empty if nothing adapts the mesh. */
    std::string what_adapts() const;

    /** The checks against the scene's entries. */
    void check(const Parameters &parameters) const;

    /** The name of its part (registered among the studies'
     *  subsections, parts/studies/study_parameters.cc). */
    inline static const std::string part_name = "mesh adaptation";
  };
} // namespace Contact

#endif
