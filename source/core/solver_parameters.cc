/* The entries of the solvers and of the verification (.prm subsections
   Solver and Verification): declaration, parsing and the checks of each
   subsection alone. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <base/dimensions.h>
#include <core/factorization.h>
#include <core/friction_method.h>
#include <core/friction_solver.h>
#include <core/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Contact
{
  // @sect3{Solver}

  namespace
  {
    // The parts that an entry of Solver chooses: each is registered in
    // every compiled dimension, and the entry lists those of one.
    constexpr int names_dimension = is_compiled_dimension(2) ? 2 : 3;
    using LinearSolvers           = LinearSolverRegistry;
    using ContactPaths            = ContactPathRegistry<names_dimension>;
    using FrictionMethods         = FrictionMethodRegistry<names_dimension>;

    // The help texts list the parts as they always did: the parts' words
    // in the order of their ranks, and 'auto' last.
    template <class Registry>
    std::string descriptions(const bool with_names)
    {
      std::string text;
      for (const auto &part : Registry::parts())
        if (!part.description.empty())
          text += (text.empty() ? "" : " ") +
                  (with_names ? part.name + ": " : std::string()) +
                  part.description;
      return text;
    }

    // The value of an entry that chooses a part or 'auto'.
    template <class Registry>
    std::string part_or_auto(const std::string &entry, const std::string &name)
    {
      return name == "auto" ? name : Registry::parse(entry, name);
    }


    // The entries of the friction problem's solver, in the subsection
    // Solver.
    void declare_friction_method_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Convexification tolerance",
        "1e-12",
        Patterns::Double(0),
        "The convexification stops when the slip rates on Gamma_3 change by "
        "less than this, relative to the largest tangential velocity, and the "
        "slip set does not change.");
      prm.declare_entry("Friction method",
                        FrictionMethods::parts().front().name,
                        Patterns::Selection(
                          FrictionMethods::selection(Entry::friction_method)),
                        "How the nonmonotone friction problem of a step is "
                        "solved. " +
                          descriptions<FrictionMethods>(true));
      Parts::declare_entries_after(prm, "Solver", "Friction method");
      prm.declare_entry("Max convexification iterations",
                        "200",
                        Patterns::Integer(2),
                        "Iteration limit of the convexification per step (at "
                        "least 2: it stops when the slip set repeats).");
      prm.declare_entry("Max active set iterations",
                        "500",
                        Patterns::Integer(1),
                        "Iteration limit of the primal-dual active set "
                        "method per Tresca problem. Usually a few suffice; "
                        "a nearly incompressible material (Poisson ratio "
                        "0.4999) needed 218 in one step of the paper's "
                        "scene at h = k = 1/16 (bench/extremes.py).");
      prm.declare_entry(
        "Active set parameter",
        "0.05",
        Patterns::Double(0),
        "c_p / K_pp in z_p = eta_p + c_p w_tau,p; 0.01 to 0.1 avoids the "
        "cycling at slip onset seen with c_p = K_pp.");
      prm.declare_entry(
        "Anderson depth",
        "5",
        Patterns::Integer(0, 20),
        "Number of previous iterates that Anderson acceleration of the "
        "convexification combines; 0 gives the paper's plain iteration. An "
        "accelerated iterate that does not lower the step's energy is "
        "rejected.");
    }

    // The entries of the linear solver and of the contact path, in the
    // subsection Solver.
    void declare_linear_solver_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Linear solver",
        "auto",
        Patterns::Selection("auto|" +
                            LinearSolvers::selection(Entry::linear_solver)),
        "How systems with K = (rho/k) M + A + k B are solved. " +
          descriptions<LinearSolvers>(false) +
          " auto: CHOLMOD on one process, Amesos_Mumps on more.");
      prm.declare_entry(
        "Step cuts",
        "0",
        Patterns::Integer(0, 20),
        "When the convexification or the active set method of a step does "
        "not converge, take the step again as two steps of k/2 (refactorising "
        "K), each of which may be cut again, at most this many times in a "
        "row; then k is restored. 0: a step that does not converge ends the "
        "run with its diagnostic. The console reports every cut and "
        "time_series.csv counts them (column step_cuts).");
      prm.declare_entry(
        "Contact solver",
        "auto",
        Patterns::Selection("auto|" +
                            ContactPaths::selection(Entry::contact_solver)),
        "How the friction problem of a step is solved. " +
          descriptions<ContactPaths>(true) +
          " auto: Delassus while Gamma_3 has at most " +
          std::to_string(SolverParameters::max_delassus_unknowns) +
          " tangential unknowns (the dense Newton steps cost O(n^3) in their "
          "number n) and, without CHOLMOD, the linear solver is direct and Z "
          "fits in " +
          number_text(SolverParameters::max_delassus_bytes / 1e9) +
          " GB per process; constraints otherwise.");
    }
  } // namespace

  void SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      declare_friction_method_entries(prm);
      declare_linear_solver_entries(prm);
    }
    prm.leave_subsection();
  }

  void SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      convexification_tolerance = prm.get_double("Convexification tolerance");
      max_convexification_iterations =
        prm.get_integer("Max convexification iterations");
      max_active_set_iterations = prm.get_integer("Max active set iterations");
      active_set_parameter      = prm.get_double("Active set parameter");
      anderson_depth            = prm.get_integer("Anderson depth");
      linear_solver   = part_or_auto<LinearSolvers>(Entry::linear_solver,
                                                  prm.get("Linear solver"));
      contact_solver  = part_or_auto<ContactPaths>(Entry::contact_solver,
                                                  prm.get("Contact solver"));
      friction_method = FrictionMethods::parse(Entry::friction_method,
                                               prm.get("Friction method"));
      step_cuts       = prm.get_integer("Step cuts");
    }
    prm.leave_subsection();

    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    // 'auto': CHOLMOD on one process, on more the distributed MUMPS where
    // the build has it.
    if (linear_solver == "auto")
      linear_solver =
        (n_processes == 1 || !LinearSolvers::is_registered("Amesos_Mumps") ?
           cholmod_name :
           "Amesos_Mumps");
    check_entry(convexification_tolerance > 0,
                "Solver/Convexification tolerance",
                convexification_tolerance,
                "a tolerance > 0");
    check_entry(active_set_parameter > 0,
                "Solver/Active set parameter",
                active_set_parameter,
                "a value > 0");
    AssertThrow(linear_solver != cholmod_name || n_processes == 1,
                ExcMessage("'Solver/Linear solver = CHOLMOD' runs on one MPI "
                           "process; on " +
                           std::to_string(n_processes) +
                           " processes choose auto or an Amesos solver "
                           "(Amesos_Mumps distributes the factor)."));
  }


  // @sect3{Verification}

  const ChoiceTable<VerificationParameters::Solution> &
  VerificationParameters::solutions()
  {
    static const ChoiceTable<Solution> table(
      Entry::manufactured_solution,
      {{"none", Solution::none}, {"slip front", Solution::slip_front}});
    return table;
  }

  void VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    {
      prm.declare_entry(
        "Manufactured solution",
        solutions().name(Solution::none),
        solutions().pattern(),
        "slip front: solve for the exact solution of ManufacturedSolution "
        "(a stick zone x < 1/2 and a slip zone x > 1/2 on Gamma_3 = {y = 0}, "
        "Gamma_1 = {x = 0}); body force, tractions of all sides but Gamma_1 "
        "and Gamma_3, a tangential load on Gamma_3 and the initial values are "
        "then computed from it (the entries for them are ignored), and the "
        "errors are reported.");
      prm.declare_entry("Amplitude",
                        "0.1",
                        Patterns::Double(0),
                        "A in u = A (t + t^2/2) U(x) [m/s]; the slip rate on "
                        "Gamma_3 reaches A (1 + t)/8.");
    }
    prm.leave_subsection();
  }

  void VerificationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    {
      manufactured_solution =
        solutions().parse(prm.get("Manufactured solution"));
      amplitude = prm.get_double("Amplitude");
    }
    prm.leave_subsection();
  }
} // namespace Contact
