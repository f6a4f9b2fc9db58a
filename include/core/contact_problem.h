/**
 * ContactProblem<dim>: the dynamic viscoelastic body with bilateral
 * frictional contact and a nonmonotone (slip rate weakening) friction law
 * of Barboteu, Bartosz, Han, Janiczko (SIAM J. Numer. Anal. 53, 2015),
 * discretised as in their section 5: Lagrange finite elements in space and
 * backward Euler in the velocity, (5.2)-(5.5).
 *
 * The class is the core that solves: the mesh and the space V_h
 * (DiscreteSpace), the loads (Loads), the matrices and the factor of K
 * (SystemMatrices), the step state, the friction solver on Gamma_3 and the
 * time loop with its step cuts. It is split over files by phase (the
 * ASPECT habit):
 *   contact_problem.cc  constructor, run(), the initial state, the time
 *                       loop, the summary
 *   setup.cc            make_grid, setup_system
 *   assembly.cc         the matrices, the factor of K, the state's
 *                       products with them (SystemMatrices)
 *   time_stepping.cc    the step, its energy balance and its cuts
 *   mesh_transfer.cc    the move to a mesh adapted during the run
 * What stores the run so that it can be resumed is a part
 * (RunStorage, run_storage.h) that the problem calls at fixed points.
 * Everything that observes a run (output, self-checks, diagnostics) is a
 * Postprocessor (postprocessor.h; the console and VTU in source/core/, the
 * others in source/parts/): the time loop is "advance; then each
 * postprocessor". The friction problem on Gamma_3 (its nodes, the path to the
 * body, the Newton method and the convexification, the nodal state) is a
 * component of its own, FrictionSolver<dim> (friction_solver.h): a step is
 * "right-hand side, friction solver, update".
 */
#ifndef contact_contact_problem_h
#define contact_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <core/parameters.h>
#include <core/discrete_space.h>
#include <core/loads.h>
#include <core/mesh_plan.h>
#include <core/run_storage.h>
#include <core/step_state.h>
#include <core/factorization.h>
#include <core/friction.h>
#include <core/friction_solver.h>
#include <core/geometry.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  using namespace dealii;

  template <int dim>
  class Postprocessor;


  /** M w_n, A w_n and B w_n of a step's velocity (condensed). */
  struct VelocityProducts
  {
    VectorType mass;
    VectorType viscosity;
    VectorType elasticity;
  };


  /**
   * The matrices of (5.2): mass (with rho), viscosity A_h, elasticity B_h,
   * and K = (1/k) M + A_h + k B_h with its factor, all condensed with the
   * constraints (assembly.cc). momentum_density[d]_i = int rho phi_i . e_d
   * and angular_momentum_density_i = int rho (x x phi_i)_z give the
   * momentum and the angular momentum of a velocity as dot products.
   */
  template <int dim>
  struct SystemMatrices
  {
    MatrixType                  mass;
    MatrixType                  viscosity;
    MatrixType                  elasticity;
    MatrixType                  system;
    std::array<VectorType, dim> momentum_density;
    VectorType                  angular_momentum_density;
    /** The factor of K, made once per mesh and again when a step is
     *  cut. */
    std::unique_ptr<Factorization> factorization;

    /** Empty matrices and vectors of the sparsity of `space`, without a
     *  factor. */
    void reinit(const DiscreteSpace<dim> &space);

    /** M, A_h, B_h and the momentum densities on `space`. */
    void assemble(const DiscreteSpace<dim> &space,
                  const MaterialParameters &material);

    /** K for the time step k, and its factor. */
    void factorize(const double              k,
                   const SolverParameters   &solver,
                   const DiscreteSpace<dim> &space,
                   TimerOutput              &timer);

    /** M w, A w and B w of a velocity w of V_h. */
    VelocityProducts
    velocity_products(const VectorType                &w,
                      const AffineConstraints<double> &constraints) const;

    /** M w_n and B u_n, which the next step's right-hand side reads, and
     *  the kinetic and elastic energy from them, after u_n and w_n were
     *  set. */
    void
    update_state_products(StepState                       &state,
                          const AffineConstraints<double> &constraints) const;

    /** int rho w dx: not condensed, since the translations it is tested
     *  with need not lie in V_h. */
    Tensor<1, dim> momentum(const VectorType &w) const
    {
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = momentum_density[d] * w;
      return result;
    }
  };


  /** What a run keeps of itself besides the problem: its wall times (of
   *  the whole run, and of the steps' first solves with K, or
   *  substitutions with its factor, summed over the steps computed by this
   *  process's run, not those before a resumed checkpoint), and the lock
   *  on its output directory (its file descriptor, closed with the last
   *  copy), held by the first process while the run lives. */
  struct RunRecord
  {
    Timer                      run;
    double                     substitution = 0;
    std::shared_ptr<const int> output_directory_lock;
  };


  /** The errors of (5.26): ||eps(u - u_h)|| (the V-norm), ||w - w_h||
   *  and ||u - u_h|| in L2. */
  struct ErrorNorms
  {
    double displacement_V  = 0;
    double velocity_L2     = 0;
    double displacement_L2 = 0;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &displacement_V &velocity_L2 &displacement_L2;
    }
  };


  /** What a whole run gives a driver (a study). */
  struct RunSummary
  {
    /** 'Geometry/Cell size' of a box; the largest cell diameter of a mesh
     *  read from a file. */
    double                  cell_size = 0;
    double                  time_step = 0;
    unsigned int            n_steps   = 0;
    types::global_dof_index n_dofs    = 0;
    double                  wall_time = 0;
    /** Largest error over the steps 1..N, with an exact solution. */
    ErrorNorms max_errors;
    /** ||eps(u_h(T))||: the scale of the V-errors. */
    double displacement_V_norm = 0;
    /** The errors at t = T, with an exact solution. */
    ErrorNorms final_errors;
    /** What a contact engineer reads of the state at T, by name: the
     *  probe displacements, the friction dissipation, the slipping share
     *  of Gamma_3's nodes, where the slip zone starts (on an open Gamma_3;
     *  NaN without slip) and the time of the first slip. An error estimate
     * compares them between runs. */
    std::vector<std::pair<std::string, double>> final_quantities;
  };


  template <int dim>
  class ContactProblem;


  /**
   * What a postprocessor reads of a run (the accessors of Postprocessor):
   * const references to the parts of the problem, which fills it once and
   * hands it to each postprocessor it takes. The loads are made at the
   * start of run() and the friction solver with each mesh, so their
   * owners' pointers are held. The timer is the one non-const part: a
   * postprocessor times its own work in it.
   */
  template <int dim>
  struct RunView
  {
    const ContactProblem<dim>                              &problem;
    const Parameters                                       &parameters;
    const StepState                                        &state;
    const DiscreteSpace<dim>                               &space;
    const SystemMatrices<dim>                              &matrices;
    const std::unique_ptr<Loads<dim>>                      &loads;
    const std::unique_ptr<FrictionSolver<dim>>             &friction_solver;
    const ConditionalOStream                               &pcout;
    TimerOutput                                            &computing_timer;
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &postprocessors;
  };


  template <int dim>
  class ContactProblem
  {
  public:
    explicit ContactProblem(const Parameters &run_parameters);
    virtual ~ContactProblem();

    RunSummary run();

    /** Observes the run after the registered postprocessors (a test, or a
     *  driver collecting solutions at common times); before run(). */
    void add_postprocessor(std::unique_ptr<Postprocessor<dim>> postprocessor);

    /** Runs on the scene's mesh changed by the cycles of `plan` (a mesh
     *  adaptation); before run(). */
    void adapt_mesh(const MeshPlan &plan);

    /** Adapts the mesh during the run after every `interval`-th step (but
     *  the last): `choose_cells` sets the refine and coarsen flags of the
     *  mesh (collective); the problem then records them in its plan and
     *  moves to the new mesh (transfer_to_adapted_mesh()); before run(). */
    void adapt_mesh_during_run(const unsigned int    interval,
                               std::function<void()> choose_cells);

    /** Whether the mesh adapts during the run (adapt_mesh_during_run()):
     *  what the postprocessors ask before they report the energy that the
     *  transfers to new meshes change. */
    bool adapts_mesh_during_run() const
    {
      return adaptation.interval > 0;
    }

    /** The scene's mesh changed by the cycles so far. */
    const MeshPlan &get_mesh_plan() const;

    /** The domain of the run: it built the mesh, and answers what the
     *  postprocessors ask of the domain (GeometryBase). */
    const Geometry<dim> &get_geometry() const
    {
      return *geometry;
    }

    unsigned int           get_step_number() const;
    const DoFHandler<dim> &get_dof_handler() const;
    const Mapping<dim>    &get_mapping() const;
    const VectorType      &get_displacement() const;
    const VectorType      &get_velocity() const;
    /** The nodal friction forces eta on Gamma_3, node-major. */
    const Vector<double> &get_friction_force() const;
    /** ||eps(v)||, the paper's V-norm, of a field on this problem's mesh. */
    double     strain_norm(const VectorType &v) const;
    VectorType ghosted(const VectorType &v) const;

  private:
    // @sect4{The seams of a variant of the scheme}
    //
    // A problem derived from this one (a test's faults,
    // tests/verification/faults.h) overrides these private virtual
    // functions; the run calls them at fixed points and gives them what
    // they may change, so that a variant reaches no member of the problem.

    /** The loads of the run, made once at its start (before anything is
     *  computed or written, so that an expression with an error is refused
     *  first). */
    virtual std::unique_ptr<Loads<dim>>
    create_loads(const Parameters         &run_parameters,
                 const DiscreteSpace<dim> &discrete_space,
                 TimerOutput              &timer) const;

    /** The friction solver on `nodes`, the nodes of Gamma_3 of the current
     *  mesh (make_contact_nodes()). */
    virtual std::unique_ptr<FrictionSolver<dim>>
    create_friction_solver(std::vector<ContactNode<dim>>    nodes,
                           const FrictionSolverEnvironment &environment) const;

    /** Called with M, A_h and B_h of a mesh before K is formed of them. */
    virtual void after_assembly(SystemMatrices<dim> & /*matrices*/) const
    {}

    /** Called after u_n and w_n were carried to an adapted mesh, with the
     *  energies of the state on the new mesh and those before the
     *  transfer; the difference is booked as the transfer's term of the
     *  balance. */
    virtual void after_mesh_transfer(EnergyBalance & /*energy*/,
                                     const EnergyBalance & /*before*/) const
    {}

    // @sect4{The phases of a run}

    // setup.cc
    void make_grid();
    /** V_h, its matrices, the vectors of the state, Gamma_3's nodes and
     *  the friction solver, the loads on them, and M, A_h and B_h. */
    void setup_system();

    // contact_problem.cc
    void time_loop();

    // time_stepping.cc
    /** The step from t_n - k to t_n, cut while it fails and cuts are
     *  left. */
    StepStatistics advance(const unsigned int cuts_left);

    // mesh_transfer.cc
    void transfer_to_adapted_mesh();

    // @sect4{The data members}
    //
    // Each with the file that sets it up or changes it.

    // The parameters (the constructor, contact_problem.cc).
    const Parameters parameters;

    ConditionalOStream  pcout;
    mutable TimerOutput computing_timer;

    // The domain of the .prm, made once: it builds the mesh (setup.cc).
    const std::unique_ptr<const Geometry<dim>> geometry;

    // Mesh, finite element space and constraints (setup.cc), the cycles of
    // a mesh adaptation that change the Geometry's mesh (adapt_mesh()) and
    // those to come during the run (mesh_transfer.cc), and the loads on the
    // space (loads.cc; those of an exact solution where a part gives one).
    DiscreteSpace<dim>          space;
    MeshAdaptation              adaptation;
    std::unique_ptr<Loads<dim>> loads;

    // The matrices and the factor of K (assembly.cc), made once per mesh
    // (and the factor again when a step is cut).
    SystemMatrices<dim> matrices;

    // The state at t_n with the time step k (time_stepping.cc).
    StepState state;

    // The friction problem on Gamma_3: its nodes, the path between them
    // and the body, and their state (friction_solver.cc, created in
    // setup.cc).
    std::unique_ptr<FrictionSolver<dim>> friction_solver;

    // The run's wall times ('Output/Print timings') and the lock on its
    // output directory (contact_problem.cc).
    RunRecord run_record;

    // What stores the members above and the postprocessors so that the
    // run can be resumed (--resume; a part, run_storage.h), if the program
    // has one.
    std::unique_ptr<RunStorage<dim>> storage;

    // What the postprocessors read of the members above (the
    // constructor).
    const RunView<dim> run_view;

    // Everything that observes the run, in the order of their ranks; last,
    // so that they are destroyed first (the VTU output's thread reads the
    // space).
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
  };
} // namespace Contact

#endif
