/* The study a scene asks for, composed (include/parts/studies/compose_study.h).
 */

#include <parts/studies/compose_study.h>
#include <base/dimensions.h>
#include <core/scene_runner.h>
#include <parts/adaptation/adapt_during_run.h>
#include <parts/studies/convergence_study.h>
#include <parts/studies/error_estimate.h>
#include <parts/studies/mesh_adaptation.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/target_error.h>

namespace Contact
{
  // The order of the tests is the precedence of the modes; the checks of
  // the parameters refuse the combinations that none of them runs (e.g. a
  // target with pilots, or a convergence study with an estimate).
  template <int dim>
  std::unique_ptr<Study<dim>> compose_study(const Parameters &scene)
  {
    if (ConvergenceStudyParameters::of(scene).levels > 0)
      return std::make_unique<ConvergenceStudy<dim>>();
    const Equipment<dim> equipment = adapt_during_run<dim>;
    if (AccuracyParameters::of(scene).target_error > 0)
      return std::make_unique<TargetError<dim>>(
        std::make_unique<ErrorEstimate<dim>>(equipment), equipment);
    std::unique_ptr<Study<dim>> run;
    if (AccuracyParameters::of(scene).estimate_error)
      run = std::make_unique<ErrorEstimate<dim>>(equipment);
    else
      run = std::make_unique<SingleRun<dim>>(equipment);
    if (MeshAdaptationParameters::of(scene).cycles > 0)
      return std::make_unique<PilotAdaptation<dim>>(std::move(run));
    return run;
  }


#define INSTANTIATE(dim) \
  template std::unique_ptr<Study<dim>> compose_study<dim>(const Parameters &);
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE


  // @sect3{The studies run every scene}

  // The program runs a scene with the study it asks for; without this part
  // it runs every scene once (core/scene_runner.h).
  namespace
  {
    class StudyRunner : public SceneRunner
    {
    public:
      void run(const Parameters &scene) override
      {
#define INSTANTIATE(dim)      \
  if (scene.dimension == dim) \
    compose_study<dim>(scene)->run(scene, {});
        CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
      }
    };

    const bool registered = SceneRunners::add(
      {"studies", "the study that the scene asks for", 10, {}, []() {
         return std::make_unique<StudyRunner>();
       }});
  } // namespace
} // namespace Contact
