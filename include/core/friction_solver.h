/**
 * FrictionSolver<dim>: the friction problem on Gamma_3 of every time step.
 *
 * Given the right-hand side of a step of (5.2), the solver returns the
 * step's velocity w_n and keeps the nodal friction forces, slip velocities
 * and stick/slip states that satisfy the friction law (5.3)-(5.4) with it.
 * How the body is seen from Gamma_3 is a path (ContactPath), chosen once by
 * 'Solver/Contact solver':
 *   - the Delassus operator D = C K^{-1} C^T from the triangular factor of K
 *     (one forward and one backward substitution per step),
 *   - D from the columns Z = K^{-1} C^T (one solve per step),
 *   - the active set imposed as constraints on the whole body (a solve with
 *     a variant of K per Newton step; no dense matrix; parts/constraints_path).
 * The methods on Gamma_3 (FrictionMethod, chosen by 'Solver/Friction
 * method': the convexification around Tresca problems, or a method of a
 * part) only see a path's three operations: v = v_free - D eta, one Newton
 * step, and y = D x.
 *
 *   friction_solver.cc   the step, the path and the convexity limit
 *   convexification.cc   the convexification (friction_method.h)
 *   contact_paths.cc     the maps C and C^T
 *   delassus_paths.cc    the two Delassus paths
 */
#ifndef contact_friction_solver_h
#define contact_friction_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <base/parts.h>
#include <core/factorization.h>
#include <core/friction.h>
#include <core/parameters.h>

#include <array>
#include <functional>
#include <limits>
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


  /**
   * Gamma_3 seen from the body: its nodes, and the maps C (the tangential
   * velocities of a body velocity) and C^T (nodal friction forces as a
   * load, condensed with the constraints like every load). Every process
   * gets all of C w.
   */
  template <int dim>
  struct ContactBoundary
  {
    std::vector<ContactNode<dim>>    nodes;
    const AffineConstraints<double> &constraints;
    const IndexSet                  &locally_owned_dofs;
    MPI_Comm                         mpi_communicator;

    unsigned int   n_unknowns() const;
    double         tangential_velocity(const ContactNode<dim> &node,
                                       const unsigned int      direction,
                                       const VectorType       &w) const;
    Vector<double> tangential_velocities(const VectorType &w) const;
    VectorType     friction_load(const Vector<double> &eta) const;
    void           add_nodal_force(const ContactNode<dim> &node,
                                   const Tensor<1, dim>   &force,
                                   VectorType             &load) const;
    Vector<double> sum_over_processes(const Vector<double> &part) const;
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
    // iterations; 1 where it ended with a slip node weakening beyond the
    // convexity limit (E not convex there: the curvature test decided);
    // the saddles of E it left along their negative curvature; 1 where the
    // convexification took over, and of these 1 where Newton's end point
    // was not certified as a local minimum of E.
    unsigned int newton_iterations      = 0;
    unsigned int beyond_convexity_limit = 0;
    unsigned int saddle_exits           = 0;
    unsigned int newton_fallbacks       = 0;
    unsigned int minima_not_certified   = 0;
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
      beyond_convexity_limit += other.beyond_convexity_limit;
      saddle_exits += other.saddle_exits;
      newton_fallbacks += other.newton_fallbacks;
      minima_not_certified += other.minima_not_certified;
      solves_with_K += other.solves_with_K;
      cg_iterations += other.cg_iterations;
    }
  };


  /** The state of Gamma_3 after a step: what the next step starts from,
   *  what a checkpoint or a step cut keeps. */
  struct FrictionState
  {
    Vector<double>         friction_force;
    Vector<double>         slip_velocity;
    std::vector<NodeState> node_state;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      std::vector<int> states;
      for (const NodeState state : node_state)
        states.push_back(static_cast<int>(state));
      archive &friction_force &slip_velocity &states;
      node_state.clear();
      for (const int state : states)
        node_state.push_back(static_cast<NodeState>(state));
    }
  };


  /** A step's friction problem not solved within the iteration limits: the
   *  one failure that 'Solver/Step cuts' retries with k/2 (every process
   *  throws it together: the decisions are reduced over the processes). */
  DeclException1(ExcStepNotConverged, std::string, << arg1);

  /** Which step is solved, for the messages of a failure. */
  struct StepLabel
  {
    unsigned int step_number = 0;
    double       time        = 0;
    double       time_step   = 0;
  };


  /**
   * The linear algebra of one path between the body and Gamma_3
   * (delassus_paths.cc, parts/constraints_path). A step calls begin_step()
   * first, then the methods on Gamma_3 call newton_step() (the
   * convexification also free_slip_velocity() and velocity_of_force()), and
   * velocity() gives w_n for the final forces.
   */
  template <int dim>
  class ContactPath
  {
  public:
    virtual ~ContactPath() = default;

    /** A new step with this right-hand side; iterative solves start from
     *  `last_velocity`, w_{n-1}. */
    virtual void begin_step(const VectorType &step_rhs,
                            const VectorType &last_velocity) = 0;
    /** v_free = C K^{-1} step_rhs, formed at its first call in a step. */
    virtual const Vector<double> &free_slip_velocity() = 0;
    /** v = v_free - D eta. */
    virtual void velocity_of_force(const Vector<double> &eta,
                                   Vector<double>       &v) = 0;
    /** One Newton step of friction.h for a linearisation. */
    virtual void
    newton_step(const std::vector<NodeLinearisation> &linearisation,
                Vector<double>                       &eta,
                Vector<double>                       &v) = 0;
    /** w_n = K^{-1} (step_rhs - C^T eta), for the step's final forces. */
    virtual void velocity(const Vector<double> &eta, VectorType &w) = 0;
    /** y = D x, outside of a step (the Lanczos method for the convexity
     *  limit). */
    virtual void apply_delassus(const Vector<double> &x, Vector<double> &y) = 0;
    /** What the summary prints about the path. */
    virtual std::string description() const = 0;
    /** max |v_free| where the step formed v_free, 0 where it did not. */
    virtual double free_slip_speed() const = 0;
    /** The curvature test of friction.h: whether the matrix of a Newton
     *  step for this linearisation (the Hessian of E on the slip set) is
     *  positive definite. */
    virtual Curvature curvature_on_slip_set(
      const std::vector<NodeLinearisation> &linearisation) = 0;
    /** The relative accuracy of E between the iterates of a step: round-off
     *  where they come from one factor or one Delassus operator, the
     *  iterative solver's tolerance where each is a solve of its own. */
    virtual double energy_accuracy() const
    {
      return energy_round_off;
    }

    /** Solves with K (or a variant) since the step began, and the wall time
     *  of the step's first solve (or its substitutions). */
    unsigned int solves               = 0;
    double       substitution_seconds = 0;
  };


  /** What a FrictionSolver reads of the problem it serves besides the
   *  nodes of Gamma_3: the run's parameters (the friction law among them),
   *  the constraints and the parallel layout of V_h, and where it reports. */
  struct FrictionSolverEnvironment
  {
    const Parameters                &parameters;
    const AffineConstraints<double> &constraints;
    const IndexSet                  &locally_owned_dofs;
    MPI_Comm                         mpi_communicator;
    const ConditionalOStream        &pcout;
    TimerOutput                     &computing_timer;
  };


  template <int dim>
  class FrictionMethod;


  template <int dim>
  class FrictionSolver
  {
  public:
    /** Takes the nodes of Gamma_3; every node sticks (slips freely without
     *  friction) and carries no force. The law's bound S mu(s) at node p
     *  is applied times `bound_scale(x_p)` where one is given (a variant
     *  of the law; a test's wrong coefficient), else as it is. */
    FrictionSolver(
      const FrictionSolverEnvironment                 &environment,
      std::vector<ContactNode<dim>>                    nodes,
      const std::function<double(const Point<dim> &)> &bound_scale = {});

    virtual ~FrictionSolver();

    /** K or its factorisation changed (the start, a step cut): the active
     *  set parameters, the path and the convexity limit. */
    void reinit(const MatrixType &system_matrix, Factorization &factorization);

    /** The slip velocities of the initial velocity. */
    void set_initial_velocity(const VectorType &velocity);

    /** One step of (5.2)-(5.4): w_n and the friction state for the step's
     *  right-hand side. Throws with a diagnostic if the friction problem is
     *  not solved. (Virtual: a variant of the solver may build on it.) */
    virtual StepStatistics solve_step(const VectorType &step_rhs,
                                      VectorType       &velocity,
                                      const StepLabel  &label);

    /**
     * How far from the law the last step's solution may be by the
     * solver's own tolerance, relative to max_p g_p(0) like the self-check
     * of the law (self_checks.cc): 0 after a method that solves the law
     * itself (to 1e-12); after the convexification, whose Tresca problem
     * has the bounds of the slip rates s of its last iterate, the largest
     * change of the bound that the remaining change of s allows,
     * S (a - b) alpha max_p |s_p - |v_p|| / (S mu(0)).
     */
    double law_residual_allowance() const;

    const ContactBoundary<dim> &boundary() const;
    /** The friction law of the run's parameters. */
    const FrictionLaw   &law() const;
    const FrictionState &state() const;
    void                 set_state(const FrictionState &state);
    std::string          description() const;
    /** Wall time of the last step's first solve with K (or a variant), or
     *  its substitutions. */
    double substitution_seconds() const;
    /** max_p |v_free,p| of the last step where its path formed v_free
     *  (always on the Delassus paths), else 0: a sticking node's velocity
     *  v_free - D eta is a difference of terms of this size, and so is its
     *  round-off. */
    double free_slip_speed() const;

  protected:
    /** The registered path `name` for K (choose_path); a solver derived
     *  from this one may return a path of its own instead, e.g. one that
     *  wraps this path. */
    virtual std::unique_ptr<ContactPath<dim>>
    make_path(const MatrixType  &system_matrix,
              Factorization     &factorization,
              const std::string &name);

  private:
    void choose_path(const MatrixType &system_matrix,
                     Factorization    &factorization);
    bool delassus_operator_pays(const Factorization &factorization) const;
    std::pair<double, bool>
         largest_weighted_delassus_eigenvalue(const double tolerance);
    void solve_friction_problem(const StepLabel &label,
                                const double     velocity_scale,
                                StepStatistics  &statistics);
    void add_contact_state(StepStatistics &statistics) const;

    const Parameters         &parameters;
    const FrictionLaw         friction_law;
    const ConditionalOStream &pcout;
    TimerOutput              &computing_timer;
    ContactBoundary<dim>      gamma3;
    // m_p times the bound's scale at every node: the weights with which
    // the law is applied (NodalLaw, the bounds of the Tresca problems).
    Vector<double> law_weights;

    std::unique_ptr<ContactPath<dim>> path;
    // The method of 'Solver/Friction method', and the core's own, the
    // convexification: the fallback of the other methods, and the method
    // for a rate independent law (one Tresca problem).
    std::unique_ptr<FrictionMethod<dim>> chosen_method;
    std::unique_ptr<FrictionMethod<dim>> convexification;
    // c_p of the active set method for every node.
    Vector<double> active_set_parameter;
    // A step's friction problem is convex while S (a - b) alpha is below
    // this (largest_weighted_delassus_eigenvalue).
    double convexity_limit = std::numeric_limits<double>::infinity();
    // The Lanczos steps that estimate it at most (each a product with D),
    // and the relative change of the estimate at which they stop (with
    // CG-AMG, where each product costs solves with K, a rougher one).
    static constexpr unsigned int max_lanczos_steps           = 100;
    static constexpr double       lanczos_tolerance           = 1e-8;
    static constexpr double       lanczos_tolerance_iterative = 1e-3;
    FrictionState                 current;
    double                        last_law_residual_allowance = 0;
  };


  /**
   * The kind of the paths between the body and Gamma_3 (base/parts.h), the
   * choices of 'Solver/Contact solver' besides 'auto', registered once per
   * compiled dimension: a path made for Gamma_3, K and its factorisation
   * (the time of its setup reported to the timer). The core's is the
   * Delassus path (delassus_paths.cc).
   */
  template <int dim>
  using ContactPathRegistry = PartRegistry<ContactPath<dim>,
                                           const ContactBoundary<dim> &,
                                           const MatrixType &,
                                           Factorization &,
                                           TimerOutput &>;

  /** The core's path, and 'auto''s while the Delassus operator pays. */
  inline const std::string delassus_path_name = "Delassus";
} // namespace Contact

#endif
