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
 *   contact_solver.cc   factorisation, Delassus operator, convexification
 *   active_set_constraints.cc  the straightforward path (whole-body solves)
 *   output.cc           VTU/PVD, time_series.csv, console
 *   checkpoint.cc       checkpoint and restart
 *   verification.cc     errors against a manufactured solution
 * Each file instantiates its own members for dim = 2 and 3.
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
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <delassus_operator.h>
#include <factorization.h>
#include <friction.h>
#include <manufactured_solution.h>
#include <parameters.h>

#include <array>
#include <deque>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  using namespace dealii;

  using MatrixType = TrilinosWrappers::SparseMatrix;
  using VectorType = TrilinosWrappers::MPI::Vector;

  /**
   * A node p of Gamma_3 that is not clamped: its dofs, its weight
   * m_p = int_Gamma3 phi_p ds, its outward normal and an orthonormal basis
   * of the tangent plane (one tangent in 2D, two in 3D). The tangential
   * unknowns of Gamma_3 (slip velocity, nodal friction force eta_p, the
   * node's share of the friction traction eta_p / m_p) are stored node-major
   * in vectors of length (dim - 1) times the number of nodes.
   */
  template <int dim>
  struct ContactNode
  {
    std::array<types::global_dof_index, dim> dofs;
    types::global_dof_index             scalar_dof = numbers::invalid_dof_index;
    Point<dim>                          location;
    Tensor<1, dim>                      normal;
    std::array<Tensor<1, dim>, dim - 1> tangents;
    double                              weight = 0;
    // Whether this process owns the node's dofs (all dofs of a vertex have
    // one owner). Every process keeps all nodes of Gamma_3; what a node
    // contributes to a distributed vector the owner adds.
    bool locally_owned = false;

    /** sum_i a_{p,i} t_i: node p's tangential components as a vector. */
    Tensor<1, dim> tangential_vector(const Vector<double> &a,
                                     const unsigned int    p) const
    {
      Tensor<1, dim> result;
      for (unsigned int i = 0; i < dim - 1; ++i)
        result += a[p * (dim - 1) + i] * tangents[i];
      return result;
    }
  };

  /** What one time step did, for the console and time_series.csv. */
  struct StepStatistics
  {
    unsigned int convexification_iterations = 0;
    unsigned int active_set_iterations      = 0;
    unsigned int rejected_accelerations     = 0;
    unsigned int cycles_cured               = 0;
    unsigned int step_cuts                  = 0;
    // The Newton method on the full law ('Solver/Friction method'): its
    // iterations, and 1 where it failed and the convexification took over.
    unsigned int newton_iterations = 0;
    unsigned int newton_fallbacks  = 0;
    // Solves with K or a variant of it (a forward and a backward
    // substitution with the factor count as one), and CG iterations.
    unsigned int       solves_with_K  = 0;
    unsigned long long cg_iterations  = 0;
    unsigned int       n_stick        = 0;
    unsigned int       n_slip         = 0;
    double             max_slip_rate  = 0;
    double             friction_force = 0;

    /** Add the iteration counts of another step (or part of one). */
    void add_counts(const StepStatistics &other)
    {
      convexification_iterations += other.convexification_iterations;
      active_set_iterations += other.active_set_iterations;
      rejected_accelerations += other.rejected_accelerations;
      cycles_cured += other.cycles_cured;
      step_cuts += other.step_cuts;
      newton_iterations += other.newton_iterations;
      newton_fallbacks += other.newton_fallbacks;
      solves_with_K += other.solves_with_K;
      cg_iterations += other.cg_iterations;
    }
  };

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
  };


  template <int dim>
  class ContactProblem
  {
  public:
    explicit ContactProblem(const Parameters &parameters);

    RunSummary run();

    /**
     * Called at the end of every time step with the problem itself; a
     * convergence study uses it to collect solutions at common times.
     */
    void set_step_observer(
      const std::function<void(const ContactProblem<dim> &)> &observer);

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
    unsigned int read_mesh_file(Triangulation<dim> &mesh);
    void         grade_towards_points(Triangulation<dim> &mesh);
    void         check_boundary_ids(const Triangulation<dim> &mesh) const;
    void         setup_system();
    void         make_constraints();
    void         setup_contact_nodes();
    std::map<types::global_dof_index, ContactNode<dim>>
         integrate_contact_faces() const;
    void setup_probes();

    // assembly.cc
    void           assemble_matrices();
    void           form_system_matrix();
    void           assemble_load(const double time,
                                 VectorType  &load_vector,
                                 const bool   with_body_force,
                                 const bool   with_surface_loads) const;
    void           set_initial_values();
    void           condensed_product(const MatrixType &matrix,
                                     const VectorType &x,
                                     VectorType       &product) const;
    Tensor<1, dim> momentum() const;
    void           update_energy_balance();

    // contact_solver.cc
    void           factorize_system_matrix();
    void           setup_contact_solver();
    void           initialise_contact_state();
    void           change_time_step(const double k);
    StepStatistics advance(const unsigned int cuts_left);
    double         largest_weighted_delassus_eigenvalue(const double tolerance);
    bool           delassus_operator_pays() const;
    void           build_delassus_operator();
    void           build_delassus_from_factor();
    void           build_delassus_from_solves();
    void           subtract_delassus_columns(const Vector<double> &eta,
                                             VectorType           &w) const;
    StepStatistics do_time_step();
    StepStatistics
         solve_friction_problem(const Vector<double> &free_slip_velocity);
    bool solve_by_newton(const Vector<double> &free_slip_velocity,
                         StepStatistics       &statistics);
    void solve_by_convexification(const Vector<double> &free_slip_velocity,
                                  StepStatistics       &statistics);
    std::pair<TrescaVelocity, TrescaNewtonStep>
                 friction_operators(const Vector<double> &free_slip_velocity);
    TrescaResult solve_tresca_problem(const Vector<double> &free_slip_velocity,
                                      const Vector<double> &bound,
                                      Vector<double>       &eta,
                                      Vector<double>       &v,
                                      std::vector<NodeState> &state);
    void         solve_with_K(VectorType &x, const VectorType &b);
    VectorType   friction_load(const Vector<double> &eta) const;
    void         add_nodal_force(const ContactNode<dim> &node,
                                 const Tensor<1, dim>   &force,
                                 VectorType             &load) const;
    std::string  convexification_failure(const double residual) const;
    void         add_contact_state(StepStatistics &statistics) const;
    double       tangential_velocity(const ContactNode<dim> &node,
                                     const unsigned int      direction,
                                     const VectorType       &w) const;
    Vector<double> tangential_velocities(const VectorType &w) const;
    Vector<double> sum_over_processes(const Vector<double> &part) const;

    // active_set_constraints.cc: the straightforward path.
    void velocity_for_friction_force(const Vector<double> &eta, VectorType &w);
    void newton_step_with_constraints(
      const std::vector<NodeLinearisation> &linearisation,
      Vector<double>                       &eta,
      Vector<double>                       &v);

    // contact_problem.cc: Gauss rules of n points per direction on the
    // cells and faces of the mesh's shape.
    Quadrature<dim>     gauss_rule(const unsigned int n_points) const;
    Quadrature<dim - 1> face_gauss_rule(const unsigned int n_points) const;

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
    void        cut_output_back_to_checkpoint() const;
    template <class Archive>
    void serialize_checkpoint_state(Archive &archive);

    // output.cc
    void           prepare_output_directory();
    void           write_vtu();
    void           write_pvd() const;
    void           write_time_series_row(const StepStatistics &statistics);
    Tensor<1, dim> probe_displacement(const unsigned int probe,
                                      const VectorType  &u_ghosted) const;
    void           print_progress(const StepStatistics &statistics) const;
    void           report_contact_state();
    void           print_summary() const;

    // Parameters and the objects fixed by them.
    const Parameters   parameters;
    const FrictionLaw  friction_law;
    const unsigned int n_time_steps;
    // The time step k: constant, except while a step is cut
    // ('Solver/Step cuts').
    double time_step;

    MPI_Comm            mpi_communicator;
    ConditionalOStream  pcout;
    mutable TimerOutput computing_timer;

    // The load data, as muparser expressions of (x, y[, z], t).
    std::unique_ptr<FunctionParser<dim>> body_force;
    std::unique_ptr<FunctionParser<dim>> initial_displacement;
    std::unique_ptr<FunctionParser<dim>> initial_velocity;
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
      tractions;
    // With 'Verification/Manufactured solution', the exact solution that
    // replaces the load data above.
    std::unique_ptr<const ManufacturedSolution<dim>> exact_solution;
    // A body force that does not depend on t is assembled once.
    const bool body_force_is_constant;
    VectorType constant_body_load;

    // Mesh and finite element space: p4est's distributed triangulation and
    // Q_p for hypercubes, a plain triangulation with P_p (FE_SimplexP and
    // its MappingFE) for simplices, which p4est does not handle. The scalar
    // space of the same degree carries the Gamma_3 quantities (slip rate,
    // status) for output.
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
    // (w.n = 0) as homogeneous constraints: V_h of the paper.
    AffineConstraints<double> constraints;

    // The matrices of (5.2): mass (with rho), viscosity A_h, elasticity
    // B_h, and K = (1/k) M + A_h + k B_h, all condensed with the
    // constraints. K is factorised once per run. momentum_density[d]_i =
    // int rho phi_i . e_d gives the momentum of a velocity as a dot product.
    MatrixType                     mass_matrix;
    MatrixType                     viscosity_matrix;
    MatrixType                     elasticity_matrix;
    MatrixType                     system_matrix;
    std::array<VectorType, dim>    momentum_density;
    std::unique_ptr<Factorization> factorization;

    // The time step state: u_n, w_n, the loads F_n and the previous ones.
    double       time;
    unsigned int step_number;
    VectorType   displacement;
    VectorType   velocity;
    VectorType   old_displacement;
    VectorType   old_velocity;
    VectorType   load;
    // M w_{n-1} and B u_{n-1} (condensed), kept from the energy balance of
    // the last step for the right-hand side of the next.
    VectorType mass_times_velocity;
    VectorType elasticity_times_displacement;
    // The right-hand side of the step without friction, condensed:
    // K w_free = step_rhs.
    VectorType step_rhs;

    // Gamma_3: its nodes, the Delassus operator D (unless the active set is
    // imposed as constraints on the whole body, 'Solver/Contact solver')
    // with Y^T = (L^{-1} P C^T)^T where K has a triangular factor, or else
    // the rows of Z = K^{-1} C^T this process owns, and the nodal state of
    // the last step.
    std::vector<ContactNode<dim>> contact_nodes;
    bool                          use_delassus_operator = false;
    SparsityPattern               delassus_factor_pattern;
    SparseMatrix<double>          delassus_factor;
    LAPACKFullMatrix<double>      delassus_columns;
    DelassusOperator              delassus_operator;
    Vector<double>                active_set_parameter;
    Vector<double>                friction_force;
    Vector<double>                slip_velocity;
    std::vector<NodeState>        node_state;
    // A step's friction problem is convex while S (a - b) alpha is below
    // this (largest_weighted_delassus_eigenvalue).
    double convexity_limit = std::numeric_limits<double>::infinity();
    // Solves with K (and its variants) of the step so far. The constraints
    // path keeps the forces and velocities of the step's last Newton steps:
    // the friction solver asks again for the velocity of forces a Newton
    // step gave (its final forces, the start of a convexification step),
    // which then needs no solve; CG starts from the newest velocity.
    unsigned int                                      solves_in_step = 0;
    std::deque<std::pair<Vector<double>, VectorType>> recent_newton_solves;

    EnergyBalance energy;

    // Output state. A probe is the cell around an 'Output/Probe points'
    // entry and the point in its reference cell; of the processes that own
    // a cell around the point, the first evaluates it, the others keep an
    // invalid cell.
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
                                                probes;
    std::ofstream                               time_series;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<double>                         pending_report_times;
    StepStatistics                              totals;
    double                                      max_relative_energy_residual;
    // Mean wall time of one forward/back substitution with the factor of K
    // (measured on the solve for the free velocity of every step).
    double                                           substitution_time = 0;
    ErrorNorms                                       current_errors;
    ErrorNorms                                       max_errors;
    std::function<void(const ContactProblem<dim> &)> step_observer;
    Timer                                            run_timer;
    // Wall time since the last checkpoint, for 'Output/Checkpoint minutes'.
    Timer checkpoint_timer;
  };
} // namespace Contact

#endif
