/* The dense SPD compliance of the unit tests of the friction solvers. */
#ifndef contact_tests_make_delassus_h
#define contact_tests_make_delassus_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

using namespace dealii;

// A dense SPD compliance: the inverse of a 1D chain stiffness, and with two
// tangential components per node its Kronecker product with an anisotropic
// 2 x 2 coupling, so that the slip direction is not that of v_free.
inline FullMatrix<double> make_delassus(const unsigned int n,
                                        const unsigned int m)
{
  LAPACKFullMatrix<double> stiffness(n, n);
  for (unsigned int i = 0; i < n; ++i)
    {
      stiffness(i, i) = 2.1;
      if (i > 0)
        stiffness(i, i - 1) = stiffness(i - 1, i) = -1;
    }
  stiffness.invert();
  // Exactly symmetric, as DelassusOperator requires (the inverse is so up
  // to round-off).
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < i; ++j)
      stiffness(i, j) = stiffness(j, i);
  const double       coupling[2][2] = {{1., 0.4}, {0.4, 0.8}};
  FullMatrix<double> D(n * m, n * m);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          D(i * m + a, j * m + b) =
            stiffness(i, j) * (m == 1 ? 1. : coupling[a][b]);
  return D;
}

#endif
