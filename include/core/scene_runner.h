/**
 * What runs a scene beyond the one run of ContactProblem<dim>: a part that
 * runs it more than once (the studies, parts/studies/) registers itself as
 * a SceneRunner, and the program (app/run.cc) runs a scene with the
 * registered runner of the lowest rank, or, where no part registered one
 * (a build of the core alone), as one run of ContactProblem<dim>.
 */
#ifndef contact_scene_runner_h
#define contact_scene_runner_h

#include <base/parts.h>
#include <core/parameters.h>

namespace Contact
{
  class SceneRunner
  {
  public:
    virtual ~SceneRunner() = default;

    /** Runs `scene`, in its dimension. */
    virtual void run(const Parameters &scene) = 0;
  };

  using SceneRunners = PartRegistry<SceneRunner>;
} // namespace Contact

#endif
