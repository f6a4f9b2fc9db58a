/* Newton's method on the full law must end on a local minimum of the step
   energy E, not on a saddle. A 3-node chain (the Delassus operator of
   make_delassus.h, one tangential component per node) with the slip rate
   weakening law well beyond the convexity limit has stationary points of E
   with a node slipping slowly and negative curvature of E along its slip.
   From 2000 random starts (forces and velocities of a previous step, a
   random v_free) per case, an independent check (the smallest eigenvalue of
   the reduced Hessian W_SS + diag(g'(s_p)) on the slip set S, W = D^{-1})
   looks at every end point:
   - with the curvature test replaced by one that certifies every point,
     some starts end on a saddle in each of the four cases (what the test
     must catch; at alpha = 5 none did before a failed true step was
     searched down to 1/64 of its length,
     FrictionNewtonConstants::shortest_true_step);
   - with the curvature test of DelassusOperator (from W, and from D alone)
     and with the capacitance test from Newton steps, which a path falls
     back on where its own test cannot tell, every start converges to a
     local minimum: where the method met a saddle it left it along its
     negative curvature (in each case some starts do, the same starts with
     every test) and went on to a minimum; none is handed back to the
     convexification. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <core/delassus_operator.h>
#include <core/friction.h>
#include <core/parameters.h>
#include <parts/newton/friction_newton.h>

#include "make_delassus.h"

#include <cmath>
#include <cstdint>
#include <iostream>

using namespace Contact;

namespace
{
  // A deterministic uniform number in [lower, upper): a linear congruential
  // generator written out, so that the starts are the same with every
  // standard library.
  struct Random
  {
    std::uint64_t state = 12345;
    double        operator()(const double lower, const double upper)
    {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return lower + (upper - lower) * static_cast<double>(state >> 11) /
                       9007199254740992.;
    }
  };

  FrictionLaw make_law(const double alpha)
  {
    ParameterHandler prm;
    FrictionParameters::declare_parameters(prm);
    prm.enter_subsection(FrictionLaws::subsection);
    prm.set("Friction law", "slip rate weakening");
    prm.set("Friction bound S", 1.);
    prm.set("a", 1.);
    prm.set("b", 0.5);
    prm.set("alpha", alpha);
    prm.leave_subsection();
    FrictionParameters parameters;
    parameters.parse_parameters(prm);
    return FrictionLaw(parameters);
  }

  // The smallest eigenvalue of W_SS + diag(g'(|v_p|)) on the slip set: the
  // Hessian of E restricted to the stick nodes' v_p = 0 (m = 1).
  double smallest_curvature(const LAPACKFullMatrix<double> &W,
                            const FrictionLaw              &law,
                            const Vector<double>           &v)
  {
    std::vector<unsigned int> slip;
    for (unsigned int p = 0; p < v.size(); ++p)
      if (v[p] != 0.)
        slip.push_back(p);
    if (slip.empty())
      return std::numeric_limits<double>::infinity();
    LAPACKFullMatrix<double> H(slip.size(), slip.size());
    for (unsigned int a = 0; a < slip.size(); ++a)
      {
        for (unsigned int b = 0; b < slip.size(); ++b)
          H(a, b) = W(slip[a], slip[b]);
        H(a, a) += law.bound_derivative(std::abs(v[slip[a]]));
      }
    H.compute_eigenvalues();
    double smallest = std::numeric_limits<double>::infinity();
    for (unsigned int a = 0; a < slip.size(); ++a)
      smallest = std::min(smallest, H.eigenvalue(a).real());
    return smallest;
  }

  struct Counts
  {
    unsigned int              converged = 0, not_minimum = 0;
    std::vector<unsigned int> left_saddle;
  };

  // How the end point is tested: not at all (every point certified), by
  // DelassusOperator's dense test from W (the velocity form) or from D
  // alone (the force form), or by the capacitance test from Newton steps
  // that a path which cannot tell falls back on.
  enum class Test
  {
    none,
    dense_velocity,
    dense_force,
    capacitance
  };

  Counts run_starts(const double alpha, const bool capped, const Test test)
  {
    const unsigned int       n = 3;
    const FullMatrix<double> D = make_delassus(n, 1);
    const DelassusOperator   delassus(D, 1);
    LAPACKFullMatrix<double> W(n, n);
    W = D;
    W.invert();
    // 1 / lambda_max(D) with unit weights.
    LAPACKFullMatrix<double> eigen(n, n);
    eigen = D;
    eigen.compute_eigenvalues();
    double largest = 0;
    for (unsigned int p = 0; p < n; ++p)
      largest = std::max(largest, eigen.eigenvalue(p).real());

    const FrictionLaw law = make_law(alpha);
    Vector<double>    weights(n), c(n);
    weights = 1.;
    for (unsigned int p = 0; p < n; ++p)
      c[p] = 0.05 / D(p, p);
    NodalLaw nodal_law{law, weights};
    nodal_law.convexity_limit = 1. / largest;
    if (capped)
      nodal_law.weakening_cap = weakening_cap_fraction / largest;

    Random random;
    Counts counts;
    for (unsigned int start = 0; start < 2000; ++start)
      {
        Vector<double> v_free(n), eta(n), v(n);
        for (unsigned int p = 0; p < n; ++p)
          {
            v_free[p] = random(-0.5, 0.5);
            eta[p]    = random(-1., 1.);
            v[p]      = random(-0.1, 0.1);
          }
        std::vector<NodeState>     state;
        const FrictionNewtonResult result = solve_friction_newton(
          [&](const std::vector<NodeLinearisation> &linearisation,
              Vector<double>                       &force,
              Vector<double>                       &velocity) {
            delassus.newton_step(linearisation, v_free, force, velocity);
          },
          [&](const std::vector<NodeLinearisation> &linearisation) {
            switch (test)
              {
                case Test::none:
                  return Curvature::positive;
                case Test::dense_velocity:
                  return delassus.curvature_on_slip_set(
                    linearisation, DelassusOperator::Form::velocity);
                case Test::dense_force:
                  return delassus.curvature_on_slip_set(
                    linearisation, DelassusOperator::Form::force);
                case Test::capacitance:
                  break;
              }
            return Curvature::unknown;
          },
          1,
          nodal_law,
          c,
          200,
          500,
          eta,
          v,
          state);
        if (result.saddle_exits > 0)
          counts.left_saddle.push_back(start);
        if (result.converged)
          {
            ++counts.converged;
            if (smallest_curvature(W, law, v) < 0.)
              ++counts.not_minimum;
          }
      }
    return counts;
  }

  void run_case(const double alpha, const bool capped)
  {
    const Counts unchecked = run_starts(alpha, capped, Test::none);
    std::cout << "alpha = " << alpha << (capped ? ", capped" : "")
              << ": without the curvature test some starts end on a saddle: "
              << (unchecked.not_minimum > 0 ? "yes" : "no") << std::endl;
    std::vector<unsigned int> dense_left_saddle;
    for (const Test test :
         {Test::dense_velocity, Test::dense_force, Test::capacitance})
      {
        const Counts checked = run_starts(alpha, capped, test);
        if (test == Test::dense_velocity)
          dense_left_saddle = checked.left_saddle;
        std::cout << "  with the "
                  << (test == Test::dense_velocity ? "dense test from W" :
                      test == Test::dense_force    ? "dense test from D" :
                                                     "capacitance test")
                  << " every start converges to a local minimum: "
                  << (checked.converged == 2000 && checked.not_minimum == 0 ?
                        "yes" :
                        "no")
                  << ", some left a saddle along its negative curvature: "
                  << (checked.left_saddle.empty() ? "no" : "yes");
        if (test != Test::dense_velocity)
          std::cout << ", the same starts as with W: "
                    << (checked.left_saddle == dense_left_saddle ? "yes" :
                                                                   "no");
        std::cout << std::endl;
      }
  }
} // namespace

int main()
{
  for (const double alpha : {5., 20., 50.})
    run_case(alpha, false);
  run_case(20., true);
}
