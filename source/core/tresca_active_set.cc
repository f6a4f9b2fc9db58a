/* The Tresca problem on Gamma_3 (the friction condition with frozen
   bounds) by the primal-dual active set method, and the complementarity
   function that it and Newton's method on the full law solve. */

#include <core/complementarity.h>
#include <core/friction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Contact
{
  // @sect3{The complementarity function}

  namespace Complementarity
  {
    double node_norm(const Vector<double> &x,
                     const unsigned int    p,
                     const unsigned int    m)
    {
      double sum = 0;
      for (unsigned int i = 0; i < m; ++i)
        sum += x[p * m + i] * x[p * m + i];
      return std::sqrt(sum);
    }

    // The linearisation of the complementarity function at one node: its
    // state, the unit vector zhat along z_p = eta_p + c_p v_p, and beta_p.
    // A node with g_p = 0 slips with eta_p = 0 whatever v_p does; its
    // direction is that of v_p (the first axis if v_p = 0) to keep it
    // deterministic.
    std::vector<NodeLinearisation> linearise(const unsigned int    m,
                                             const Vector<double> &eta,
                                             const Vector<double> &v,
                                             const Vector<double> &g,
                                             const Vector<double> &c)
    {
      std::vector<NodeLinearisation> result(g.size());
      for (unsigned int p = 0; p < g.size(); ++p)
        {
          NodeLinearisation &node = result[p];
          node.direction.assign(m, 0.);
          double z_norm = 0, v_norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              node.direction[i] = eta[p * m + i] + c[p] * v[p * m + i];
              z_norm += node.direction[i] * node.direction[i];
              v_norm += v[p * m + i] * v[p * m + i];
            }
          z_norm     = std::sqrt(z_norm);
          node.bound = g[p];
          node.force = g[p];
          if (g[p] == 0.)
            {
              node.state = NodeState::slip;
              for (unsigned int i = 0; i < m; ++i)
                node.direction[i] =
                  (v_norm > 0 ? v[p * m + i] / std::sqrt(v_norm) : i == 0);
            }
          else if (z_norm > g[p])
            {
              node.state = NodeState::slip;
              for (double &d : node.direction)
                d /= z_norm;
              node.beta = (z_norm - g[p]) / (g[p] * c[p]);
            }
        }
      return result;
    }

    // The sets that the cycle detection compares: stick, or slip with (in
    // 2D) its sign.
    std::vector<int>
    set_signature(const std::vector<NodeLinearisation> &linearisation)
    {
      std::vector<int> signature;
      for (const NodeLinearisation &node : linearisation)
        signature.push_back(node.state == NodeState::stick ? 0 :
                            node.direction.size() > 1      ? 1 :
                            node.direction[0] > 0          ? 1 :
                                                             -1);
      return signature;
    }

    // max_p |eta_p - P_{B(g_p)}(eta_p + c_p v_p)|, with the Euclidean norm
    // of the node's vector, not the largest component: a change of the
    // tangent basis (a rotated scene) must not move the decisions taken on
    // it. Zero at a solution.
    double residual(const unsigned int    m,
                    const Vector<double> &eta,
                    const Vector<double> &v,
                    const Vector<double> &g,
                    const Vector<double> &c)
    {
      double residual = 0;
      for (unsigned int p = 0; p < g.size(); ++p)
        {
          std::vector<double> z(m);
          double              z_norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              z[i] = eta[p * m + i] + c[p] * v[p * m + i];
              z_norm += z[i] * z[i];
            }
          z_norm              = std::sqrt(z_norm);
          const double scale  = (z_norm > g[p] ? g[p] / z_norm : 1.);
          double       defect = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              const double difference = eta[p * m + i] - scale * z[i];
              defect += difference * difference;
            }
          residual = std::max(residual, std::sqrt(defect));
        }
      return residual;
    }
  } // namespace Complementarity


  // @sect3{The Tresca problem by the primal-dual active set method}

  // The orthonormal basis of one node's tangential plane in which the
  // Newton step is diagonal: stick nodes keep the canonical basis; slip
  // nodes take (zhat, zhat rotated by 90 degrees) for m = 2.
  FullMatrix<double> local_basis(const NodeLinearisation &node)
  {
    const unsigned int m = node.direction.size();
    FullMatrix<double> basis(m, m);
    for (unsigned int i = 0; i < m; ++i)
      basis(i, i) = 1;
    if (node.state == NodeState::slip)
      for (unsigned int i = 0; i < m; ++i)
        {
          basis(i, 0) = node.direction[i];
          if (m == 2)
            basis(i, 1) = (i == 0 ? -node.direction[1] : node.direction[0]);
        }
    return basis;
  }

  using Complementarity::linearise;
  using Complementarity::set_signature;

  TrescaResult solve_tresca(const TrescaVelocity   &velocity,
                            const TrescaNewtonStep &newton_step,
                            const unsigned int      m,
                            const Vector<double>   &g,
                            const Vector<double>   &c_initial,
                            const unsigned int      max_iterations,
                            Vector<double>         &eta,
                            Vector<double>         &v,
                            std::vector<NodeState> &state,
                            const double            relative_tolerance)
  {
    AssertDimension(eta.size(), g.size() * m);
    TrescaResult                  result;
    Vector<double>                c = c_initial;
    std::vector<std::vector<int>> history;
    const double                  tolerance =
      relative_tolerance *
      std::max(g.linfty_norm(), std::numeric_limits<double>::min());

    if (velocity)
      velocity(eta, v);
    auto linearisation = linearise(m, eta, v, g, c);

    // Progress test for m = 2, where the slip directions may keep turning
    // without a set repeating: if the residual has not halved within
    // `patience` steps, c is halved as for a cycle.
    const unsigned int patience      = 8;
    double             best_residual = std::numeric_limits<double>::max();
    unsigned int       steps_without_progress = 0;
    const auto         halve_c                = [&]() {
      c *= 0.5;
      ++result.cycles_cured;
      history.clear();
      best_residual          = std::numeric_limits<double>::max();
      steps_without_progress = 0;
      linearisation          = linearise(m, eta, v, g, c);
    };

    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        newton_step(linearisation, eta, v);
        history.push_back(set_signature(linearisation));

        linearisation                    = linearise(m, eta, v, g, c);
        const std::vector<int> signature = set_signature(linearisation);
        const double residual = Complementarity::residual(m, eta, v, g, c);
        if (signature == history.back() && residual <= tolerance)
          {
            result.converged = true;
            break;
          }
        if (residual <= 0.5 * best_residual)
          {
            best_residual          = residual;
            steps_without_progress = 0;
          }
        else
          ++steps_without_progress;
        if ((signature != history.back() &&
             std::find(history.begin(), history.end(), signature) !=
               history.end()) ||
            steps_without_progress >= patience)
          halve_c();
      }
    state.resize(g.size());
    for (unsigned int p = 0; p < g.size(); ++p)
      state[p] = linearisation[p].state;
    return result;
  }

} // namespace Contact
