/* The V-error at T of runs of a scene against a reference run of it, for
   bench/adapted_mesh.py: a run may be on a mesh adapted by pilots ('Mesh
   adaptation/Cycles'), whose wall time is counted with the run's, or
   adapted during the run ('Mesh adaptation/Interval'; the unknowns printed
   are then those of the last mesh).

     adapted_mesh_error scene.prm reference-entries... [-- run-entries...]...

   Each group of 'Section/Entry=value' settings (the first the reference's,
   then one per run, separated by --) is applied to scene.prm. Printed per
   run: one line "unknowns <N> steps <n> pilots <s> wall <s> error <e>",
   with ||eps(u_ref(T) - I u(T))||, I the nodal interpolant onto the
   reference's space, and the wall times of the pilots and of the run. */

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <app/run.h>
#include <core/contact_problem.h>
#include <parts/adaptation/adapt_during_run.h>
#include <parts/studies/mesh_adaptation.h>
#include <parts/studies/reference_interpolation.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/sub_run.h>

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

template <int dim>
void compare(const std::string                           &scene,
             const std::vector<std::vector<std::string>> &groups)
{
  ContactProblem<dim> reference(read_parameters(scene, groups[0]));
  const RunAtTimes    exact =
    run_onto<dim>(reference, nullptr, 0, "reference.log");
  const ReferenceInterpolation<dim> onto(reference);
  for (unsigned int g = 1; g < groups.size(); ++g)
    {
      const Parameters   parameters = read_parameters(scene, groups[g]);
      dealii::Timer      pilots_timer;
      MeshPlan           plan;
      std::string        table;
      std::ostringstream pilot_lines;
      std::streambuf    *console = std::cout.rdbuf(pilot_lines.rdbuf());
      if (MeshAdaptationParameters::of(parameters).cycles > 0)
        plan = adapt_mesh_by_pilots<dim>(parameters, table);
      std::cout.rdbuf(console);
      const double        pilots = pilots_timer.wall_time();
      dealii::Timer       run_timer;
      ContactProblem<dim> problem(parameters);
      problem.adapt_mesh(plan);
      adapt_during_run(problem, parameters);
      const RunAtTimes run = run_onto<dim>(
        problem, &onto, 0, parameters.output.directory + "/console.log");
      const double wall = run_timer.wall_time();
      const double error =
        strain_distance(reference, exact.displacement, run.displacement);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << "unknowns " << run.summary.n_dofs << " steps "
                  << run.summary.n_steps << " pilots " << pilots << " wall "
                  << wall << " error " << std::setprecision(6) << error
                  << std::endl;
    }
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: adapted_mesh_error scene.prm entries... [-- "
                   "entries...]...\n";
      return 1;
    }
  std::vector<std::vector<std::string>> groups(1);
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--")
      groups.emplace_back();
    else
      groups.back().push_back(argv[i]);
  const unsigned int dimension = read_parameters(argv[1], groups[0]).dimension;
  if (dimension == 2)
    compare<2>(argv[1], groups);
  else
    compare<3>(argv[1], groups);
}
