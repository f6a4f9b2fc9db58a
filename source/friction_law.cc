/* The friction law (6.1) and the nodal Tresca solver on Gamma_3. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <friction.h>

#include <algorithm>
#include <cmath>

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
    // The stick/slip state that the complementarity function
    // eta_p = P_[-g_p, g_p](eta_p + c_p v_p) predicts. A node with g_p = 0
    // slips with eta_p = 0 whatever its sign, so it is reported as
    // slip_positive to keep the state deterministic.
    std::vector<NodeState> predict_state(const Vector<double> &eta,
                                         const Vector<double> &v,
                                         const Vector<double> &g,
                                         const Vector<double> &c)
    {
      std::vector<NodeState> state(eta.size());
      for (unsigned int p = 0; p < eta.size(); ++p)
        {
          const double z = eta[p] + c[p] * v[p];
          if (g[p] == 0.)
            state[p] = NodeState::slip_positive;
          else if (std::abs(z) <= g[p])
            state[p] = NodeState::stick;
          else
            state[p] =
              (z > 0 ? NodeState::slip_positive : NodeState::slip_negative);
        }
      return state;
    }

    // Given the state, eta is known on the slip set and v = 0 on the stick
    // set, so eta_S solves D_SS eta_S = v_free_S - D_SL eta_L.
    void solve_for_state(const FullMatrix<double>     &D,
                         const Vector<double>         &v_free,
                         const Vector<double>         &g,
                         const std::vector<NodeState> &state,
                         Vector<double>               &eta,
                         Vector<double>               &v)
    {
      const unsigned int        n = v_free.size();
      std::vector<unsigned int> stick;
      for (unsigned int p = 0; p < n; ++p)
        if (state[p] == NodeState::stick)
          stick.push_back(p);
        else
          eta[p] = static_cast<int>(state[p]) * g[p];

      if (!stick.empty())
        {
          const unsigned int       m = stick.size();
          LAPACKFullMatrix<double> D_SS(m, m);
          Vector<double>           rhs(m);
          for (unsigned int i = 0; i < m; ++i)
            {
              rhs[i] = v_free[stick[i]];
              for (unsigned int q = 0; q < n; ++q)
                if (state[q] != NodeState::stick)
                  rhs[i] -= D(stick[i], q) * eta[q];
              for (unsigned int j = 0; j < m; ++j)
                D_SS(i, j) = D(stick[i], stick[j]);
            }
          D_SS.set_property(LAPACKSupport::symmetric);
          D_SS.compute_cholesky_factorization();
          D_SS.solve(rhs);
          for (unsigned int i = 0; i < m; ++i)
            eta[stick[i]] = rhs[i];
        }

      D.vmult(v, eta);
      v.sadd(-1., 1., v_free);
      for (const unsigned int p : stick)
        v[p] = 0.;
    }
  } // namespace


  TrescaResult solve_tresca_2d(const FullMatrix<double> &D,
                               const Vector<double>     &v_free,
                               const Vector<double>     &g,
                               const Vector<double>     &c_initial,
                               const unsigned int        max_iterations,
                               Vector<double>           &eta,
                               Vector<double>           &v,
                               std::vector<NodeState>   &state)
  {
    AssertDimension(D.m(), v_free.size());
    AssertDimension(eta.size(), v_free.size());
    TrescaResult                        result;
    Vector<double>                      c = c_initial;
    std::vector<std::vector<NodeState>> history;

    D.vmult(v, eta);
    v.sadd(-1., 1., v_free);
    state = predict_state(eta, v, g, c);

    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        solve_for_state(D, v_free, g, state, eta, v);
        history.push_back(state);

        state = predict_state(eta, v, g, c);
        if (state == history.back())
          {
            result.converged = true;
            break;
          }
        if (std::find(history.begin(), history.end(), state) != history.end())
          {
            c *= 0.5;
            ++result.cycles_cured;
            history.clear();
          }
      }
    return result;
  }
} // namespace Contact
