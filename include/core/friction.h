/**
 * The friction law of the paper and the nodal Tresca problem that one
 * convexification iteration solves on Gamma_3:
 *
 *   friction_law.cc          FrictionLaw
 *   anderson_acceleration.cc AndersonAcceleration
 *   tresca_active_set.cc     solve_tresca(), by the primal-dual active set
 *                            method
 */
#ifndef contact_friction_h
#define contact_friction_h

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/parameters.h>

#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /** The Tresca active set method and Newton's method on the full law stop
   *  at this residual relative to the largest bound max_p g_p(0). */
  constexpr double friction_residual_tolerance = 1e-12;
  /** An iterate lowers the energy E on Gamma_3 if E grows by at most this
   *  much relative to its size: round-off of the sum. */
  constexpr double energy_round_off = 1e-13;
  /**
   * The slip threshold mu(s) S of (3.6) of the slip rate s = |w_tau|, for
   * the law of the entry 'Friction law' (core/friction_laws.h; for the slip
   * rate weakening law the paper's (6.1), mu(s) = (a - b) exp(-alpha s) + b,
   * whose one-sided Lipschitz constant (H(mu)(c)) is lambda = (a - b) alpha).
   * What holds for every law is decided here once: no friction term where
   * S = 0, and a rate independent law has the derivative 0 and the
   * potential S mu(0) s. Each function costs at most one virtual call.
   */
  class FrictionLaw
  {
  public:
    explicit FrictionLaw(const FrictionParameters &parameters);

    /** Friction coefficient mu(s), s >= 0. */
    double coefficient(const double slip_rate) const;

    /** Slip threshold S mu(s) [N/m^(dim-1)] of (3.6). */
    double bound(const double slip_rate) const;

    /** d/ds S mu(s): the tangent of the bound in the Newton method. */
    double bound_derivative(const double slip_rate) const;

    /** j(v) = S int_0^|v| mu(r) dr of (3.8), for the step's energy. */
    double potential(const double slip_velocity) const;

    /** No friction term at all (mu = 0, e.g. law 'none', or S = 0). */
    bool is_frictionless() const;

    /** mu does not depend on s: one Tresca problem per step suffices. */
    bool is_rate_independent() const;

    /** lambda in H(mu)(c): the rate at which mu may decrease. */
    double one_sided_lipschitz_constant() const;

    /** S lambda: the steepest weakening of the bound, max_s -d/ds S mu(s)
     *  (0 without friction or for a rate independent law). */
    double steepest_weakening() const;

  private:
    /** Shared with the parameters it was read from; immutable. */
    const std::shared_ptr<const FrictionLaws::Interface> law;
    const double                                         S;
    /** The law's properties, asked once rather than per node. */
    const bool frictionless;
    const bool rate_independent;
  };


  /**
   * Anderson acceleration (type II, Walker and Ni 2011) of a fixed point
   * iteration x <- G(x): the next iterate combines the last `depth` images
   * G(x_i) with the weights that minimise the combined residual
   * |sum gamma_i (G(x_i) - x_i)|. Depth 0 is the plain iteration.
   */
  class AndersonAcceleration
  {
  public:
    explicit AndersonAcceleration(const unsigned int history_depth);

    /** Given x and G(x), overwrite x with the next iterate. */
    void next_iterate(Vector<double> &x, const Vector<double> &image);

    /** Forget the history; the next step is a plain one. */
    void restart();

    bool last_step_was_accelerated() const;

  private:
    const unsigned int          depth;
    std::vector<Vector<double>> residual_differences;
    std::vector<Vector<double>> image_differences;
    Vector<double>              previous_residual;
    Vector<double>              previous_image;
    bool                        accelerated;
  };


  /**
   * The Tresca problem with given nodal bounds g_p >= 0 on the tangential
   * unknowns of Gamma_3, m = dim - 1 per node (node-major: unknown p m + i
   * is component i of node p), in terms of the Delassus operator
   * D = C K^{-1} C^T (doc/algorithm.md):
   *
   *   v = v_free - D eta,
   *   |eta_p| <= g_p if v_p = 0,   eta_p = g_p v_p / |v_p| otherwise,
   *
   * i.e. the nodal form of the friction condition (5.3) with the
   * coefficient frozen. It is solved by the primal-dual active set method,
   * the semismooth Newton method on the complementarity function
   * eta_p = P_{B(g_p)}(z_p), z_p = eta_p + c_p v_p (the formulation of
   * Hueber, Stadler and Wohlmuth 2008; the step below is the plain
   * generalised derivative of the projection, not their damped variant):
   * stick where |z_p| <= g_p (impose v_p = 0), slip elsewhere. On a slip node
   * the generalised derivative of the projection, (g_p / |z_p|) (I - zhat
   * zhat^T), gives two conditions in the local basis (zhat, tangents of zhat):
   * eta_p . zhat = g_p, and v_p . t = beta_p eta_p . t with beta_p = (|z_p| -
   * g_p) / (g_p c_p) >= 0 along the other directions. Every Newton step is then
   * one SPD solve, on the body (parts/constraints_path) or on D
   * (DelassusOperator, which solves for the forces or for the velocities,
   * whichever set is smaller). For m = 1 (2D)
   * there are no such directions: the slip set fixes eta_p = g_p sign(z_p)
   * and the method ends when the sets and signs repeat, with (eta, v)
   * exact. For m = 2 the slip directions converge superlinearly; the method
   * stops when the sets repeat and eta - P(z) is below `relative_tolerance`
   * times max_p g_p (round-off unless the caller asks for less). If a set seen
   * before (not the last one) comes back, the method cycles; c is then halved,
   * which is what cures the cycling at slip onset (doc/algorithm.md).
   */
  struct TrescaResult
  {
    unsigned int iterations   = 0;
    unsigned int cycles_cured = 0;
    bool         converged    = false;
  };

  enum class NodeState : int
  {
    stick,
    slip
  };

  /**
   * The linearisation of the complementarity function at one node: its
   * state, the unit vector zhat along z_p = eta_p + c_p v_p (in the node's
   * tangent basis), and beta_p. A node with g_p = 0 slips with eta_p = 0
   * whatever v_p does; its direction is that of v_p (the first axis if
   * v_p = 0) to keep it deterministic.
   */
  struct NodeLinearisation
  {
    NodeState           state = NodeState::stick;
    std::vector<double> direction;
    double              beta = 0;
    /** g_p at the linearisation point. */
    double bound = 0;
    /** On a slip node the force along zhat is force + slope (zhat . v_p):
     *  force = g_p and slope = 0 for the Tresca problem (frozen bound);
     *  the tangent of g_p(|v_p|) for the full law, slope = g_p'(s) <= 0
     *  and force = g_p(s) - s g_p'(s) at the slip rate s of the iterate. */
    double force = 0;
    double slope = 0;
    /** The steepest slope with which the Newton matrix is certainly
     *  positive definite (a method's cap on the weakening): a path whose
     *  solver needs a definite matrix assembles max(slope, definite_slope)
     *  and adds the rest as a low-rank correction. */
    double definite_slope = -std::numeric_limits<double>::infinity();
  };

  /** A Newton step's solver found its matrix not positive definite
   *  (CHOLMOD refuses such a matrix): the Newton method on the full law
   *  then counts the step as failed and tries another model. */
  DeclExceptionMsg(ExcIndefiniteNewtonMatrix,
                   "The matrix of a Newton step is not positive definite.");

  /** The orthonormal basis of a node's tangent plane in which the Newton
   *  step is diagonal: columns (zhat, zhat turned by 90 degrees) on slip
   *  nodes, the identity on stick nodes. */
  FullMatrix<double> local_basis(const NodeLinearisation &node);

  /** v = v_free - D eta, however D is represented. */
  using TrescaVelocity =
    std::function<void(const Vector<double> &eta, Vector<double> &v)>;
  /** One Newton step: the new (eta, v) for the given linearisation; on
   *  entry (eta, v) is the current iterate. */
  using TrescaNewtonStep =
    std::function<void(const std::vector<NodeLinearisation> &linearisation,
                       Vector<double>                       &eta,
                       Vector<double>                       &v)>;

  /** Whether the Hessian of E on the slip set at a solution is positive
   *  definite: the matrix of a Newton step for the linearisation with the
   *  true slopes (stick nodes held at v_p = 0) is that Hessian, rotated.
   *  `unknown` where the path cannot tell at a reasonable cost. */
  enum class Curvature
  {
    positive,
    not_positive,
    unknown
  };
  using CurvatureTest =
    std::function<Curvature(const std::vector<NodeLinearisation> &)>;

  /** Whether a matrix that is symmetric up to round-off is positive
   *  definite: one Cholesky factorisation of its symmetric part. */
  Curvature definiteness(LAPACKFullMatrix<double> matrix);

  /** The method with the linear algebra supplied by the caller (e.g. on the
   *  whole body instead of on D). The first sets are those of eta and the
   *  velocity v = velocity(eta); without a velocity function (an empty
   *  one), those of eta and v as given, which then need not belong to each
   *  other (a guess of the sets that costs no solve). */
  TrescaResult
  solve_tresca(const TrescaVelocity   &velocity,
               const TrescaNewtonStep &newton_step,
               const unsigned int      n_components,
               const Vector<double>   &g,
               const Vector<double>   &c,
               const unsigned int      max_iterations,
               Vector<double>         &eta,
               Vector<double>         &v,
               std::vector<NodeState> &state,
               const double relative_tolerance = friction_residual_tolerance);

} // namespace Contact

#endif
