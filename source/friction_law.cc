/* The friction law (6.1) and the nodal Tresca solver on Gamma_3. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <friction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Contact
{
  // @sect3{The friction law}

  FrictionLaw::FrictionLaw(const FrictionParameters &parameters)
    : law(parameters.law)
    , S(parameters.bound_S)
    , a(parameters.a)
    , b(parameters.b)
    , alpha(parameters.alpha)
  {}

  double FrictionLaw::coefficient(const double slip_rate) const
  {
    switch (law)
      {
        case FrictionParameters::Law::none:
          return 0.;
        case FrictionParameters::Law::constant:
          return a;
        case FrictionParameters::Law::slip_rate_weakening:
          // (6.1)
          return (a - b) * std::exp(-alpha * slip_rate) + b;
      }
    return 0.;
  }

  double FrictionLaw::bound(const double slip_rate) const
  {
    return S * coefficient(slip_rate);
  }

  double FrictionLaw::potential(const double slip_velocity) const
  {
    const double s = std::abs(slip_velocity);
    if (is_frictionless())
      return 0.;
    if (is_rate_independent())
      return S * coefficient(0.) * s;
    return S * (b * s + (a - b) * (1. - std::exp(-alpha * s)) / alpha);
  }

  bool FrictionLaw::is_frictionless() const
  {
    return law == FrictionParameters::Law::none || S == 0. ||
           (a == 0. && b == 0.);
  }

  bool FrictionLaw::is_rate_independent() const
  {
    return law != FrictionParameters::Law::slip_rate_weakening || a == b ||
           alpha == 0.;
  }

  double FrictionLaw::one_sided_lipschitz_constant() const
  {
    return is_rate_independent() ? 0. : (a - b) * alpha;
  }


  // @sect3{Anderson acceleration}

  AndersonAcceleration::AndersonAcceleration(const unsigned int depth)
    : depth(depth)
    , accelerated(false)
  {}

  void AndersonAcceleration::restart()
  {
    residual_differences.clear();
    image_differences.clear();
    previous_residual.reinit(0);
    previous_image.reinit(0);
    accelerated = false;
  }

  bool AndersonAcceleration::last_step_was_accelerated() const
  {
    return accelerated;
  }

  void AndersonAcceleration::next_iterate(Vector<double>       &x,
                                          const Vector<double> &image)
  {
    Vector<double> residual(image);
    residual -= x;
    if (depth > 0 && previous_residual.size() == x.size())
      {
        residual_differences.push_back(residual);
        residual_differences.back() -= previous_residual;
        image_differences.push_back(image);
        image_differences.back() -= previous_image;
        if (residual_differences.size() > depth)
          {
            residual_differences.erase(residual_differences.begin());
            image_differences.erase(image_differences.begin());
          }
      }
    previous_residual = residual;
    previous_image    = image;

    const unsigned int m = residual_differences.size();
    x                    = image;
    accelerated          = (m > 0);
    if (m == 0)
      return;

    // Least squares min |residual - dF gamma| by the normal equations,
    // regularised relative to their size (m is small).
    LAPACKFullMatrix<double> normal(m, m);
    Vector<double>           gamma(m);
    double                   trace = 0;
    for (unsigned int i = 0; i < m; ++i)
      {
        gamma[i] = residual_differences[i] * residual;
        for (unsigned int j = 0; j < m; ++j)
          normal(i, j) = residual_differences[i] * residual_differences[j];
        trace += normal(i, i);
      }
    if (trace == 0.)
      {
        accelerated = false;
        return;
      }
    for (unsigned int i = 0; i < m; ++i)
      normal(i, i) += 1e-10 * trace;
    normal.set_property(LAPACKSupport::symmetric);
    normal.compute_cholesky_factorization();
    normal.solve(gamma);
    for (unsigned int i = 0; i < m; ++i)
      x.add(-gamma[i], image_differences[i]);
  }


  // @sect3{The Tresca problem by the primal-dual active set method}

  namespace
  {
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
          z_norm = std::sqrt(z_norm);
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

    // One Newton step: in the rotated unknowns eta' = Q^T eta (Q block
    // diagonal of the local bases), the components eta'_{p,0} = g_p of the
    // slip nodes are fixed, as are the components with D_rr = 0 of stick
    // nodes (a zero tangent: a direction the node cannot move in, e.g. on a
    // symmetry plane; eta' = 0 there), and the others solve
    //   (Q^T D Q + diag beta)_FF eta'_F = (Q^T v_free)_F - (Q^T D Q)_FL g_L,
    // which is SPD. Then v = v_free - D eta, and v_p = 0 where p sticks.
    // Q^T D Q is formed entry by entry from the m x m blocks, O((nm)^2 m^2).
    void newton_step(const FullMatrix<double>             &D,
                     const std::vector<NodeLinearisation> &linearisation,
                     const Vector<double>                 &v_free,
                     const Vector<double>                 &g,
                     Vector<double>                       &eta,
                     Vector<double>                       &v)
    {
      const unsigned int              n = g.size(), m = D.m() / n;
      std::vector<FullMatrix<double>> Q;
      for (const NodeLinearisation &node : linearisation)
        Q.push_back(local_basis(node));
      // For m = 1 the rotation is a sign per node.
      std::vector<double> sign(n);
      for (unsigned int p = 0; p < n; ++p)
        sign[p] = Q[p](0, 0);
      const auto rotated_D = [&](const unsigned int r, const unsigned int s) {
        if (m == 1)
          return sign[r] * D(r, s) * sign[s];
        const unsigned int p = r / m, a = r % m, q = s / m, b = s % m;
        double             entry = 0;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            entry += Q[p](i, a) * D(p * m + i, q * m + j) * Q[q](j, b);
        return entry;
      };

      std::vector<unsigned int> free, fixed;
      Vector<double>            rotated_eta(n * m);
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int i = 0; i < m; ++i)
          if ((linearisation[p].state == NodeState::stick &&
               D(p * m + i, p * m + i) > 0) ||
              (linearisation[p].state == NodeState::slip && i > 0 && g[p] > 0))
            free.push_back(p * m + i);
          else
            {
              fixed.push_back(p * m + i);
              rotated_eta[p * m + i] =
                (linearisation[p].state == NodeState::slip && i == 0 ? g[p] :
                                                                       0.);
            }

      if (!free.empty())
        {
          const unsigned int       n_free = free.size();
          LAPACKFullMatrix<double> matrix(n_free, n_free);
          Vector<double>           rhs(n_free);
          for (unsigned int a = 0; a < n_free; ++a)
            {
              const unsigned int r = free[a], p = r / m;
              for (unsigned int i = 0; i < m; ++i)
                rhs[a] += Q[p](i, r % m) * v_free[p * m + i];
              for (const unsigned int s : fixed)
                rhs[a] -= rotated_D(r, s) * rotated_eta[s];
              for (unsigned int b = 0; b <= a; ++b)
                matrix(a, b) = matrix(b, a) = rotated_D(r, free[b]);
              matrix(a, a) += linearisation[p].beta;
            }
          matrix.set_property(LAPACKSupport::symmetric);
          matrix.compute_cholesky_factorization();
          matrix.solve(rhs);
          for (unsigned int a = 0; a < n_free; ++a)
            rotated_eta[free[a]] = rhs[a];
        }

      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int i = 0; i < m; ++i)
          {
            eta[p * m + i] = 0;
            for (unsigned int a = 0; a < m; ++a)
              eta[p * m + i] += Q[p](i, a) * rotated_eta[p * m + a];
          }
      D.vmult(v, eta);
      v.sadd(-1., 1., v_free);
      for (unsigned int p = 0; p < n; ++p)
        if (linearisation[p].state == NodeState::stick)
          for (unsigned int i = 0; i < m; ++i)
            v[p * m + i] = 0.;
    }

    // max_p |eta_p - P_{B(g_p)}(eta_p + c_p v_p)|: zero at a solution.
    double complementarity_residual(const unsigned int    m,
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
          z_norm             = std::sqrt(z_norm);
          const double scale = (z_norm > g[p] ? g[p] / z_norm : 1.);
          for (unsigned int i = 0; i < m; ++i)
            residual =
              std::max(residual, std::abs(eta[p * m + i] - scale * z[i]));
        }
      return residual;
    }
  } // namespace


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

  TrescaResult solve_tresca(const FullMatrix<double> &D,
                            const unsigned int        m,
                            const Vector<double>     &v_free,
                            const Vector<double>     &g,
                            const Vector<double>     &c,
                            const unsigned int        max_iterations,
                            Vector<double>           &eta,
                            Vector<double>           &v,
                            std::vector<NodeState>   &state)
  {
    AssertDimension(D.m(), v_free.size());
    const auto velocity = [&](const Vector<double> &eta, Vector<double> &v) {
      D.vmult(v, eta);
      v.sadd(-1., 1., v_free);
    };
    const auto step = [&](const std::vector<NodeLinearisation> &linearisation,
                          Vector<double>                       &eta,
                          Vector<double>                       &v) {
      newton_step(D, linearisation, v_free, g, eta, v);
    };
    return solve_tresca(velocity, step, m, g, c, max_iterations, eta, v, state);
  }


  TrescaResult solve_tresca(const TrescaVelocity   &velocity,
                            const TrescaNewtonStep &newton_step,
                            const unsigned int      m,
                            const Vector<double>   &g,
                            const Vector<double>   &c_initial,
                            const unsigned int      max_iterations,
                            Vector<double>         &eta,
                            Vector<double>         &v,
                            std::vector<NodeState> &state)
  {
    AssertDimension(eta.size(), g.size() * m);
    TrescaResult                  result;
    Vector<double>                c = c_initial;
    std::vector<std::vector<int>> history;
    const double                  tolerance =
      1e-12 * std::max(g.linfty_norm(), std::numeric_limits<double>::min());

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
        const double residual = complementarity_residual(m, eta, v, g, c);
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
