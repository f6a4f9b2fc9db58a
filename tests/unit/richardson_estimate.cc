/* The Richardson extrapolation of 'Accuracy/Estimate error'
   (richardson_estimate, error_estimate.cc): exact for a quantity whose
   error is one power of h, whatever the power; and each way in which three
   runs can fail to be in the asymptotic range gets its warning and no
   extrapolation (the estimate is then the difference of the two finer
   runs). Every check of the estimate is made to fire here. */

#include <error_estimate.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
  void print(const std::string &label,
             const double       d_fine,
             const double       d_coarse,
             const bool         signed_differences)
  {
    const Contact::RichardsonEstimate e =
      Contact::richardson_estimate(d_fine, d_coarse, signed_differences);
    std::cout << label << ": order " << std::setprecision(4) << e.order
              << ", estimated error " << e.error
              << ", warning: " << (e.warning.empty() ? "none" : e.warning)
              << std::endl;
  }
} // namespace

int main()
{
  // Q_h = Q + C h^p on h, 2h, 4h: the estimate must be C h^p exactly.
  for (const double p : {2. / 3, 1., 2.})
    {
      const double Q = 0.3, C = -0.05, h = 1. / 64;
      const auto   value = [&](const double size) {
        return Q + C * std::pow(size, p);
      };
      const Contact::RichardsonEstimate e =
        Contact::richardson_estimate(value(h) - value(2 * h),
                                     value(2 * h) - value(4 * h),
                                     true);
      std::cout << "power law, p = " << std::setprecision(4) << p << ": order "
                << e.order << ", estimated / true error "
                << e.error / std::abs(C * std::pow(h, p))
                << ", warning: " << (e.warning.empty() ? "none" : e.warning)
                << std::endl;
    }
  print("norms of field differences, halving", 1e-3, 2e-3, false);
  print("differences that change sign", 1e-3, -2e-3, true);
  print("differences that grow", 2e-3, 1e-3, true);
  print("an implausibly high order", 1e-5, 1e-3, true);
  print("an implausibly low order", 1e-3, 1.2e-3, true);
  print("equal on the finer runs", 0., 1e-3, true);
  print("equal on all runs", 0., 0., true);
  print("undefined on a run", 1e-3, std::nan(""), true);
}
