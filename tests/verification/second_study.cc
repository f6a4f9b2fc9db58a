/* A study added from outside the program, as doc/tutorial.md's checklist
   "Adding a study" describes: a class derived from Study<dim> that wraps
   another study (given at construction) and builds a run of its own as a
   scene variant, defined in this file alone, with no file of base/, core/
   or parts/studies/ changed. It runs the scene (through the wrapped study, in
   the scene's directory) and the scene with k halved (in a subdirectory), and
   gives back the scene's run with the differences of its quantities at T.

   Checked: the wrapped study's run and the study's own run both happen
   (their numbers of steps), the quantities at T of both runs are those of
   the same scene (the same names, in the same order), and the difference
   of the friction dissipation at T between k and k/2 shrinks when k does:
   from k = 1/16 to k = 1/32 by more than a factor 1.2 (it prints the
   factor). */

#include <deal.II/base/mpi.h>

#include <app/run.h>
#include <core/quantity.h>
#include <parts/studies/scene_variant.h>
#include <parts/studies/study.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

namespace
{
  template <int dim>
  class TimeStepHalving : public Study<dim>
  {
  public:
    TimeStepHalving(std::unique_ptr<Study<dim>> wrapped_study,
                    const Equipment<dim>       &equipment)
      : wrapped(std::move(wrapped_study))
      , equip(equipment)
    {}

    RunResult run(const Parameters      &scene,
                  const StudyInput<dim> &input) override
    {
      const RunResult   result = wrapped->run(scene, input);
      const std::string directory =
        scene.output.directory + "/halved-time-step";
      const Parameters    halved = parameters_of(scene,
                                              {0,
                                                  2 * scene.time.n_steps(),
                                                  scene.geometry.fe_degree,
                                                  directory,
                                                  /*quiet=*/true});
      ContactProblem<dim> problem(halved);
      problem.adapt_mesh(input.plan);
      equip(problem, halved);
      const RunSummary finer = problem.run();

      differences.clear();
      for (unsigned int i = 0; i < finer.final_quantities.size(); ++i)
        {
          AssertThrow(finer.final_quantities[i].first ==
                        result.summary.final_quantities[i].first,
                      dealii::ExcInternalError());
          differences.emplace_back(finer.final_quantities[i].first,
                                   finer.final_quantities[i].second -
                                     result.summary.final_quantities[i].second);
        }
      steps = {result.summary.n_steps, finer.n_steps};
      return result;
    }

    std::vector<std::pair<std::string, double>> differences;
    std::pair<unsigned int, unsigned int>       steps;

  private:
    const std::unique_ptr<Study<dim>> wrapped;
    const Equipment<dim>              equip;
  };


  double friction_dissipation(
    const std::vector<std::pair<std::string, double>> &differences)
  {
    for (const auto &[name, value] : differences)
      if (name == Quantity{Quantity::Kind::friction_dissipation}.name())
        return value;
    AssertThrow(false, dealii::ExcMessage("no friction dissipation at T"));
    return 0;
  }
} // namespace


int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Equipment<2> no_equipment = [](ContactProblem<2> &,
                                       const Parameters &) {};

  std::vector<double> dissipation_differences;
  for (const double time_step : {1. / 16, 1. / 32})
    {
      const Parameters scene =
        read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm",
                        {"Geometry/Cell size=0.125",
                         "Time/Time step=" + std::to_string(time_step),
                         "Output/VTU interval=0",
                         "Output/Progress interval=0",
                         "Output/Print timings=false",
                         "Output/Output directory=run-" +
                           std::to_string(int(1 / time_step))});
      TimeStepHalving<2> study(std::make_unique<SingleRun<2>>(no_equipment),
                               no_equipment);
      std::ostringstream console_output;
      auto *const        console = std::cout.rdbuf(console_output.rdbuf());
      study.run(scene, {});
      std::cout.rdbuf(console);

      std::cout << "k = 1/" << int(1 / time_step) << ": the scene's run "
                << study.steps.first << " steps, the study's own run "
                << study.steps.second << " steps; quantities at T compared:";
      for (const auto &[name, difference] : study.differences)
        std::cout << ' ' << name;
      std::cout << std::endl;
      dissipation_differences.push_back(
        std::abs(friction_dissipation(study.differences)));
    }
  const double ratio = dissipation_differences[0] / dissipation_differences[1];
  std::cout << "friction dissipation at T, |D(k/2) - D(k)| for k = 1/16 over "
               "k = 1/32: "
            << std::fixed << std::setprecision(1) << ratio
            << (ratio > 1.2 ? " (shrinks with k)" : " (does NOT shrink with k)")
            << std::endl;
}
