/**
 * The study that a scene asks for, composed of the studies of parts/studies/
 * (compose_study.cc): a convergence study, a run to a target error (whose
 * chosen run is a run with its error estimate), pilots that adapt the mesh
 * (wrapping a single run or a run with its error estimate), a run with its
 * error estimate, or a single run. Every study that builds runs is given
 * the mesh adaptation during the run (adapt_during_run()) to equip them
 * with.
 */
#ifndef contact_compose_study_h
#define contact_compose_study_h

#include <core/parameters.h>
#include <parts/studies/study.h>

#include <memory>

namespace Contact
{
  /** The study of `scene`; run it with `study->run(scene, {})`. */
  template <int dim>
  std::unique_ptr<Study<dim>> compose_study(const Parameters &scene);
} // namespace Contact

#endif
