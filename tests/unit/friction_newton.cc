/* Newton's method on the full nonmonotone law against the convexification
   (a fixed point around Tresca problems), on a dense Delassus operator with
   one (2D) and two (3D) tangential components per node and the slip rate
   weakening bound g_p(s) = S ((a - b) exp(-alpha s) + b):
   - both satisfy the law v = v_free - D eta, |eta_p| <= g_p(0) where
     v_p = 0, eta_p = g_p(|v_p|) v_p / |v_p| elsewhere, to round-off;
   - where the step problem is convex (small alpha) they give the same
     solution, Newton in fewer iterations;
   - where it is not (alpha large), Newton still converges (its line search
     and convexification steps), to a solution of the law, which may be
     another solution than the convexification's (both are printed);
   - a Newton iteration that leaves out the derivative of the bound is the
     convexification's step: it needs more iterations (the check that the
     derivative is in the Jacobian);
   - the step's energy E measured from a reference iterate, without v_free,
     differs between iterates as E does, and a convex step whose first
     Newton step the solver refuses (where E is not known) still ends on
     its solution. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <core/delassus_operator.h>
#include <core/friction.h>
#include <core/parameters.h>
#include <parts/newton/friction_newton.h>

#include "make_delassus.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace Contact;

struct Law
{
  double S, a, b, alpha;
  double bound(const double s) const
  {
    return S * ((a - b) * std::exp(-alpha * s) + b);
  }
  double slope(const double s) const
  {
    return -S * (a - b) * alpha * std::exp(-alpha * s);
  }
};

double
node_norm(const Vector<double> &x, const unsigned int p, const unsigned m)
{
  double sum = 0;
  for (unsigned int i = 0; i < m; ++i)
    sum += x[p * m + i] * x[p * m + i];
  return std::sqrt(sum);
}

// The largest violation of the law relative to g(0), and the stick/slip
// pattern.
std::pair<double, std::string> violation(const FullMatrix<double> &D,
                                         const unsigned int        m,
                                         const Vector<double>     &v_free,
                                         const Law                &law,
                                         const Vector<double>     &eta,
                                         const Vector<double>     &v)
{
  const unsigned int n = eta.size() / m;
  Vector<double>     residual(n * m);
  D.vmult(residual, eta);
  residual += v;
  residual -= v_free;
  double      worst = residual.linfty_norm();
  std::string pattern;
  for (unsigned int p = 0; p < n; ++p)
    {
      const double speed = node_norm(v, p, m), force = node_norm(eta, p, m);
      if (speed < 1e-12)
        {
          worst = std::max(worst, force - law.bound(0));
          pattern += 'S';
          continue;
        }
      for (unsigned int i = 0; i < m; ++i)
        worst = std::max(worst,
                         std::abs(eta[p * m + i] -
                                  law.bound(speed) * v[p * m + i] / speed));
      pattern += 'L';
    }
  return {worst / law.bound(0), pattern};
}

// The law as a .prm file gives it: through the declaration and the parser
// of the subsection Friction.
FrictionLaw make_friction_law(const Law &law)
{
  ParameterHandler prm;
  FrictionParameters::declare_parameters(prm);
  prm.enter_subsection(FrictionLaws::subsection);
  prm.set("Friction law", "slip rate weakening");
  prm.set("Friction bound S", law.S);
  prm.set("a", law.a);
  prm.set("b", law.b);
  prm.set("alpha", law.alpha);
  prm.leave_subsection();
  FrictionParameters parameters;
  parameters.parse_parameters(prm);
  return FrictionLaw(parameters);
}

// Newton's method on the full law from eta = 0, v = v_free, with unit
// weights, the given Newton step and the curvature test on D.
FrictionNewtonResult solve_from_rest(const DelassusOperator   &delassus,
                                     const FullMatrix<double> &D,
                                     const unsigned int        m,
                                     const Vector<double>     &v_free,
                                     const FrictionLaw        &friction_law,
                                     const Vector<double>     &c,
                                     const TrescaNewtonStep   &step,
                                     Vector<double>           &eta,
                                     Vector<double>           &v)
{
  Vector<double> weights(c.size());
  weights = 1.;
  // The convexity limit 1 / lambda_max(D) (unit weights), as the program
  // gives it to the method.
  LAPACKFullMatrix<double> eigen(D.m(), D.n());
  eigen = D;
  eigen.compute_eigenvalues();
  double largest = 0;
  for (unsigned int r = 0; r < D.m(); ++r)
    largest = std::max(largest, eigen.eigenvalue(r).real());
  NodalLaw law{friction_law, weights};
  law.convexity_limit = 1. / largest;
  eta.reinit(v_free.size());
  v = v_free;
  std::vector<NodeState> state;
  return solve_friction_newton(
    step,
    [&](const std::vector<NodeLinearisation> &linearisation) {
      return delassus.curvature_on_slip_set(linearisation);
    },
    m,
    law,
    c,
    200,
    500,
    eta,
    v,
    state);
}

void check(const std::string    &name,
           const unsigned int    m,
           const Vector<double> &v_free,
           const Law            &law)
{
  const unsigned int       n = v_free.size() / m;
  const FullMatrix<double> D = make_delassus(n, m);
  const DelassusOperator   delassus(D, m);
  Vector<double>           c(n);
  for (unsigned int p = 0; p < n; ++p)
    c[p] = 0.05 / D(p * m, p * m);

  const FrictionLaw friction_law = make_friction_law(law);
  // with_slope = false leaves the derivative of the bound out of the
  // Jacobian.
  const auto newton =
    [&](const bool with_slope, Vector<double> &eta, Vector<double> &v) {
      const TrescaNewtonStep step =
        [&](const std::vector<NodeLinearisation> &linearisation,
            Vector<double>                       &eta,
            Vector<double>                       &v) {
          std::vector<NodeLinearisation> used = linearisation;
          if (!with_slope)
            for (NodeLinearisation &node : used)
              {
                node.force = node.bound;
                node.slope = 0;
              }
          delassus.newton_step(used, v_free, eta, v);
        };
      return solve_from_rest(
        delassus, D, m, v_free, friction_law, c, step, eta, v);
    };

  Vector<double>             eta, v;
  const FrictionNewtonResult result      = newton(true, eta, v);
  const auto [newton_violation, pattern] = violation(D, m, v_free, law, eta, v);

  Vector<double>             eta_frozen, v_frozen;
  const FrictionNewtonResult frozen = newton(false, eta_frozen, v_frozen);

  // The convexification: Tresca problems with the bounds of the last slip
  // rates until the rates stop changing.
  Vector<double>         eta_fixed(n * m), v_fixed(v_free), bounds(n);
  std::vector<NodeState> state;
  unsigned int           fixed_point_iterations = 0, active_set_iterations = 0;
  for (; fixed_point_iterations < 1000; ++fixed_point_iterations)
    {
      Vector<double> old_v(v_fixed);
      for (unsigned int p = 0; p < n; ++p)
        bounds[p] = law.bound(node_norm(v_fixed, p, m));
      active_set_iterations +=
        solve_tresca(
          delassus, v_free, bounds, c, 500, eta_fixed, v_fixed, state)
          .iterations;
      old_v -= v_fixed;
      if (old_v.linfty_norm() <= 1e-13 * v_free.linfty_norm())
        break;
    }
  Vector<double> difference(eta);
  difference -= eta_fixed;
  // Where the step problem is not convex both may be right and differ.
  const double fixed_violation =
    violation(D, m, v_free, law, eta_fixed, v_fixed).first;

  std::cout << name << " (m = " << m << ", alpha = " << law.alpha
            << "): Newton converged " << result.converged << " in "
            << result.iterations << " iterations (" << result.damped_steps
            << " damped, " << result.convexification_steps
            << " convexification steps), law holds: "
            << (newton_violation < 1e-11 ? "yes" : "no") << ", state "
            << pattern << "; without the slope " << frozen.iterations
            << " iterations; convexification " << fixed_point_iterations + 1
            << " iterations (" << active_set_iterations
            << " active set), same solution: "
            << (difference.linfty_norm() < 1e-9 * law.bound(0) ? "yes" : "no")
            << " (its law holds: " << (fixed_violation < 1e-9 ? "yes" : "no")
            << ")" << std::endl;
}

// One Newton step solved for the forces and for the velocities
// (DelassusOperator): the same step, for a linearisation with stick nodes,
// Tresca slip nodes, sloped slip nodes and (m = 2) a slip node with
// beta = 0.
void compare_forms(const unsigned int m)
{
  const unsigned int             n = 12;
  const FullMatrix<double>       D = make_delassus(n, m);
  const DelassusOperator         delassus(D, m);
  std::vector<NodeLinearisation> linearisation(n);
  Vector<double>                 v_free(n * m);
  for (unsigned int p = 0; p < n; ++p)
    {
      NodeLinearisation &node = linearisation[p];
      node.direction.assign(m, 0.);
      node.direction[0] = (p % 2 ? -1. : 1.);
      if (m == 2)
        {
          node.direction[0] = std::cos(0.5 * p);
          node.direction[1] = std::sin(0.5 * p);
        }
      for (unsigned int i = 0; i < m; ++i)
        v_free[p * m + i] = std::sin(1. + p + 3. * i);
      if (p < 4)
        continue;
      node.state = NodeState::slip;
      node.bound = node.force = 0.2 + 0.01 * p;
      node.beta               = (p == 5 ? 0. : 0.1 * p);
      if (p >= 8)
        node.slope = -0.3 * p;
    }
  Vector<double> eta_force(n * m), v_force(n * m), eta_velocity(n * m),
    v_velocity(n * m);
  delassus.newton_step(
    linearisation, v_free, eta_force, v_force, DelassusOperator::Form::force);
  delassus.newton_step(linearisation,
                       v_free,
                       eta_velocity,
                       v_velocity,
                       DelassusOperator::Form::velocity);
  eta_velocity -= eta_force;
  v_velocity -= v_force;
  std::cout << "Newton step on D (m = " << m
            << "): force and velocity form agree: "
            << (eta_velocity.linfty_norm() <= 1e-10 * eta_force.linfty_norm() &&
                    v_velocity.linfty_norm() <= 1e-10 * v_free.linfty_norm() ?
                  "yes" :
                  "no")
            << std::endl;
}

// On a large Delassus operator (m = 2, 1000 unknowns) the blocks of
// consecutive Newton steps on (nearly) the same unknowns are solved by
// GMRES preconditioned with an earlier factor: the method must end on the
// same solution as with every block factorised (a new operator, without a
// factor to reuse, for every step).
void check_factor_reuse()
{
  const unsigned int       n = 500, m = 2;
  const FullMatrix<double> D = make_delassus(n, m);
  const DelassusOperator   delassus(D, m);
  Vector<double>           v_free(n * m), c(n);
  for (unsigned int p = 0; p < n; ++p)
    {
      const double angle = 0.01 * p, speed = 0.3 * (p % 50 - 20.);
      v_free[p * m]     = speed * std::cos(angle);
      v_free[p * m + 1] = speed * std::sin(angle);
      c[p]              = 0.05 / D(p * m, p * m);
    }
  // S (a - b) alpha below the smallest 1/D_rr: a convex step problem.
  const Law         law{0.3, 1., 0.5, 0.5};
  const FrictionLaw friction_law = make_friction_law(law);
  const auto        solve =
    [&](const TrescaNewtonStep &step, Vector<double> &eta, Vector<double> &v) {
      return solve_from_rest(
        delassus, D, m, v_free, friction_law, c, step, eta, v);
    };

  Vector<double>             eta, v, eta_factorised, v_factorised;
  const FrictionNewtonResult reusing = solve(
    [&](const std::vector<NodeLinearisation> &linearisation,
        Vector<double>                       &eta,
        Vector<double>                       &v) {
      delassus.newton_step(linearisation, v_free, eta, v);
    },
    eta,
    v);
  const FrictionNewtonResult factorising = solve(
    [&](const std::vector<NodeLinearisation> &linearisation,
        Vector<double>                       &eta,
        Vector<double>                       &v) {
      DelassusOperator(D, m).newton_step(linearisation, v_free, eta, v);
    },
    eta_factorised,
    v_factorised);
  eta_factorised -= eta;
  std::cout << "factor reuse (m = 2, " << n * m
            << " unknowns): Newton converged " << reusing.converged
            << " (every block factorised: " << factorising.converged << ") in "
            << reusing.iterations << " iterations (" << factorising.iterations
            << "), blocks solved by GMRES with an earlier factor: "
            << (delassus.preconditioned_solves() > 0 ? "yes" : "no")
            << ", law holds: "
            << (violation(D, m, v_free, law, eta, v).first < 1e-11 ? "yes" :
                                                                     "no")
            << ", same solution: "
            << (eta_factorised.linfty_norm() < 1e-9 * law.bound(0) ? "yes" :
                                                                     "no")
            << std::endl;
}

// E measured from a reference iterate (NodalLaw::energy(), no v_free)
// orders iterates as E itself does: for iterates with v = v_free - D eta
// its differences are those of 1/2 eta . (v_free - v) + sum_p j(|v_p|).
void check_energy_without_v_free(const unsigned int m)
{
  const unsigned int       n = 12;
  const FullMatrix<double> D = make_delassus(n, m);
  const Law                law{0.3, 1., 0.5, 20.};
  const FrictionLaw        friction_law = make_friction_law(law);
  Vector<double>           weights(n);
  weights = 1.;
  NodalLaw nodal_law{friction_law, weights};

  Vector<double>              v_free(n * m);
  std::vector<Vector<double>> eta(3, Vector<double>(n * m)),
    v(3, Vector<double>(n * m));
  for (unsigned int r = 0; r < n * m; ++r)
    {
      v_free[r] = std::sin(1. + 2. * r);
      for (unsigned int k = 0; k < 3; ++k)
        eta[k][r] = 0.3 * std::cos(0.7 * r + k);
    }
  for (unsigned int k = 0; k < 3; ++k)
    {
      D.vmult(v[k], eta[k]);
      v[k].sadd(-1., 1., v_free);
    }
  const auto with_v_free = [&](const unsigned int k) {
    double value = 0;
    for (unsigned int r = 0; r < n * m; ++r)
      value += 0.5 * eta[k][r] * (v_free[r] - v[k][r]);
    for (unsigned int p = 0; p < n; ++p)
      value += friction_law.potential(node_norm(v[k], p, m));
    return value;
  };
  double mismatch = 0, size = 0, scale = 0;
  for (unsigned int k = 1; k < 3; ++k)
    {
      const double difference =
        nodal_law.energy(eta[0], v[0], eta[k], v[k], scale) -
        nodal_law.energy(eta[0], v[0], eta[0], v[0], scale);
      const double expected = with_v_free(k) - with_v_free(0);
      mismatch = std::max(mismatch, std::abs(difference - expected));
      size     = std::max(size, std::abs(expected));
    }
  std::cout << "E from a reference iterate (m = " << m
            << "): differences as with v_free: "
            << (mismatch <= 1e-13 * size ? "yes" : "no") << std::endl;
}

// Where the solver refuses the first Newton step of a convex problem
// (ExcIndefiniteNewtonMatrix), the iterate is still the start, which
// does not solve the step's equations, so E is not known there: the
// convexification step that replaces it must be taken without a
// comparison, and the method must end on the one solution.
void check_refused_first_step()
{
  const unsigned int       n = 12, m = 1;
  const FullMatrix<double> D = make_delassus(n, m);
  const DelassusOperator   delassus(D, m);
  Vector<double>           v_free(n), c(n);
  for (unsigned int p = 0; p < n; ++p)
    {
      v_free[p] = -0.4 + 0.1 * p;
      c[p]      = 0.05 / D(p, p);
    }
  const Law         law{0.08, 1., 0.5, 2.};
  const FrictionLaw friction_law = make_friction_law(law);
  unsigned int      calls        = 0;
  const auto        step = [&](const bool refuse_first) -> TrescaNewtonStep {
    return [&, refuse_first](const std::vector<NodeLinearisation> &model,
                             Vector<double>                       &eta,
                             Vector<double>                       &v) {
      if (refuse_first && calls++ == 0)
        throw ExcIndefiniteNewtonMatrix();
      delassus.newton_step(model, v_free, eta, v);
    };
  };
  Vector<double>             eta, v, eta_refused, v_refused;
  const FrictionNewtonResult plain = solve_from_rest(
    delassus, D, m, v_free, friction_law, c, step(false), eta, v);
  const FrictionNewtonResult refused = solve_from_rest(delassus,
                                                       D,
                                                       m,
                                                       v_free,
                                                       friction_law,
                                                       c,
                                                       step(true),
                                                       eta_refused,
                                                       v_refused);
  const bool                 law_holds =
    violation(D, m, v_free, law, eta_refused, v_refused).first < 1e-11;
  eta_refused -= eta;
  std::cout << "first Newton step refused (m = 1, alpha = 2): converged "
            << refused.converged << " (not refused: " << plain.converged
            << ") with " << refused.convexification_steps
            << " convexification step, law holds: "
            << (law_holds ? "yes" : "no") << ", same solution: "
            << (eta_refused.linfty_norm() < 1e-9 * law.bound(0) ? "yes" : "no")
            << std::endl;
}

int main()
{
  check_energy_without_v_free(1);
  check_energy_without_v_free(2);
  check_refused_first_step();
  check_factor_reuse();
  compare_forms(1);
  compare_forms(2);
  const unsigned int n = 12;
  Vector<double>     ramp(n), turning(2 * n);
  for (unsigned int p = 0; p < n; ++p)
    {
      ramp[p]            = -0.4 + 0.1 * p;
      const double angle = p * M_PI / 6;
      turning[2 * p]     = (0.1 * p - 0.3) * std::cos(angle);
      turning[2 * p + 1] = (0.1 * p - 0.3) * std::sin(angle);
    }
  for (const double alpha : {2., 20.})
    {
      check("stick and slip both ways", 1, ramp, {0.08, 1., 0.5, alpha});
      check("turning directions", 2, turning, {0.3, 1., 0.5, alpha});
    }
  for (const double alpha : {200., 2000.})
    {
      check("not convex", 1, ramp, {0.08, 1., 0.1, alpha});
      check("not convex, turning", 2, turning, {0.3, 1., 0.1, alpha});
    }
}
