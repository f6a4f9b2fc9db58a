/**
 * A variant of a scene: the same scene with another h, k, element degree
 * and output directory, as the drivers run it (the levels of a convergence
 * study, the coarse runs of an error estimate, the pilots of a target and
 * the run it chooses).
 */
#ifndef contact_scene_variant_h
#define contact_scene_variant_h

#include <core/parameters.h>

#include <string>

namespace Contact
{
  /** A scene with other h, k, degree and output directory. */
  struct SceneVariant
  {
    /** h = 2^-h_halvings times the scene's, by the entries that the
     *  geometry names (GeometryBase::entries_with_h_halved(): the box's
     *  'Cell size', or 'Mesh refinements' more). Negative: coarser.
     *  Powers of 2 keep the meshes nested and h exact. */
    int h_halvings;
    /** k = T / n_steps (the run a target chooses has a number of steps
     *  that is no power-of-2 multiple of the scene's). */
    unsigned int n_steps;
    unsigned int degree;
    std::string  directory;
    /** A quiet variant (a coarse run of an error estimate, a pilot) writes
     *  what an estimate compares (its state at T and time_series.csv) and,
     *  where it adapts its mesh during the run, the adaptation's files: no
     *  VTU, Gamma_3 history or checkpoint, and it runs without error
     *  estimate or target. A variant that is not quiet has
     *  the output of the scene; of a scene with a target it is the chosen
     *  run, which runs with its error estimate. */
    bool quiet;
    /** false: a scene that adapts its mesh during the run runs on its
     *  uniform mesh instead (the uniform pilots and candidates of a
     *  target). */
    bool adapts_during_run = true;
  };

  /** The parameters of `variant` of `scene`, checked as those of a scene
   *  are. Its used_parameters are the scene's with the entries of the
   *  variant set (numbers with 17 digits, read back as the same double). */
  Parameters parameters_of(const Parameters   &scene,
                           const SceneVariant &variant);
} // namespace Contact

#endif
