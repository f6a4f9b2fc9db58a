/**
 * 'Mesh adaptation/Interval' > 0: the mesh adapted during the run from the
 * indicators (mesh_indicators.h) of every Interval-th step
 * (adapt_during_run.cc). It equips a ContactProblem before its run; app/
 * gives it to the studies as their Equipment (study.h), and they equip
 * each run they build with it.
 */
#ifndef contact_adapt_during_run_h
#define contact_adapt_during_run_h

#include <core/parameters.h>
#include <core/contact_problem.h>

namespace Contact
{
  /** Where `parameters` (the problem's own, which must outlive it) ask for
   *  it ('Mesh adaptation/Interval' > 0): makes `problem` adapt its mesh
   *  during its run, from the indicators of the step of each adaptation,
   *  and write adaptation.csv and adapted_mesh.txt; before its run().
   *  Otherwise nothing. */
  template <int dim>
  void adapt_during_run(ContactProblem<dim> &problem,
                        const Parameters    &parameters);
} // namespace Contact

#endif
