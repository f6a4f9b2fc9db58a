/**
 * 'Mesh adaptation/Cycles' > 0 (mesh_adaptation.cc).
 */
#ifndef contact_mesh_adaptation_h
#define contact_mesh_adaptation_h

#include <core/parameters.h>
#include <core/mesh_plan.h>
#include <parts/studies/study.h>

#include <memory>
#include <string>

namespace Contact
{
  /** Runs the pilots of the scene, each on the mesh its predecessor adapted
   *  from error indicators gathered over its steps (each in its own
   *  subdirectory adaptation-cycle-c), then the scene on the adapted mesh by
   *  `run_on_adapted_mesh` (a single run, or a run with its error
   *  estimate, whose coarse runs are on that mesh coarsened); the run in
   *  the scene's directory writes the cycles' table (adaptation.txt) and
   *  the adapted mesh's cycles (adapted_mesh.txt). --resume runs on the
   *  mesh its checkpoint stores, without the pilots. */
  template <int dim>
  class PilotAdaptation : public Study<dim>
  {
  public:
    explicit PilotAdaptation(std::unique_ptr<Study<dim>> run_on_adapted_mesh);

    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override;

  private:
    const std::unique_ptr<Study<dim>> adapted_run;
  };
} // namespace Contact

#endif
