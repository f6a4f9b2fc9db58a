/* Anderson acceleration of a fixed point iteration (the convexification
   around Tresca problems). */

#include <deal.II/lac/lapack_full_matrix.h>

#include <core/friction.h>

namespace Contact
{
  // @sect3{Anderson acceleration}

  AndersonAcceleration::AndersonAcceleration(const unsigned int history_depth)
    : depth(history_depth)
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
    // Tikhonov regularisation of the least-squares problem: consecutive
    // residual differences can be nearly dependent.
    constexpr double regularisation = 1e-10;
    for (unsigned int i = 0; i < m; ++i)
      normal(i, i) += regularisation * trace;
    normal.set_property(LAPACKSupport::symmetric);
    normal.compute_cholesky_factorization();
    normal.solve(gamma);
    for (unsigned int i = 0; i < m; ++i)
      x.add(-gamma[i], image_differences[i]);
  }

} // namespace Contact
