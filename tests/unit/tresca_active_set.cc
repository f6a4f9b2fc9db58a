/* The primal-dual active set method for the nodal Tresca problem
   v = v_free - D eta, |eta_p| <= g_p, eta_p = g_p sign(v_p) where v_p != 0:
   it terminates with sets that repeat, its answer satisfies the friction
   conditions exactly and agrees with projected Gauss-Seidel on the dual
   problem min 1/2 eta^T D eta - v_free^T eta, |eta_p| <= g_p. Also Anderson
   acceleration on a linear fixed point. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <friction.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace Contact;

// A dense SPD compliance: the inverse of a 1D chain stiffness.
FullMatrix<double> make_delassus(const unsigned int n)
{
  LAPACKFullMatrix<double> stiffness(n, n);
  for (unsigned int i = 0; i < n; ++i)
    {
      stiffness(i, i) = 2.1;
      if (i > 0)
        stiffness(i, i - 1) = stiffness(i - 1, i) = -1;
    }
  stiffness.invert();
  FullMatrix<double> D(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      D(i, j) = stiffness(i, j);
  return D;
}

Vector<double> projected_gauss_seidel(const FullMatrix<double> &D,
                                      const Vector<double>     &v_free,
                                      const Vector<double>     &g)
{
  Vector<double> eta(v_free.size());
  for (unsigned int sweep = 0; sweep < 20000; ++sweep)
    for (unsigned int p = 0; p < eta.size(); ++p)
      {
        double r = v_free[p];
        for (unsigned int q = 0; q < eta.size(); ++q)
          if (q != p)
            r -= D(p, q) * eta[q];
        eta[p] = std::max(-g[p], std::min(g[p], r / D(p, p)));
      }
  return eta;
}

void check(const std::string    &name,
           const Vector<double> &v_free,
           const Vector<double> &g,
           const double          c_factor)
{
  const unsigned int       n = v_free.size();
  const FullMatrix<double> D = make_delassus(n);
  Vector<double>           c(n), eta(n), v(n);
  for (unsigned int p = 0; p < n; ++p)
    c[p] = c_factor / D(p, p);
  std::vector<NodeState> state;
  const TrescaResult     result =
    solve_tresca_2d(D, v_free, g, c, 100, eta, v, state);

  // The friction conditions, and v = v_free - D eta.
  double         violation = 0;
  Vector<double> residual(n);
  D.vmult(residual, eta);
  residual += v;
  residual -= v_free;
  violation = residual.linfty_norm();
  for (unsigned int p = 0; p < n; ++p)
    {
      violation = std::max(violation, std::abs(eta[p]) - g[p]);
      if (state[p] == NodeState::stick)
        violation = std::max(violation, std::abs(v[p]));
      else
        violation = std::max(violation, g[p] * std::abs(v[p]) - eta[p] * v[p]);
    }
  Vector<double> difference = projected_gauss_seidel(D, v_free, g);
  difference -= eta;

  std::string pattern;
  for (const NodeState s : state)
    pattern += (s == NodeState::stick         ? 'S' :
                s == NodeState::slip_positive ? '+' :
                                                '-');
  std::cout << name << " (c = " << c_factor << "/D_pp): converged "
            << result.converged << " in " << result.iterations
            << " iterations, cycles cured " << result.cycles_cured << ", state "
            << pattern
            << ", conditions hold: " << (violation < 1e-12 ? "yes" : "no")
            << ", agrees with projected Gauss-Seidel: "
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
  for (unsigned int p = 0; p < n; ++p)
    {
      ramp[p]        = -0.4 + 0.1 * p;
      g[p]           = 0.08;
      large_bound[p] = 100;
    }
  for (const double c : {0.05, 1., 20.})
    check("stick and slip both ways", ramp, g, c);
  check("all stick", ramp, large_bound, 0.05);
  check("no friction (g = 0)", ramp, zero_bound, 0.05);
  anderson(0);
  anderson(3);
}
