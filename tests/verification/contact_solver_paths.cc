/* The ways of solving the friction problem of a step,
   'Solver/Contact solver = Delassus' (on Gamma_3 alone, with D = C K^{-1}
   C^T, built from CHOLMOD's triangular factor or, with another linear
   solver, from the columns of Z = K^{-1} C^T) and '= constraints' (every
   Newton step a solve on the whole body with the stick nodes fixed), run
   the same semismooth Newton method on the same discrete problem: their
   iterates differ by round-off only. Here the three run three scenes, and
   the displacement, the velocity and the nodal friction forces of each
   Delassus path are compared with the constraints path at every step,
   relative to each field's largest value over the run (on two processes,
   the Delassus path from Z with MUMPS):
   - the paper's scene at h = k = 1/32 (2D, 36 steps, stick and slip);
   - prm/inclined_foundation.prm, unrefined (Gamma_3 at 14 degrees, so the
     bilateral constraint couples the x and y dofs of every node);
   - prm/barboteu2015_3d.prm at h = k = 1/8 (3D, slip in turning
     directions, where the slip nodes add the spring (1/beta) t t^T). */

#include <deal.II/base/mpi.h>

#include <core/contact_problem.h>
#include <core/postprocessor.h>
#include <app/run.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

struct Trajectory
{
  std::vector<VectorType>             displacements;
  std::vector<VectorType>             velocities;
  std::vector<dealii::Vector<double>> friction_forces;
};

template <int dim>
Trajectory run(const std::string              &scene,
               const std::vector<std::string> &sets,
               const std::string              &contact_solver,
               const std::string              &linear_solver)
{
  std::vector<std::string> all_sets = sets;
  for (const std::string &set :
       std::vector<std::string>{"Output/VTU interval=0",
                                "Output/Progress interval=0",
                                "Output/Print timings=false",
                                "Output/Report times=",
                                "Output/Output directory=run-" +
                                  contact_solver + "-" + linear_solver})
    all_sets.push_back(set);
  all_sets.push_back("Solver/Contact solver=" + contact_solver);
  all_sets.push_back("Solver/Linear solver=" + linear_solver);
  const Parameters parameters =
    read_parameters(CONTACT_PRM_DIR "/" + scene, all_sets);

  ContactProblem<dim> problem(parameters);
  Trajectory          trajectory;
  problem.add_postprocessor(
    std::make_unique<StepObserver<dim>>([&](const ContactProblem<dim> &p) {
      trajectory.displacements.push_back(p.get_displacement());
      trajectory.velocities.push_back(p.get_velocity());
      trajectory.friction_forces.push_back(p.get_friction_force());
    }));
  // The runs' console output is not part of this test's output.
  std::ostringstream silent;
  auto *const        console = std::cout.rdbuf(silent.rdbuf());
  problem.run();
  std::cout.rdbuf(console);
  return trajectory;
}

// max_n |a_n - b_n|_inf / max_n |a_n|_inf
template <typename Vector>
double relative_difference(const std::vector<Vector> &a,
                           const std::vector<Vector> &b)
{
  AssertThrow(a.size() == b.size(), dealii::ExcInternalError());
  double difference = 0, scale = 1e-300;
  for (unsigned int n = 0; n < a.size(); ++n)
    {
      Vector d(a[n]);
      d -= b[n];
      difference = std::max(difference, d.linfty_norm());
      scale      = std::max(scale, a[n].linfty_norm());
    }
  return difference / scale;
}

// The Delassus paths against the constraints path. On several processes
// CHOLMOD is not available: there MUMPS solves on both paths, and the
// Delassus path works from Z.
template <int dim>
void compare(const std::string              &name,
             const std::string              &scene,
             const std::vector<std::string> &sets)
{
  const bool serial =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
  const Trajectory constraints =
    run<dim>(scene, sets, "constraints", serial ? "CHOLMOD" : "Amesos_Mumps");
  const auto agrees = [&](const std::string &linear_solver) {
    const Trajectory delassus =
      run<dim>(scene, sets, "Delassus", linear_solver);
    return std::max(
             {relative_difference(delassus.displacements,
                                  constraints.displacements),
              relative_difference(delassus.velocities, constraints.velocities),
              relative_difference(delassus.friction_forces,
                                  constraints.friction_forces)}) < 1e-10 ?
             "yes" :
             "no";
  };
  std::ostringstream line;
  line << name << ": " << constraints.displacements.size()
       << " steps; displacement, velocity and friction forces agree with "
          "the constraints path to 1e-10: ";
  if (serial)
    line << "Delassus from CHOLMOD's factor " << agrees("CHOLMOD")
         << ", Delassus from Z (Amesos_Klu) " << agrees("Amesos_Klu");
  else
    line << "Delassus from Z (Amesos_Mumps) " << agrees("Amesos_Mumps");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << line.str() << std::endl;
}

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>("paper's scene, h = k = 1/32",
             "barboteu2015.prm",
             {"Geometry/Cell size=0.03125", "Time/Time step=0.03125"});
  compare<2>("inclined foundation",
             "inclined_foundation.prm",
             {"Geometry/Mesh refinements=0", "Time/Time step=0.0625"});
  compare<3>("3D scene, h = k = 1/8",
             "barboteu2015_3d.prm",
             {"Geometry/Cell size=0.125", "Time/Time step=0.125"});
}
