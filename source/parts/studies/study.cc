/* The simplest study: the scene run once (include/parts/studies/study.h). */

#include <base/dimensions.h>
#include <parts/studies/study.h>

namespace Contact
{
  template <int dim>
  SingleRun<dim>::SingleRun(const Equipment<dim> &equipment)
    : equip(equipment)
  {}


  template <int dim>
  RunResult SingleRun<dim>::run(const Parameters      &scene,
                                const StudyInput<dim> &input)
  {
    ContactProblem<dim> problem(scene);
    problem.adapt_mesh(input.plan);
    equip(problem, scene);
    if (input.equip_scene_run)
      input.equip_scene_run(problem, scene);
    return {problem.run(), {}};
  }


#define INSTANTIATE(dim) template class SingleRun<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
