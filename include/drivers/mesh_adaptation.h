/**
 * 'Mesh adaptation/Cycles' > 0: pilot runs of the whole scene, each on the
 * mesh its predecessor adapted from error indicators gathered over all of
 * its steps, and then the run on the adapted mesh; 'Mesh adaptation/
 * Interval' > 0: the mesh adapted during the run from the indicators of
 * every Interval-th step (mesh_adaptation.cc).
 */
#ifndef contact_mesh_adaptation_h
#define contact_mesh_adaptation_h

#include <base/parameters.h>
#include <core/contact_problem.h>
#include <core/mesh_plan.h>

#include <string>

namespace Contact
{
  /** Runs the pilots of `scene` (each in its own subdirectory
   *  adaptation-cycle-c), then the scene on the adapted mesh; writes the
   *  cycles' table (adaptation.txt) and the adapted mesh's cycles
   *  (adapted_mesh.txt). --resume runs on the mesh its checkpoint stores,
   *  without the pilots. */
  template <int dim>
  void run_with_mesh_adaptation(const Parameters &scene);

  /** The pilots alone: runs them and returns the adapted mesh's cycles,
   *  and the table of the cycles as text. */
  template <int dim>
  MeshPlan adapt_mesh_by_pilots(const Parameters &scene, std::string &table);

  /** 'Mesh adaptation/Interval' > 0: makes `problem` adapt its mesh during
   *  its run, from the indicators of the step of each adaptation, and write
   *  adaptation.csv and adapted_mesh.txt; before its run(). */
  template <int dim>
  void adapt_during_run(ContactProblem<dim>            &problem,
                        const MeshAdaptationParameters &adaptation);
} // namespace Contact

#endif
