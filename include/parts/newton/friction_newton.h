/**
 * Newton's method on the full nonmonotone friction law of a step on
 * Gamma_3: solve_friction_newton(), the nodal law and the energy of a step
 * that it descends on, its tuned constants and the method as a class whose
 * members are the state of the iteration. The friction method 'Newton'
 * (newton_method.cc) solves a step with it.
 *
 *   newton_method.cc                 the friction method 'Newton' and its
 *                                    entry
 *   nodal_law.cc                     NodalLaw
 *   friction_newton.cc               the iteration: start, Newton steps with
 *                                    their line search, convexification
 *                                    steps, extrapolation, stick proposals
 *   friction_newton_second_order.cc  at a solution: whether it is a local
 *                                    minimum of E, and the exit from a saddle
 */
#ifndef contact_friction_newton_h
#define contact_friction_newton_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/friction.h>

#include <limits>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  namespace Entry
  {
    inline const std::string max_newton_iterations =
      "Solver/Max Newton iterations";
  } // namespace Entry

  /** While the stick/slip sets still change, Newton's model caps the
   *  weakening at this fraction of the convexity limit, where the model is
   *  convex; below the same fraction a solution is a local minimum without
   *  a test (the 10 % cover the error of the limit's Lanczos estimate). */
  constexpr double weakening_cap_fraction = 0.9;

  /**
   * The nodal friction law with the coefficient not frozen: node p's bound
   * g_p(s) = m_p S mu(s) at slip rate s, its derivative, and the energy of
   * a step on Gamma_3 (the discrete counterpart of (3.8)),
   *   E(v) = 1/2 (v - v_free)^T D^{-1} (v - v_free) + sum_p m_p j(|v_p|),
   * which is 1/2 eta^T D eta + sum_p m_p j(|v_p|) for v = v_free - D eta.
   */
  struct NodalLaw
  {
    const FrictionLaw    &law;
    const Vector<double> &weights;
    /** The steepest weakening per unit weight, |g_p'| / m_p, that the
     *  Newton model takes while it is far from the solution (infinite: the
     *  true slope throughout). Below the convexity limit of the step's
     *  problem it keeps the model convex. */
    double weakening_cap = std::numeric_limits<double>::infinity();
    /** 1 / lambda_max(M^{1/2} D M^{1/2}): E is convex while the weakening
     *  per unit weight stays below it (friction_solver.cc); 0 where it is
     *  not known, and nothing is then certified without the curvature
     *  test. */
    double convexity_limit = 0;
    /** The relative accuracy of E (ContactPath::energy_accuracy()): a
     *  line search accepts a step whose E is above the last one by less
     *  than this times the size of E's error (energy()). */
    double energy_accuracy = energy_round_off;
    /** The size of the body's velocities in the step (max |w_{n-1}|): the
     *  solves' error in v, and so in E, is relative to it. */
    double velocity_scale = 0;

    /** Whether E may be nonconvex: the steepest weakening of the law is not
     *  below weakening_cap_fraction times the convexity limit. */
    bool   may_be_nonconvex() const;
    double bound(const unsigned int p, const double s) const;
    double slope(const unsigned int p, const double s) const;
    /** E at (eta, v) minus 1/2 eta_0^T D eta_0 of a reference iterate
     *  (eta_0, v_0): 1/2 (eta + eta_0) . (v_0 - v) + sum_p m_p j(|v_p|),
     *  for iterates with v = v_free - D eta (no v_free needed). In scale
     *  the size of its error (round-off and the solves' accuracy). */
    double energy(const Vector<double> &reference_eta,
                  const Vector<double> &reference_v,
                  const Vector<double> &eta,
                  const Vector<double> &v,
                  double               &scale) const;
  };

  /** What the Newton method on the full law did. */
  struct FrictionNewtonResult
  {
    unsigned int iterations = 0;
    /** Newton steps shortened by the line search. */
    unsigned int damped_steps = 0;
    /** Convexification steps (a Tresca problem with the bounds of the
     *  current slip rates): the start where E may be nonconvex and those
     *  tried where no Newton step lowered E or the solver refused the
     *  Newton matrix (one each, also where its Tresca problem was solved
     *  twice or did not converge), and the active set iterations they
     *  took. */
    unsigned int convexification_steps = 0;
    unsigned int active_set_iterations = 0;
    /** Converged to a solution of the law that is a local minimum of E:
     *  below the convexity limit, or certified by the curvature test. */
    bool converged = false;
    /** At the solution some slip node weakens faster than
     *  weakening_cap_fraction times the convexity limit: E is not convex
     *  there, and the curvature test decided. */
    bool beyond_convexity_limit = false;
    /** The law holds, but the curvature test did not find a local minimum
     *  (a saddle, or a path that cannot tell): converged is false, and the
     *  caller takes another method. */
    bool minimum_not_certified = false;
    /** Saddles of E (solutions of the law with negative curvature on the
     *  slip set) that the method left along their negative curvature. */
    unsigned int saddle_exits = 0;
    /** A Tresca problem (the start, or a convexification step) did not
     *  converge within its active set iterations. */
    bool tresca_failed = false;
  };

  /**
   * The friction problem of a step with the full nonmonotone law (5.3),
   *
   *   v = v_free - D eta,
   *   |eta_p| <= g_p(0) if v_p = 0,  eta_p = g_p(|v_p|) v_p / |v_p| else,
   *
   * by a semismooth Newton method on the complementarity function
   * F_p = eta_p - P_{B(g_p(|v_p|))}(eta_p + c_p v_p): the linearisation of
   * solve_tresca() plus, on slip nodes, the derivative of the bound,
   * g_p' (zhat . dv), so that slip rates and forces are found together
   * instead of by a fixed point around Tresca problems. The Jacobian stays
   * symmetric; it is indefinite where the step problem is not convex
   * (g_p' < 0 is the weakening). The solutions of the law are the
   * stationary points of the step's energy E (NodalLaw), and the
   * globalisation (line search, convexification steps, a test of the end
   * point and the exit from saddles) makes the method a descent method on
   * E that ends on a local minimum: FrictionNewton (below) describes it
   * step by step and holds its tuned constants.
   * (eta, v, state) are the solution where the result converged and are
   * unspecified otherwise.
   */
  FrictionNewtonResult
  solve_friction_newton(const TrescaNewtonStep &newton_step,
                        const CurvatureTest    &curvature,
                        const unsigned int      n_components,
                        const NodalLaw         &law,
                        const Vector<double>   &c,
                        const unsigned int      max_iterations,
                        const unsigned int      max_active_set_iterations,
                        Vector<double>         &eta,
                        Vector<double>         &v,
                        std::vector<NodeState> &state);


  /**
   * The tuned constants of Newton's method on the full law, each with what
   * it controls and why it has its value. (The tolerances that it shares
   * with the rest of the friction solver, friction_residual_tolerance and
   * energy_round_off, are in friction.h.)
   */
  struct FrictionNewtonConstants
  {
    /** The Tresca problem with which the method starts where E may be
     *  nonconvex, and that of a convexification step inside it, stops once
     *  its sets repeat and its residual is below this fraction of its
     *  largest bound: the sets, which select the solution, are then
     *  decided, and the remaining digits are left to Newton's method, whose
     *  steps solve the same conditions on those sets. (Every test scene
     *  ends on the solutions of the start solved to
     *  friction_residual_tolerance, to the printed digits, and the 3D scene
     *  at h = k = 1/32 with the same stick/slip counts at every printed
     *  step; at 1e-2 the 3D scene at h = k = 1/16 ends on another local
     *  minimum: doc/algorithm.md, which also gives what the same stop
     *  changed in the convexification step.) */
    double start_residual_tolerance = 1e-3;

    /** The Armijo constant of the line search on E: a step of length t
     *  along a direction with the directional derivative E' < 0 is
     *  accepted when E decreases by at least sufficient_decrease t |E'|. */
    double sufficient_decrease = 1e-4;

    /** A Newton step is halved while its length stays above this: three
     *  halvings (a third saves convexification steps, a fourth was rarely
     *  taken in the 3D scenes). */
    double shortest_step = 0.1;

    /** Where neither model's step lowers E within those halvings, the step
     *  with the true slopes is halved further while its length stays above
     *  this (down to 1/64; no solve) before a convexification step (which
     *  costs several solves) is taken: where the Hessian on the slip set
     *  is nearly singular the true step is far too long, and a short step
     *  along it may still lower E (doc/algorithm.md). */
    double shortest_true_step = 0.01;

    /** The model switches from the capped to the true slopes once the sets
     *  repeat after a full step and the residual is below this fraction of
     *  max_p g_p(0) (a failed true step halves that threshold, so that the
     *  two models do not take turns at the same residual). */
    double uncapping_residual = 0.1;

    /** After this many full capped steps in a row on repeating sets that
     *  were slow (below), a full capped step is extrapolated: where E is
     *  nearly flat along the step (near a fold of the slip solutions, at
     *  slip onset) the model's curvature is far above E's, and its steps
     *  are far too short (bench/friction_solver.md). */
    unsigned int slow_limit = 2;

    /** A step is slow when its residual is above this fraction of the last
     *  one's (it fell by less than 30 %, or grew: creeping steps count
     *  too). */
    double slow_contraction = 0.7;

    /** The extrapolation of a slow full step takes the lengths 2, 4, ... up
     *  to this while E keeps falling (no solve: eta and v move
     *  together). */
    double longest_extrapolation = 8;

    /** After this many full capped steps in a row on repeating sets whose
     *  residual grew, the slip nodes that weaken faster than the cap and
     *  slowed down are proposed to stick: where a node's true weakening is
     *  much steeper than the cap, the capped model creeps towards its
     *  stick state (the residual grows by 10 to 40 % per step while E falls
     *  by little, until the node sticks). */
    unsigned int creep_limit = 3;

    /** A saddle of E is left along its negative curvature at most this
     *  many times per step; then (or where the test cannot tell) the
     *  result says minimum_not_certified and the caller takes another
     *  method. */
    unsigned int max_saddle_exits = 3;

    /** The exit from a saddle searches the lengths that change a slip rate
     *  by up to this times the fastest steep node's rate, both ways... */
    double saddle_reach = 2.;

    /** ... halved while the length stays above this fraction of that
     *  reach (ten lengths each way). */
    double shortest_saddle_length = 1e-3;
  };


  /**
   * The globalised semismooth Newton method on the full law of
   * solve_friction_newton() (above), one object per solve: the
   * constructor takes the problem and the iterate (eta, v) on entry, and
   * solve() runs the method on it. The solutions of the law are the
   * stationary points of the step's energy E (NodalLaw), and the
   * globalisation makes the method a descent method on E that ends on a
   * local minimum; solve() reads top to bottom as the method:
   * - The start: where E may be nonconvex (law.may_be_nonconvex()) the
   *   start selects the solution: the first iterate is then the
   *   convexification's, the Tresca problem with the bounds of the
   *   previous slip rates (a descent from the previous velocities, counted
   *   as a convexification step; its active set method's first sets are
   *   those of eta and v on entry, no solve; it stops at
   *   start_residual_tolerance once its sets repeat), and every Newton
   *   step from it is line searched. Where that start already satisfies
   *   the full law (max |F_p| below the tolerance), it is the solution,
   *   with the same second-order check. Where E is convex its one
   *   stationary point is the minimiser whichever way it is reached: the
   *   first step starts from the previous step's forces, slip velocities
   *   and sets (eta, v on entry), which need not solve this step's
   *   equations; E is measured from the first iterate that does
   *   (NodalLaw::energy()), so the method never forms v_free, which on
   *   the constraints path would cost a solve (where the solver refuses
   *   the first step of a convex problem, the convexification step that
   *   replaces it is taken without a comparison, and E is measured from
   *   its result).
   * - The Newton step: while the sets change, the model caps the
   *   weakening at law.weakening_cap (below the convexity limit the model
   *   is convex and its step a direction of descent; with the true slope,
   *   a node just entering slip is pulled back towards stick); once the
   *   sets repeat after a full step and max |F_p| is below
   *   uncapping_residual max_p g_p(0), the true slope takes over for the
   *   quadratic convergence.
   * - Its line search: a step is accepted on sufficient decrease of E
   *   (Armijo, with the directional derivative of E, which is nonsmooth
   *   at stick nodes; plain decrease where that derivative is not
   *   negative); it is halved up to three times; if that fails, the other
   *   model (capped or true slope) is tried from the same iterate (a
   *   failed true step also halves the residual below which the true
   *   slope is taken again); if both fail (or the true step, where no cap
   *   makes it the only model), the true step is halved further, down to
   *   1/64 (shortest_true_step, no solve), and if that fails too, or the
   *   step's solver refuses its matrix (ExcIndefiniteNewtonMatrix: both
   *   models give it the same capped matrix), a convexification step is
   *   taken instead (the Tresca problem with the bounds of the current
   *   slip rates), which lowers E because j is concave along |v| (a
   *   majorisation); it is solved to start_residual_tolerance, and to
   *   friction_residual_tolerance only where that rougher solution does
   *   not lower E.
   * - The extrapolation: after slow_limit full capped steps in a row on
   *   repeating sets whose residual fell by less than 30 % (E nearly flat
   *   along the step, the model's curvature far above E's), a full capped
   *   step is extrapolated to lengths 2, 4, ... up to
   *   longest_extrapolation while E keeps falling (no solve).
   * - The stick proposal: after creep_limit full capped steps on repeating
   *   sets whose residual grew (the capped model creeping towards a node's
   *   stick state), the slip nodes weakening faster than the cap that
   *   slowed down are proposed to stick: one Newton step with them held,
   *   taken if it lowers E.
   * - Convergence: at a solution (the sets repeat and max_p |F_p| (the
   *   Euclidean norm of the node's vector) <= friction_residual_tolerance
   *   max_p g_p(0)) where some slip node weakens faster than
   *   weakening_cap_fraction times the convexity limit, the curvature test
   *   decides whether it is a local minimum.
   * - The saddle exit: where the test finds negative curvature (a saddle),
   *   the method leaves the point along the direction of most negative
   *   curvature on the slip set, to the lowest E among a few lengths both
   *   ways (no solve: v and eta move together), and goes on from there
   *   with the capped model; every later step keeps E below the saddle's,
   *   so it is never met again. After max_saddle_exits such exits, or
   *   where the test cannot tell, or no length lowers E, the result says
   *   so (minimum_not_certified) and is not converged.
   */
  class FrictionNewton
  {
  public:
    /** The method's tuned constants. */
    static constexpr FrictionNewtonConstants constants{};

    /** The arguments of solve_friction_newton(); (eta, v) are the iterate,
     *  the previous step's state on entry and the solution on return. */
    FrictionNewton(const TrescaNewtonStep &step_solver,
                   const CurvatureTest    &curvature_test,
                   const unsigned int      n_components,
                   const NodalLaw         &nodal_law,
                   const Vector<double>   &parameter_c,
                   const unsigned int      max_newton_iterations,
                   const unsigned int      max_tresca_iterations,
                   Vector<double>         &iterate_eta,
                   Vector<double>         &iterate_v);

    /** Runs the method (once per object); the final sets in `state`. */
    FrictionNewtonResult solve(std::vector<NodeState> &state);

  private:
    /** What a Newton step with its line search gave: the accepted length
     *  (0: none), whether it was the capped model's, and whether the
     *  solver refused the step's matrix. */
    struct Step
    {
      double length  = 1.;
      bool   capped  = false;
      bool   refused = false;
    };

    // The method, in the order of solve() (friction_newton.cc).
    bool start();
    Step newton_step_with_line_search();
    bool try_other_model(const Step &step);
    void search_true_step_further(Step &step);
    bool convexification_instead();
    void extrapolate();
    bool accept_trial();
    void count_slow_steps(const bool full_capped_step, const double last);
    bool stick_proposal_taken();
    bool ends_step();

    // At a solution (friction_newton_second_order.cc).
    Curvature test_second_order();
    bool      leave_saddle();
    double    lowest_energy_along(const Vector<double> &direction_eta,
                                  const Vector<double> &direction_v,
                                  const double          reach);

    // The linearisation and the steps it gives.
    std::vector<NodeLinearisation> linearise(const bool capped_model) const;
    double                         law_residual() const;
    double                         backtrack(const double shortest_length);
    bool convexification_step(const double relative_tolerance);
    bool propose_stick();

    // The energy E, measured from a reference iterate.
    double energy_at(const Vector<double> &eta_at,
                     const Vector<double> &v_at,
                     double               &scale) const;
    double energy_from(const Vector<double> &from_eta,
                       const Vector<double> &from_v);
    double energy_here();

    // The problem.
    const TrescaNewtonStep &newton_step;
    const CurvatureTest    &curvature;
    const unsigned int      m;
    const NodalLaw         &law;
    const Vector<double>   &c;
    const unsigned int      max_iterations;
    const unsigned int      max_active_set_iterations;
    /** max_p g_p(0), the scale of the residuals. */
    const double largest_bound;
    /** The residual of a solution, friction_residual_tolerance times
     *  largest_bound. */
    const double tolerance;
    /** Whether the law has a cap, so that the model may switch between the
     *  capped and the true slopes. */
    const bool may_uncap;
    /** Whether E may be nonconvex: the start is then a convexification
     *  step. */
    const bool nonconvex;

    FrictionNewtonResult result;

    // The iterate and its linearisation.
    Vector<double> &eta, &v;
    /** Whether the model caps the weakening (else: the true slopes). */
    bool                           capped;
    std::vector<NodeLinearisation> linearisation;
    /** The complementarity residual of the iterate (infinite before the
     *  first step and after a saddle exit). */
    double residual;

    // The energy E: formed only where a line search needs it, so that a
    // step solved by its start or its first full Newton step never forms
    // it, and measured from the first iterate where it is needed
    // (NodalLaw::energy()), one that solves the step's equations.
    /** E at the iterate; NaN until it is first needed. */
    double         energy;
    Vector<double> reference_eta, reference_v;
    /** Whether (eta, v) solve the step's equations: not the previous
     *  step's state on entry. */
    bool solves_step;

    /** The trial iterate of a step and its E; after the step, the iterate
     *  before it. */
    Vector<double> new_eta, new_v;
    double         new_energy;
    /** The full step with the true slopes from the current iterate, kept
     *  for the longer search of search_true_step_further(). */
    Vector<double> true_step_eta, true_step_v;

    // Where a model's step fails to lower E, the other model is tried.
    /** The residual below which the true slopes take over. */
    double uncap_below;
    /** Whether the capped or the true model's step failed from the
     *  current iterate. */
    bool capped_failed, uncapped_failed;

    /** Full capped steps on repeating sets in a row whose residual grew
     *  (stick proposal after creep_limit). */
    unsigned int creeping;
    /** Full capped steps on repeating sets in a row whose residual fell by
     *  less than slow_contraction (extrapolation after slow_limit). */
    unsigned int slow_steps;
  };

} // namespace Contact

#endif
