/* The primal-dual active set method for the nodal Tresca problem
   v = v_free - D eta, |eta_p| <= g_p, eta_p = g_p v_p / |v_p| where
   v_p != 0, with one (2D) and two (3D) tangential components per node: it
   terminates, its answer satisfies the friction conditions to round-off and
   agrees with projected gradient steps on the dual problem
   min 1/2 eta^T D eta - v_free^T eta, |eta_p| <= g_p. Also Anderson
   acceleration on a linear fixed point. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <core/delassus_operator.h>
#include <core/friction.h>

#include "make_delassus.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace Contact;

// The dual problem min 1/2 eta^T D eta - v_free^T eta, |eta_p| <= g_p, by
// projected gradient steps: slow, but obviously right.
Vector<double> projected_gradient(const FullMatrix<double> &D,
                                  const unsigned int        m,
                                  const Vector<double>     &v_free,
                                  const Vector<double>     &g)
{
  Vector<double> eta(v_free.size()), gradient(v_free.size());
  const double   step = 1. / D.frobenius_norm();
  for (unsigned int iteration = 0; iteration < 100000; ++iteration)
    {
      D.vmult(gradient, eta);
      gradient -= v_free;
      eta.add(-step, gradient);
      for (unsigned int p = 0; p < g.size(); ++p)
        {
          double norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            norm += eta[p * m + i] * eta[p * m + i];
          norm = std::sqrt(norm);
          if (norm > g[p])
            for (unsigned int i = 0; i < m; ++i)
              eta[p * m + i] *= g[p] / norm;
        }
    }
  return eta;
}

void check(const std::string    &name,
           const unsigned int    m,
           const Vector<double> &v_free,
           const Vector<double> &g,
           const double          c_factor)
{
  const unsigned int       n = g.size();
  const FullMatrix<double> D = make_delassus(n, m);
  Vector<double>           c(n), eta(n * m), v(n * m);
  for (unsigned int p = 0; p < n; ++p)
    c[p] = c_factor / D(p * m, p * m);
  std::vector<NodeState> state;
  const TrescaResult     result =
    solve_tresca(DelassusOperator(D, m), v_free, g, c, 100, eta, v, state);

  // The friction conditions, and v = v_free - D eta.
  Vector<double> residual(n * m);
  D.vmult(residual, eta);
  residual += v;
  residual -= v_free;
  double      violation = residual.linfty_norm();
  std::string pattern;
  for (unsigned int p = 0; p < n; ++p)
    {
      double eta_norm = 0, v_norm = 0, eta_dot_v = 0;
      for (unsigned int i = 0; i < m; ++i)
        {
          eta_norm += eta[p * m + i] * eta[p * m + i];
          v_norm += v[p * m + i] * v[p * m + i];
          eta_dot_v += eta[p * m + i] * v[p * m + i];
        }
      eta_norm  = std::sqrt(eta_norm);
      v_norm    = std::sqrt(v_norm);
      violation = std::max(violation, eta_norm - g[p]);
      if (state[p] == NodeState::stick)
        violation = std::max(violation, v_norm);
      else
        violation =
          std::max({violation, g[p] * v_norm - eta_dot_v, g[p] - eta_norm});
      pattern += (state[p] == NodeState::stick ? 'S' :
                  m == 2                       ? 'L' :
                  eta[p] > 0                   ? '+' :
                  eta[p] < 0                   ? '-' :
                                                 '0');
    }
  Vector<double> difference = projected_gradient(D, m, v_free, g);
  difference -= eta;

  std::cout << name << " (m = " << m << ", c = " << c_factor
            << "/D_pp): converged " << result.converged << " in "
            << result.iterations << " iterations, cycles cured "
            << result.cycles_cured << ", state " << pattern
            << ", conditions hold: " << (violation < 1e-12 ? "yes" : "no")
            << ", agrees with projected gradient: "
            << (difference.linfty_norm() < 1e-9 ? "yes" : "no") << std::endl;
}

void anderson(const unsigned int depth)
{
  // x = A x + b with A = diag(0.95 ... 0.5): plain iteration is slow.
  const unsigned int   n = 10;
  Vector<double>       x(n), image(n);
  AndersonAcceleration acceleration(depth);
  unsigned int         iterations = 0;
  for (; iterations < 2000; ++iterations)
    {
      for (unsigned int i = 0; i < n; ++i)
        image[i] = (0.95 - 0.05 * i) * x[i] + 1.;
      Vector<double> change(image);
      change -= x;
      if (change.linfty_norm() < 1e-10)
        break;
      acceleration.next_iterate(x, image);
    }
  std::cout << "Anderson depth " << depth << ": " << iterations
            << " iterations, x_0 = " << x[0] << std::endl;
}

int main()
{
  std::cout << std::setprecision(6);
  const unsigned int n = 12;
  Vector<double>     ramp(n), g(n), zero_bound(n), large_bound(n);
  Vector<double>     turning(2 * n);
  for (unsigned int p = 0; p < n; ++p)
    {
      ramp[p]        = -0.4 + 0.1 * p;
      g[p]           = 0.08;
      large_bound[p] = 100;
      // In the plane: a slip velocity whose size grows and whose direction
      // turns by 30 degrees from node to node.
      const double angle = p * M_PI / 6;
      turning[2 * p]     = (0.1 * p - 0.3) * std::cos(angle);
      turning[2 * p + 1] = (0.1 * p - 0.3) * std::sin(angle);
    }
  for (const double c : {0.05, 1., 20.})
    check("stick and slip both ways", 1, ramp, g, c);
  check("all stick", 1, ramp, large_bound, 0.05);
  check("no friction (g = 0)", 1, ramp, zero_bound, 0.05);
  Vector<double> g_plane(n);
  g_plane = 0.3;
  for (const double c : {0.05, 1., 20.})
    check("stick and slip in turning directions", 2, turning, g_plane, c);
  check("all stick", 2, turning, large_bound, 0.05);
  check("no friction (g = 0)", 2, turning, zero_bound, 0.05);
  anderson(0);
  anderson(3);
}
