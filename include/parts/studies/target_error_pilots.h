/**
 * The pilots of a target error (target_error.h): runs of the scene with
 * H, 2H, 4H and K, 2K, 4K for each element degree (and mesh family) that
 * measure how its error falls with h and with k, and what a run costs
 * (target_error_pilots.cc). The target (target_error.cc) chooses from
 * what they measured.
 */
#ifndef contact_target_error_pilots_h
#define contact_target_error_pilots_h

#include <core/parameters.h>
#include <parts/studies/study.h>
#include <parts/studies/sub_run.h>

#include <functional>
#include <string>
#include <vector>

namespace Contact
{
  namespace TargetPilots
  {
    /** A pilot, with its displacement at each of its steps on the mesh of
     *  the pilot with h = H and k = K of its degree. */
    struct Pilot
    {
      std::string  name;
      unsigned int degree;
      /** Of the family of meshes adapted during the run
       *  (scene_variant.cc), with the number of adaptations that changed
       *  its mesh. */
      bool         adapted;
      RunAtTimes   run;
      unsigned int mesh_changes = 0;
    };

    /** The error of one direction (h or k) at the pilots' H or K, with the
     *  order used to extrapolate it, from the three pilots f (H), m (2H)
     *  and c (4H) (or K, 2K, 4K): the Richardson estimate (richardson.h)
     *  for the target quantity, with the order lowered to what the scheme
     *  can give, never raised: below min_plausible_order the direction
     *  predicts nothing (error NaN; a note says why). */
    struct DirectionFit
    {
      double      error = 0;
      double      order = 0;
      std::string note;
    };

    /** What a degree's pilots say, of uniform meshes or of meshes adapted
     *  during the run: the space part of the V-norm and of the target
     *  quantity, and the fit a + b x of their wall times against x =
     *  unknowns * steps (unknowns at T). */
    struct DegreeModel
    {
      unsigned int            degree;
      bool                    adapted;
      DirectionFit            space_V;
      DirectionFit            space;
      types::global_dof_index n_dofs = 0;
      double                  a = 0, b = 1;
    };

    /** Everything the pilots measured. */
    struct PilotResults
    {
      std::vector<Pilot>       pilots;
      std::vector<DegreeModel> models;
      DirectionFit             time_V;
      DirectionFit             time;
      /** |quantity| on the first pilot, the scale of a relative target. */
      double size = 0;
      /** The cosine of the angle between the space and the time error. */
      double cosine    = 1;
      double wall_time = 0;
    };

    /** Whether the scene has two families of candidates, uniform meshes
     *  and meshes adapted during the run: it adapts during the run, and
     *  the target quantity does not need the states over time on one
     *  mesh. */
    bool has_adapted_family(const Parameters &parameters);

    /** The scene as the candidates of a degree and family run it (the
     *  adapted family's 'Target unknowns' scaled to the degree, from the
     *  uniform pilots, which run first). */
    Parameters scene_of(const Parameters   &scene,
                        const PilotResults &results,
                        const unsigned int  degree,
                        const bool          adapted);

    /** Runs the pilots of every degree and family of the scene, each
     *  equipped by `equipment`, printing a line per pilot, and fits the
     *  models. */
    template <int dim>
    PilotResults
    run_pilots(const Parameters                               &parameters,
               const Equipment<dim>                           &equipment,
               const std::function<void(const std::string &)> &print);
  } // namespace TargetPilots
} // namespace Contact

#endif
