/* The end points of Newton's method on the full law (FrictionNewton): the
   test whether a solution of the law is a local minimum of E, and the exit
   from a saddle along its negative curvature. */

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <core/complementarity.h>
#include <parts/newton/friction_newton.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  using Complementarity::node_norm;

  // @sect3{The second-order conditions}

  namespace
  {
    // The responses of the capped model to more force along zhat_b on the
    // slip nodes B that weaken faster than `cap`, and the capacitance matrix
    // they give. With the true slopes the Newton matrix is
    // H = H_c - sum_{p in B} delta_p z_p z_p^T, where H_c caps the
    // weakening at `cap` (positive definite, below the convexity limit),
    // delta_p is the excess and z_p the load of a unit force along zhat_p.
    // H is positive definite iff the capacitance matrix
    // I - Delta^{1/2} Z^T H_c^{-1} Z Delta^{1/2} is (Sylvester's law of
    // inertia), and Z^T H_c^{-1} Z is the response of the slip velocities
    // along zhat to unit forces, which |B| + 1 Newton steps with the capped
    // model give (more force along zhat_b is the load -z_b; it is scaled
    // like the forces, so that the difference of two steps is not lost in
    // their round-off): |B| + 1 solves.
    struct SteepResponses
    {
      std::vector<unsigned int> nodes;
      std::vector<double>       excess;
      // Forces and velocities per unit force along zhat_b.
      std::vector<Vector<double>> eta, v;
      LAPACKFullMatrix<double>    capacitance;
    };

    SteepResponses steep_responses(const TrescaNewtonStep        &newton_step,
                                   const unsigned int             m,
                                   const NodalLaw                &law,
                                   const double                   cap,
                                   std::vector<NodeLinearisation> capped,
                                   const Vector<double>          &eta,
                                   const Vector<double>          &v)
    {
      SteepResponses result;
      for (unsigned int p = 0; p < capped.size(); ++p)
        if (capped[p].state == NodeState::slip &&
            capped[p].slope < -cap * law.weights[p])
          {
            result.nodes.push_back(p);
            result.excess.push_back(-capped[p].slope - cap * law.weights[p]);
            capped[p].slope = -cap * law.weights[p];
          }
      const auto response = [&](const std::vector<NodeLinearisation> &model,
                                Vector<double>                       &force,
                                Vector<double>                       &w) {
        force = eta;
        w     = v;
        newton_step(model, force, w);
      };
      double force_scale = 0;
      for (const NodeLinearisation &node : capped)
        force_scale = std::max(force_scale, node.bound);
      Vector<double> base_eta, base_v;
      response(capped, base_eta, base_v);
      const unsigned int n_steep = result.nodes.size();
      result.eta.resize(n_steep);
      result.v.resize(n_steep);
      result.capacitance.reinit(n_steep, n_steep);
      for (unsigned int b = 0; b < n_steep; ++b)
        {
          std::vector<NodeLinearisation> model = capped;
          model[result.nodes[b]].force += force_scale;
          response(model, result.eta[b], result.v[b]);
          result.eta[b] -= base_eta;
          result.eta[b] /= force_scale;
          result.v[b] -= base_v;
          result.v[b] /= force_scale;
          for (unsigned int a = 0; a < n_steep; ++a)
            {
              double along = 0;
              for (unsigned int i = 0; i < m; ++i)
                along += capped[result.nodes[a]].direction[i] *
                         result.v[b][result.nodes[a] * m + i];
              result.capacitance(a, b) =
                (a == b ? 1. : 0.) +
                std::sqrt(result.excess[a] * result.excess[b]) * along;
            }
        }
      return result;
    }

    // The curvature test from Newton steps alone, for a path whose own test
    // cannot tell (the Delassus path where D is singular on the stick
    // unknowns; tests/unit/friction_newton_minimum compares it with the
    // dense test).
    Curvature
    capacitance_test(const TrescaNewtonStep               &newton_step,
                     const unsigned int                    m,
                     const NodalLaw                       &law,
                     const double                          cap,
                     const std::vector<NodeLinearisation> &linearisation,
                     const Vector<double>                 &eta,
                     const Vector<double>                 &v)
    {
      return definiteness(
        steep_responses(newton_step, m, law, cap, linearisation, eta, v)
          .capacitance);
    }

    // The eigenvector of the symmetric part of `matrix` for its lowest
    // eigenvalue if that is negative, else an empty vector.
    Vector<double> most_negative_direction(LAPACKFullMatrix<double> matrix)
    {
      const unsigned int n = matrix.m();
      Vector<double>     direction;
      if (n == 0)
        return direction;
      double size = 1.;
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < a; ++b)
          matrix(a, b) = matrix(b, a) = 0.5 * (matrix(a, b) + matrix(b, a));
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          size += std::abs(matrix(a, b));
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      matrix.compute_eigenvalues_symmetric(
        -size, 0., 1e-12 * size, eigenvalues, eigenvectors);
      if (eigenvalues.size() == 0)
        return direction;
      unsigned int lowest = 0;
      for (unsigned int k = 1; k < eigenvalues.size(); ++k)
        if (eigenvalues[k] < eigenvalues[lowest])
          lowest = k;
      direction.reinit(n);
      for (unsigned int a = 0; a < n; ++a)
        direction[a] = eigenvectors(a, lowest);
      return direction;
    }
  } // namespace

  // Whether a solution is a local minimum of E: certified without a test
  // where every slip node weakens slower than weakening_cap_fraction times
  // the convexity limit (friction_solver.cc), by the path's curvature test
  // on the Hessian otherwise, or where that cannot tell by the capacitance
  // test. Returns the verdict, which it also records in the result.
  Curvature FrictionNewton::test_second_order()
  {
    const double certified   = weakening_cap_fraction * law.convexity_limit;
    const auto   true_slopes = linearise(false);
    for (unsigned int p = 0; p < true_slopes.size(); ++p)
      {
        const double weakening = -true_slopes[p].slope;
        if (true_slopes[p].state == NodeState::slip && weakening > 0 &&
            !(weakening < certified * law.weights[p]))
          result.beyond_convexity_limit = true;
      }
    Curvature verdict = Curvature::positive;
    try
      {
        if (result.beyond_convexity_limit)
          verdict = curvature(true_slopes);
        if (verdict == Curvature::unknown && certified > 0)
          verdict = capacitance_test(
            newton_step, m, law, certified, true_slopes, eta, v);
      }
    catch (const ExcIndefiniteNewtonMatrix &)
      {
        // The capped model's matrix was refused: nothing is certified.
        verdict = Curvature::unknown;
      }
    result.converged             = (verdict == Curvature::positive);
    result.minimum_not_certified = !result.converged;
    return verdict;
  }

  // Leaves a stationary point of E that is not a local minimum along the
  // direction of most negative curvature on the slip set: with y the
  // eigenvector of the capacitance matrix for its smallest eigenvalue
  // 1 - mu < 0, the response (deta, dv) of the capped model to the forces
  // Delta^{1/2} y along zhat has the curvature
  //   dv^T H dv = mu (1 - mu) |y|^2 < 0,
  // so E falls to both sides. v and eta move together (v = v_free - D eta
  // stays affine), so the line search costs no solve: the lengths that
  // change a slip rate by up to saddle_reach times the fastest steep
  // node's rate, both ways, and the lowest E is taken if it is below the
  // saddle's. Returns whether E fell. Its |B| + 1 Newton steps are those of
  // the capacitance test. The slopes are the true ones: the iterate may
  // have converged with the capped model, whose slopes are all at the cap.
  bool FrictionNewton::leave_saddle()
  {
    const std::vector<NodeLinearisation> true_slopes = linearise(false);
    const double cap = weakening_cap_fraction * law.convexity_limit;
    if (!(cap > 0))
      return false;
    const SteepResponses responses =
      steep_responses(newton_step, m, law, cap, true_slopes, eta, v);
    const Vector<double> y = most_negative_direction(responses.capacitance);
    if (y.size() == 0)
      return false;
    Vector<double> direction_eta(eta.size()), direction_v(v.size());
    double         fastest = 0;
    for (unsigned int b = 0; b < y.size(); ++b)
      {
        const double force = std::sqrt(responses.excess[b]) * y[b];
        direction_eta.add(force, responses.eta[b]);
        direction_v.add(force, responses.v[b]);
        fastest = std::max(fastest, node_norm(v, responses.nodes[b], m));
      }
    double largest_change = 0;
    for (unsigned int p = 0; p < true_slopes.size(); ++p)
      largest_change = std::max(largest_change, node_norm(direction_v, p, m));
    if (!(largest_change > 0))
      return false;
    const double length =
      lowest_energy_along(direction_eta,
                          direction_v,
                          constants.saddle_reach * fastest / largest_change);
    if (length == 0.)
      return false;
    eta.add(length, direction_eta);
    v.add(length, direction_v);
    return true;
  }

  // The length t in +-reach 2^{-k}, k = 0, ..., 9, with the lowest
  // E(eta + t deta, v + t dv), if that is below `energy` (then lowered to
  // it) beyond round-off; 0 otherwise.
  double
  FrictionNewton::lowest_energy_along(const Vector<double> &direction_eta,
                                      const Vector<double> &direction_v,
                                      const double          reach)
  {
    double         scale = 0, best_length = 0;
    Vector<double> trial_eta(eta), trial_v(v);
    for (const double sign : {1., -1.})
      for (double length = reach;
           length > constants.shortest_saddle_length * reach;
           length /= 2)
        {
          trial_eta = eta;
          trial_eta.add(sign * length, direction_eta);
          trial_v = v;
          trial_v.add(sign * length, direction_v);
          const double trial_energy = energy_at(trial_eta, trial_v, scale);
          if (trial_energy < energy - law.energy_accuracy * scale)
            {
              energy      = trial_energy;
              best_length = sign * length;
            }
        }
    return best_length;
  }

} // namespace Contact
