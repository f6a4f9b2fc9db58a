/**
 * ContactProblem<dim>: the dynamic viscoelastic body with bilateral
 * frictional contact and a nonmonotone (slip rate weakening) friction law
 * of Barboteu, Bartosz, Han, Janiczko (SIAM J. Numer. Anal. 53, 2015),
 * discretised as in their section 5: Lagrange finite elements in space and
 * backward Euler in the velocity, (5.2)-(5.5).
 *
 * The class is split over several files by phase (the ASPECT habit):
 *   contact_problem.cc  constructor, run()
 *   setup.cc            make_grid, setup_system, constraints, Gamma_3 nodes
 *   assembly.cc         matrices, loads, initial values, energies
 *   time_stepping.cc    factorisation of K, the step and its cuts
 *   output.cc           VTU/PVD, time_series.csv, console
 *   checkpoint.cc       checkpoint and restart
 *   self_checks.cc      the checks every run makes of its own results
 *   verification.cc     errors against a manufactured solution
 * Each file instantiates its own members for dim = 2 and 3. The friction
 * problem on Gamma_3 (its nodes, the path to the body, the Newton method
 * and the convexification, the nodal state) is a component of its own,
 * FrictionSolver<dim> (friction_solver.h): a step is "right-hand side,
 * friction solver, update".
 */
#ifndef contact_contact_problem_h
#define contact_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <gamma3/factorization.h>
#include <gamma3/friction.h>
#include <gamma3/friction_solver.h>
#include <core/manufactured_solution.h>
#include <base/parameters.h>

#include <array>
#include <deque>
#include <fstream>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /**
   * The terms of the discrete energy identity of backward Euler, (5.7)
   * summed over the steps: kinetic + elastic energy now, plus everything
   * dissipated so far (viscous, frictional and the numerical dissipation
   * rho/2 |w_n - w_{n-1}|^2 + k^2/2 <B w_n, w_n> of the scheme) equals the
   * initial energy plus the work of the loads.
   */
  struct EnergyBalance
  {
    double kinetic               = 0;
    double elastic               = 0;
    double initial               = 0;
    double external_work         = 0;
    double viscous_dissipation   = 0;
    double friction_dissipation  = 0;
    double numerical_dissipation = 0;

    double residual() const
    {
      return kinetic + elastic + viscous_dissipation + friction_dissipation +
             numerical_dissipation - initial - external_work;
    }
    double scale() const
    {
      return std::max({kinetic + elastic,
                       initial + std::abs(external_work),
                       viscous_dissipation + std::abs(friction_dissipation) +
                         numerical_dissipation});
    }

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &kinetic &elastic &initial &external_work &viscous_dissipation
        &friction_dissipation &numerical_dissipation;
    }
  };


  /**
   * The self-checks of a run (self_checks.cc, doc/verification.md), each a
   * relative violation that round-off keeps far below
   * ContactProblem::self_check_tolerance:
   *   - algebraic_energy: the energy identity from the products of the
   *     step's matrices with w_n. It holds whenever each step solves its
   *     linear system with the eta it reports, whatever the matrices, the
   *     loads or the friction law: it checks the solve and the bookkeeping.
   *   - quadrature_energy: the same identity with every term integrated
   *     from the fields (1/2 int rho |w_h|^2, 1/2 int B eps(u_h):eps(u_h),
   *     ...) and the loads' expressions, not from the matrices and the
   *     load vector: it catches wrong matrices, loads or constraints.
   *   - friction_law: the friction law (5.3) at the converged slip rates,
   *     FrictionSolver::law_residual: it catches a wrong coefficient, sign
   *     or stick condition. It fails where it exceeds the tolerance and
   *     twice what the convexification's own tolerance allows
   *     (friction_law_allowance, FrictionSolver::law_residual_allowance).
   *   - negative_friction_power: a step whose friction power on the
   *     slipping nodes is negative, relative to the energies (friction
   *     only dissipates; FrictionSolver::slip_power).
   *   - moment_balance: the balance of moments about the z-axis, (5.2)
   *     tested with the rigid rotation r = e_z x x, relative to the
   *     largest sum so far of the magnitudes of the products it adds up
   *     (moment_scale, update_moments()). Checked only where r lies in
   *     V_h (MomentBalance): it catches wrong loads or velocities in the
   *     balance law of the angular momentum.
   */
  struct SelfCheckValues
  {
    double algebraic_energy        = 0;
    double quadrature_energy       = 0;
    double friction_law            = 0;
    double friction_law_allowance  = 0;
    double friction_law_excess     = 0;
    double negative_friction_power = 0;
    double moment_balance          = 0;
    double moment_scale            = 0;

    void take_largest(const SelfCheckValues &other)
    {
      algebraic_energy  = std::max(algebraic_energy, other.algebraic_energy);
      quadrature_energy = std::max(quadrature_energy, other.quadrature_energy);
      friction_law      = std::max(friction_law, other.friction_law);
      friction_law_allowance =
        std::max(friction_law_allowance, other.friction_law_allowance);
      friction_law_excess =
        std::max(friction_law_excess, other.friction_law_excess);
      negative_friction_power =
        std::max(negative_friction_power, other.negative_friction_power);
      moment_balance = std::max(moment_balance, other.moment_balance);
      moment_scale   = std::max(moment_scale, other.moment_scale);
    }

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &algebraic_energy &quadrature_energy &friction_law
        &friction_law_allowance &friction_law_excess &negative_friction_power
          &moment_balance &moment_scale;
    }
  };


  /** deal.II's own distributed vector, for the cell loops that read a
   *  field's entries (self_checks.cc). */
  using FastVector = LinearAlgebra::distributed::Vector<double>;


  /** The integrals of the fields that the energy identity by quadrature
   *  adds up (self_checks.cc). */
  struct FieldIntegrals
  {
    double kinetic       = 0; // 1/2 int rho |w_n|^2
    double velocity_jump = 0; // 1/2 int rho |w_n - w_{n-1}|^2
    double elastic       = 0; // 1/2 int B eps(u_n) : eps(u_n)
    double viscous_power = 0; // int A eps(w_n) : eps(w_n)
    double elastic_power = 0; // int B eps(w_n) : eps(w_n)
  };


  /**
   * The moments about the z-axis through the origin (the axis normal to
   * the plane in 2D) at t_n: the angular momentum L_n = int rho (x x w_n)_z
   * (with the mass matrix's quadrature), the moment of the loads F_n, that
   * of the friction forces -C^T eta_n on the body, and what is left of
   * (L_n - L_{n-1}) / k: the moment of the reactions of the constraints
   * (clamp, normal reactions of Gamma_3 and of symmetry planes). (5.2)
   * tested with the rotation r = e_z x x gives
   *   (L_n - L_{n-1}) / k = applied + friction + reaction
   * where r lies in V_h, with reaction = 0: no clamp, and every normal
   * constraint normal to r, as on a Gamma_3 that is a circle or a cylinder
   * around the z-axis; and the mapping's degree at most the element's, so
   * that r is its own interpolant.
   */
  struct MomentBalance
  {
    double angular_momentum = 0;
    double applied          = 0;
    double friction         = 0;
    double reaction         = 0;
  };


  /** F(t) . w of a field w, and the sum of the magnitudes of the products
   *  it is the sum of: the scale of its round-off. */
  struct LoadPower
  {
    double power     = 0;
    double magnitude = 0;
  };


  /** M w_n, A w_n and B w_n of a step's velocity (condensed). */
  struct VelocityProducts
  {
    VectorType mass;
    VectorType viscosity;
    VectorType elasticity;
  };


  /** The errors of (5.26): ||eps(u - u_h)|| (the V-norm), ||w - w_h||
   *  and ||u - u_h|| in L2. */
  struct ErrorNorms
  {
    double displacement_V  = 0;
    double velocity_L2     = 0;
    double displacement_L2 = 0;
  };

  /** What a whole run gives a convergence study. */
  struct RunSummary
  {
    /** 'Geometry/Cell size' of a box; the largest cell diameter of a mesh
     *  read from a file. */
    double                  cell_size = 0;
    double                  time_step = 0;
    unsigned int            n_steps   = 0;
    types::global_dof_index n_dofs    = 0;
    double                  wall_time = 0;
    /** Largest error over the steps 1..N, with a manufactured solution. */
    ErrorNorms max_errors;
    /** ||eps(u_h(T))||: the scale of the V-errors. */
    double displacement_V_norm = 0;
    /** The errors at t = T, with a manufactured solution. */
    ErrorNorms final_errors;
    /** What a contact engineer reads of the state at T, by name: the
     *  probe displacements, the friction dissipation, the slipping share
     *  of Gamma_3's nodes, where the slip zone starts (on an open Gamma_3;
     *  NaN without slip) and the time of the first slip. An error estimate
     * compares them between runs. */
    std::vector<std::pair<std::string, double>> final_quantities;
  };


  /** Creates `directory` and locks it for this process while the returned
   *  handle lives (collective; throws, naming the holder, when another
   *  process has it). The kernel releases the lock however the process
   *  ends. */
  std::shared_ptr<const int> lock_output_directory(const std::string &directory,
                                                   const MPI_Comm communicator);

  /** Removes what earlier runs left in `directory`: the files this program
   *  writes (VTU/PVD, time series, Gamma_3 history, parameters,
   *  checkpoints, estimate, target and study tables) and the coarse-*,
   *  level-* and (unless kept) pilot-* directories of such runs; other
   *  files stay. On the first process. */
  void remove_results(const std::string &directory,
                      const bool         keep_pilots,
                      const MPI_Comm     communicator);

  /** The names of a target's pilot directories (target_error.cc), which a
   *  fresh run removes with its other results. */
  inline const std::string pilot_directory_pattern =
    "pilot-q[12]-[24]?h-[24]?k";


  /** The stick/slip state of Gamma_3: its counts, and the x range of the
   *  slipping nodes (empty without slip). */
  struct SlipZone
  {
    unsigned int n_stick = 0;
    unsigned int n_slip  = 0;
    double       from    = 0;
    double       to      = 0;
    // On a shell: the sticking nodes on the arc from `from` to `to`.
    unsigned int n_stick_inside = 0;
  };


  /**
   * The first slip of a run (ContactProblem::track_slip_onset): its time
   * (NaN while every node sticks), its step, how the time was found, and
   * the friction's utilisation max_p |eta_p| / (m_p S mu(0)) of the last
   * two steps in which every node stuck, from which it is extrapolated.
   */
  struct SlipOnset
  {
    enum class Estimate : unsigned int
    {
      extrapolated, // within the step, from the utilisation
      beyond_step,  // the extrapolation passes t_n: t_n
      not_rising,   // the utilisation did not rise: t_{n-1}
      too_few_steps // fewer than two all-stick steps before: t_{n-1}
    };

    double       time        = std::numeric_limits<double>::quiet_NaN();
    unsigned int step        = 0;
    Estimate     estimate    = Estimate::too_few_steps;
    double       utilisation = 0;
    double       previous_utilisation = 0;
    unsigned int stick_steps          = 0;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &time &step &estimate &utilisation &previous_utilisation
        &stick_steps;
    }
  };


  template <int dim>
  class ContactProblem
  {
  public:
    explicit ContactProblem(const Parameters &run_parameters);
    ~ContactProblem();

    RunSummary run();

    /**
     * Called at the end of every time step with the problem itself; a
     * convergence study uses it to collect solutions at common times.
     */
    void set_step_observer(
      const std::function<void(const ContactProblem<dim> &)> &observer);

    /** Errors injected on purpose: for the tests of the self-checks only,
     *  before run(). */
    void set_sabotage(const Sabotage<dim> &sabotage);

    unsigned int           get_step_number() const;
    const DoFHandler<dim> &get_dof_handler() const;
    const VectorType      &get_displacement() const;
    const VectorType      &get_velocity() const;
    /** The nodal friction forces eta on Gamma_3, node-major. */
    const Vector<double> &get_friction_force() const;

    /** ||eps(v)||, the paper's V-norm, of a field on this problem's mesh. */
    double strain_norm(const VectorType &v) const;

    const Mapping<dim> &get_mapping() const;
    /** A copy of a distributed vector with this process's ghost entries, for
     *  FEValues, DataOut and point evaluation. */
    VectorType ghosted(const VectorType &v) const;

  private:
    // setup.cc
    void         make_grid();
    void         build_mesh(Triangulation<dim> &mesh);
    unsigned int make_box(Triangulation<dim> &mesh);
    unsigned int make_shell(Triangulation<dim> &mesh);
    void         check_memory(const double       cells,
                              const double       unknowns,
                              const std::string &entry) const;
    unsigned int read_mesh_file(Triangulation<dim> &mesh);
    void         grade_towards_points(Triangulation<dim> &mesh);
    void         check_boundary_ids(const Triangulation<dim> &mesh) const;
    void         setup_system();
    void         make_constraints();
    std::vector<ContactNode<dim>> contact_nodes() const;
    std::map<types::global_dof_index, ContactNode<dim>>
                 integrate_contact_faces() const;
    void         setup_probes();
    unsigned int probe_near_curved_boundary(
      const Point<dim> &point,
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
        &probe) const;

    // assembly.cc
    using CellVisitor =
      std::function<void(const typename DoFHandler<dim>::active_cell_iterator &,
                         const Vector<double> &)>;
    using NodeVisitor =
      std::function<void(const ContactNode<dim> &, const Tensor<1, dim> &)>;
    void assemble_matrices();
    void form_system_matrix();
    void visit_loads(const double       load_time,
                     const bool         with_body_force,
                     const bool         with_surface_loads,
                     const CellVisitor &visit_cell,
                     const NodeVisitor &visit_node) const;
    void assemble_load(const double load_time,
                       VectorType  &load_vector,
                       const bool   with_body_force,
                       const bool   with_surface_loads) const;
    void assemble_constant_body_load();
    std::vector<LoadPower>
                     load_power(const double                           load_time,
                                const std::vector<const FastVector *> &fields) const;
    void             set_initial_values();
    void             warn_of_normal_component(const VectorType  &values,
                                              const std::string &entry) const;
    void             condensed_product(const MatrixType &matrix,
                                       const VectorType &x,
                                       VectorType       &product) const;
    Tensor<1, dim>   momentum() const;
    VelocityProducts velocity_products() const;
    void             update_energy_balance(const VelocityProducts &products);

    // time_stepping.cc
    void           factorize_system_matrix();
    void           change_time_step(const double k);
    StepStatistics advance(const unsigned int cuts_left);
    StepStatistics do_time_step();
    StepLabel      step_label() const;

    // contact_problem.cc
    void time_loop();

    // contact_problem.cc: Gauss rules of n points per direction on the
    // cells and faces of the mesh's shape.
    Quadrature<dim>     gauss_rule(const unsigned int n_points) const;
    Quadrature<dim - 1> face_gauss_rule(const unsigned int n_points) const;

    // self_checks.cc
    FastVector     fast_ghosted(const VectorType &v) const;
    FieldIntegrals field_integrals(const FastVector &u,
                                   const FastVector &w,
                                   const FastVector &old_w) const;
    void           setup_moment_balance();
    void           start_self_checks();
    void           check_step();
    double         update_moments(const LoadPower &applied);
    void           print_self_checks() const;
    void           print_why_moments_are_not_checked() const;
    void           require_self_checks() const;

    // verification.cc
    void       check_manufactured_setup() const;
    ErrorNorms compute_errors() const;

    // checkpoint.cc
    std::string checkpoint_name() const;
    std::string checkpoint_shape() const;
    bool        checkpoint_due() const;
    void        require_checkpoint() const;
    void        save_checkpoint();
    void        load_checkpoint();
    std::string read_checkpoint_payload() const;
    void        cut_output_back_to_checkpoint() const;
    template <class Archive>
    void serialize_checkpoint_state(Archive &archive);

    // output.cc
    void claim_output_directory();
    void prepare_output_directory();
    struct VtuOutput;
    std::string vtu_piece_name(const unsigned int step,
                               const unsigned int process) const;
    void        write_vtu();
    void        cell_average_stress(VtuOutput &output) const;
    void        add_vtu_fields(VtuOutput &output) const;
    void write_vtu_piece(VtuOutput &output, const std::string &file) const;
    void finish_vtu();
    void write_pvd() const;
    void write_time_series_row(const StepStatistics &statistics);
    void write_gamma3_history_rows();
    Tensor<1, dim> probe_displacement(const unsigned int probe,
                                      const VectorType  &u_ghosted) const;
    void           print_progress(const StepStatistics &statistics) const;
    bool           is_nearest_step(const double t) const;
    bool           report_due() const;
    SlipZone       slip_zone() const;
    void           track_slip_onset();
    void           print_slip_onset() const;
    void           report_contact_state();
    std::vector<std::pair<std::string, double>> final_quantities() const;
    void                                        print_summary() const;

    // The data members, each group with the file that sets it up or
    // changes it.
    //
    // Parameters and the objects fixed by them (the constructor,
    // contact_problem.cc).
    const Parameters   parameters;
    const FrictionLaw  friction_law;
    const unsigned int n_time_steps;
    // The time step k: constant, except while a step is cut
    // ('Solver/Step cuts').
    double time_step;

    MPI_Comm            mpi_communicator;
    ConditionalOStream  pcout;
    mutable TimerOutput computing_timer;

    // The load data, as muparser expressions of (x, y[, z], t) (the
    // constructor; evaluated in assembly.cc).
    std::unique_ptr<FunctionParser<dim>> body_force;
    std::unique_ptr<FunctionParser<dim>> initial_displacement;
    std::unique_ptr<FunctionParser<dim>> initial_velocity;
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
      tractions;
    // With 'Verification/Manufactured solution', the exact solution that
    // replaces the load data above.
    std::unique_ptr<const ManufacturedSolution<dim>> exact_solution;
    // A body force that does not depend on t is assembled once; its cell
    // vectors (of the locally owned cells, in the order of the cell loop)
    // give its power in load_power().
    const bool                  body_force_is_constant;
    VectorType                  constant_body_load;
    std::vector<Vector<double>> constant_body_cell_loads;

    // Mesh and finite element space (setup.cc): p4est's distributed
    // triangulation and Q_p for hypercubes, a plain triangulation with P_p
    // (FE_SimplexP and its MappingFE) for simplices, which p4est does not
    // handle. The scalar space of the same degree carries the Gamma_3
    // quantities (slip rate, status) for output.
    const std::unique_ptr<Triangulation<dim>>       triangulation;
    const std::unique_ptr<const FiniteElement<dim>> scalar_fe;
    const FESystem<dim>                             fe;
    const std::unique_ptr<const Mapping<dim>>       mapping;
    const Quadrature<dim>                           quadrature;
    const Quadrature<dim>                           mass_quadrature;
    const Quadrature<dim - 1>                       face_quadrature;
    DoFHandler<dim>                                 dof_handler;
    DoFHandler<dim>                                 scalar_dof_handler;
    IndexSet                                        locally_owned_dofs;
    IndexSet                                        locally_relevant_dofs;

    // Clamped Gamma_1 (u = 0, hence w = 0) and the bilateral Gamma_3
    // (w.n = 0) as homogeneous constraints: V_h of the paper
    // (make_constraints(), setup.cc).
    AffineConstraints<double> constraints;

    // The matrices of (5.2): mass (with rho), viscosity A_h, elasticity
    // B_h, and K = (1/k) M + A_h + k B_h, all condensed with the
    // constraints (assembly.cc). K is factorised once per run
    // (time_stepping.cc). momentum_density[d]_i = int rho phi_i . e_d and
    // angular_momentum_density_i = int rho (x x phi_i)_z give the momentum
    // and the angular momentum of a velocity as dot products.
    MatrixType                     mass_matrix;
    MatrixType                     viscosity_matrix;
    MatrixType                     elasticity_matrix;
    MatrixType                     system_matrix;
    std::array<VectorType, dim>    momentum_density;
    VectorType                     angular_momentum_density;
    std::unique_ptr<Factorization> factorization;

    // The time step state: u_n, w_n, the loads F_n and the previous ones
    // (do_time_step(), time_stepping.cc).
    double       time;
    unsigned int step_number;
    VectorType   displacement;
    VectorType   velocity;
    VectorType   old_displacement;
    VectorType   old_velocity;
    VectorType   load;
    // What the next step's right-hand side needs of this one: M w_{n-1}
    // and B u_{n-1} (condensed, updated by the time step), and the
    // right-hand side of the step without friction: K w_free = step_rhs.
    VectorType mass_times_velocity;
    VectorType elasticity_times_displacement;

    // The friction problem on Gamma_3: its nodes, the path between them
    // and the body, and their state (friction_solver.cc, created in
    // setup.cc).
    std::unique_ptr<FrictionSolver<dim>> friction_solver;

    // The energy balance of the discrete identity (assembly.cc).
    EnergyBalance energy;
    // The self-checks (self_checks.cc): the energy identity's terms by
    // quadrature, and the checks' values of the last step and their
    // largest over the steps.
    EnergyBalance   energy_by_quadrature;
    SelfCheckValues step_checks;
    SelfCheckValues largest_checks;
    // The rotation r = e_z x x (interpolated), its tangential components on
    // Gamma_3 (C r), how much the constraints change it relative to its
    // size, whether it lies in V_h (the moment balance is then a
    // self-check), and the moments of the last step.
    FastVector     rotation;
    Vector<double> rotation_on_gamma3;
    double         rotation_defect           = 0;
    bool           moment_balance_is_checked = false;
    MomentBalance  moments;
    // Above it a self-check has failed, and the run ends with an error
    // (the summary prints which).
    static constexpr double self_check_tolerance = 1e-8;
    Sabotage<dim>           sabotage;

    // Output state (output.cc). A probe is the cell around an 'Output/Probe
    // points' entry and the point in its reference cell; of the processes that
    // own a cell around the point, the first evaluates it, the others keep an
    // invalid cell.
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
                                                probes;
    std::ofstream                               time_series;
    std::ofstream                               gamma3_history;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<double>                         pending_report_times;
    SlipOnset                                   slip_onset;
    StepStatistics                              totals;
    // Wall time of the steps' first solves with K (or substitutions with
    // its factor), summed over the steps computed by this process's run
    // (not those before a resumed checkpoint), and their number.
    double                                           substitution_time = 0;
    unsigned int                                     steps_timed       = 0;
    ErrorNorms                                       current_errors;
    ErrorNorms                                       max_errors;
    std::function<void(const ContactProblem<dim> &)> step_observer;
    Timer                                            run_timer;
    // Wall time since the last checkpoint, for 'Output/Checkpoint minutes'.
    Timer checkpoint_timer;
    // Wall time of the time loop of this run (not the setup before it), for
    // the time left in the progress line.
    Timer time_loop_timer;
    // The lock on the output directory (its file descriptor, closed with
    // the last copy), held by the first process while the run lives.
    std::shared_ptr<const int> output_directory_lock;
    // The VTU output being written in the background (output.cc), last so
    // that it is destroyed first: its destructor waits for the thread,
    // which reads the members above.
    std::shared_ptr<VtuOutput> pending_vtu;
  };
} // namespace Contact

#endif
