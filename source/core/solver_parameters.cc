/* The entries of the solvers and of the verification (.prm subsections
   Solver and Verification): declaration, parsing and the checks of each
   subsection alone. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <core/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace Contact
{
  // @sect3{Solver}

  const ChoiceTable<SolverParameters::LinearSolver> &
  SolverParameters::linear_solvers()
  {
    static const ChoiceTable<LinearSolver> table(
      Entry::linear_solver,
      {{"auto", LinearSolver::automatic},
       {"CHOLMOD", LinearSolver::cholmod},
       {"Amesos_Klu", LinearSolver::amesos_klu},
       {"Amesos_Mumps", LinearSolver::amesos_mumps},
       {"Amesos_Lapack", LinearSolver::amesos_lapack},
       {"CG-AMG", LinearSolver::cg_amg}});
    return table;
  }

  const ChoiceTable<SolverParameters::ContactSolver> &
  SolverParameters::contact_solvers()
  {
    static const ChoiceTable<ContactSolver> table(
      Entry::contact_solver,
      {{"auto", ContactSolver::automatic},
       {"Delassus", ContactSolver::delassus},
       {"constraints", ContactSolver::constraints}});
    return table;
  }

  const ChoiceTable<SolverParameters::FrictionMethod> &
  SolverParameters::friction_methods()
  {
    static const ChoiceTable<FrictionMethod> table(
      Entry::friction_method,
      {{"Newton", FrictionMethod::newton},
       {"convexification", FrictionMethod::convexification}});
    return table;
  }

  namespace
  {
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
      prm.declare_entry(
        "Friction method",
        SolverParameters::friction_methods().name(
          SolverParameters::FrictionMethod::newton),
        SolverParameters::friction_methods().pattern(),
        "How the nonmonotone friction problem of a step is solved. Newton: "
        "a semismooth Newton method on the full law, with the derivative of "
        "the friction coefficient in its Jacobian (on the constraints path "
        "the solver gets the matrix with the weakening capped below the "
        "convexity limit, positive definite, and the true slopes enter by a "
        "low-rank correction), a line search with sufficient decrease of "
        "the step's energy from the previous step's forces, and a "
        "convexification step (a Tresca problem) where the Newton step does "
        "not lower it. An end point beyond the convexity limit must pass a "
        "test of the energy's curvature (a local minimum, not a saddle); "
        "where it does not, or where Newton does not converge within 'Max "
        "Newton iterations', the convexification solves the step. "
        "convexification: the paper's fixed point, one Tresca "
        "problem per iteration (with Anderson acceleration), solved by the "
        "primal-dual active set method; it is the fallback of Newton. Both "
        "find the same solution where the step problem has one; where it "
        "has several (S (a - b) alpha above the convexity limit printed at "
        "start-up) both start with the same Tresca step from the previous "
        "step's state and may then end on different local minima: Newton "
        "returns the one its descent on the step's energy reaches "
        "(doc/algorithm.md), and its summary line counts the steps beyond "
        "the convexity limit and the steps the convexification took over.");
      prm.declare_entry("Max Newton iterations",
                        "50",
                        Patterns::Integer(1),
                        "Iteration limit of the Newton method per step; "
                        "then the convexification takes over.");
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
        SolverParameters::linear_solvers().name(
          SolverParameters::LinearSolver::automatic),
        SolverParameters::linear_solvers().pattern(),
        "How systems with K = (rho/k) M + A + k B are solved. CHOLMOD "
        "(SuiteSparse's supernodal Cholesky, one process) or a Trilinos "
        "Amesos solver (Amesos_Mumps: MUMPS, distributed over the processes) "
        "factorise K once per run; CG-AMG: conjugate gradients with Trilinos "
        "ML's algebraic multigrid (built once per run), for meshes whose "
        "factor does not fit, relative residual " +
          number_text(SolverParameters::cg_relative_residual) +
          ". auto: CHOLMOD on one process, Amesos_Mumps on more.");
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
        SolverParameters::contact_solvers().name(
          SolverParameters::ContactSolver::automatic),
        SolverParameters::contact_solvers().pattern(),
        "How the friction problem of a step is solved. Delassus: on the "
        "tangential unknowns of Gamma_3 alone, with the dense Delassus "
        "operator D = C K^{-1} C^T built once per run: from "
        "Y = L^{-1} P C^T (sparse; K = P^T L L^T P by CHOLMOD), a step then "
        "costs one forward and one backward substitution and dense work on "
        "Gamma_3; with the other linear solvers from Z = K^{-1} C^T (dense, "
        "one solve per tangential unknown of Gamma_3), a step then costs one "
        "solve and a product with Z. constraints: the straightforward path; "
        "every Newton step of the active set method solves on the whole "
        "body with the sticking nodes held fixed as constraints, and "
        "refactorises; no D. auto: Delassus while Gamma_3 has at most " +
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
      linear_solver   = linear_solvers().parse(prm.get("Linear solver"));
      contact_solver  = contact_solvers().parse(prm.get("Contact solver"));
      friction_method = friction_methods().parse(prm.get("Friction method"));
      max_newton_iterations = prm.get_integer("Max Newton iterations");
      step_cuts             = prm.get_integer("Step cuts");
    }
    prm.leave_subsection();

    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (linear_solver == LinearSolver::automatic)
      linear_solver =
        (n_processes == 1 ? LinearSolver::cholmod : LinearSolver::amesos_mumps);
    iterative_linear_solver = (linear_solver == LinearSolver::cg_amg);

    check_entry(convexification_tolerance > 0,
                "Solver/Convexification tolerance",
                convexification_tolerance,
                "a tolerance > 0");
    check_entry(active_set_parameter > 0,
                "Solver/Active set parameter",
                active_set_parameter,
                "a value > 0");
    AssertThrow(linear_solver != LinearSolver::cholmod || n_processes == 1,
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
