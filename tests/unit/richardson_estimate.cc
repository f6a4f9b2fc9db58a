/* The Richardson extrapolation of 'Accuracy/Estimate error'
   (richardson_estimate, richardson.cc): exact for a quantity whose
   error is one power of h, whatever the power; conservative for error
   fields that change shape; and each way in which the runs can fail to be
   in the asymptotic range gives no estimate and says why. Every check of
   the estimate is made to fire here. */

#include <parts/studies/richardson.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  void print(const std::string         &label,
             const std::vector<double> &differences,
             const bool                 signed_differences)
  {
    const Contact::RichardsonEstimate e =
      Contact::richardson_estimate(differences, signed_differences);
    std::cout << label << ": orders";
    for (const double order : e.measured_orders)
      std::cout << " " << std::setprecision(4) << order;
    std::cout << ", order used " << e.order << ", estimated error " << e.error
              << ", status: " << (e.status.empty() ? "estimated" : e.status)
              << (e.reason.empty() ? "" : " (" + e.reason + ")") << std::endl;
  }
} // namespace

int main()
{
  // Q_h = Q + C h^p on h, 2h, 4h, 8h: the estimate must be C h^p exactly,
  // with three runs or four.
  for (const double p : {2. / 3, 1., 2.})
    for (const unsigned int n_runs : {3u, 4u})
      {
        const double Q = 0.3, C = -0.05, h = 1. / 64;
        const auto   value = [&](const double size) {
          return Q + C * std::pow(size, p);
        };
        std::vector<double> differences;
        for (unsigned int r = 0; r + 1 < n_runs; ++r)
          differences.push_back(value((1u << r) * h) - value((2u << r) * h));
        const Contact::RichardsonEstimate e =
          Contact::richardson_estimate(differences, true);
        std::cout << "power law, p = " << std::setprecision(4) << p << ", "
                  << n_runs << " runs: order " << e.order
                  << ", estimated / true error "
                  << e.error / std::abs(C * std::pow(h, p))
                  << ", status: " << (e.status.empty() ? "estimated" : e.status)
                  << std::endl;
      }
  // Error fields of three runs with norms E, r E, r^2 E whose consecutive
  // ones correlate with c (and the first and last with c^2), built from
  // orthonormal vectors a, b, d: where the errors change shape (c < 1) the
  // estimate from the norms of the differences is too large, never too
  // small.
  for (const double c : {1., 0.7, 0.3, 0.})
    {
      const double E = 1e-3, r = std::pow(2., 2. / 3), s = std::sqrt(1 - c * c);
      const std::array<std::array<double, 3>, 3> e = {
        {{E, 0, 0},
         {r * E * c, r * E * s, 0},
         {r * r * E * c * c, r * r * E * c * s, r * r * E * s}}};
      const auto distance = [&](const unsigned int i, const unsigned int j) {
        double sum = 0;
        for (unsigned int k = 0; k < 3; ++k)
          sum += (e[i][k] - e[j][k]) * (e[i][k] - e[j][k]);
        return std::sqrt(sum);
      };
      std::cout << "error fields correlated with c = " << c
                << ": estimated / true error " << std::setprecision(4)
                << Contact::richardson_estimate({distance(0, 1),
                                                 distance(1, 2)},
                                                false)
                       .error /
                     E
                << std::endl;
    }
  // Errors e_h + e_k of orders 2 in h and 1 in k (quadratic elements) on
  // runs with (h, k), (2h, 2k), (4h, 4k): d_fine = 3 e_h + e_k, d_coarse =
  // 12 e_h + 2 e_k. The two-order estimate must recover |e_h + e_k| for a
  // quantity and, with the cosine c of the parts, for a field; one order
  // (plain Richardson) does not where the parts are comparable.
  for (const double space_share : {0., 0.3, 0.7, 1.})
    for (const double c : {0., 0.5})
      {
        const double E_h = 1e-3 * space_share, E_k = 1e-3 - E_h;
        const double d_fine   = Contact::combined_error(3 * E_h, E_k, c);
        const double d_coarse = Contact::combined_error(12 * E_h, 2 * E_k, c);
        const double exact    = Contact::combined_error(E_h, E_k, c);
        std::cout
          << "space share " << space_share << ", cosine " << c
          << ": two orders / true error "
          << Contact::two_order_error_estimate(d_fine,
                                               d_coarse,
                                               {2, 1, c},
                                               true) /
               exact
          << ", for a quantity "
          << Contact::two_order_error_estimate(3 * E_h - E_k,
                                               12 * E_h - 2 * E_k,
                                               {2, 1, 1},
                                               false) /
               std::abs(E_h - E_k)
          << ", one order "
          << Contact::richardson_estimate({d_fine, d_coarse}, false).error /
               exact
          << std::endl;
      }
  std::cout << "orders 1 and 0.9 are not told apart: "
            << Contact::two_order_error_estimate(1e-3, 2e-3, {1, 0.9, 0}, true)
            << std::endl;
  print("norms of field differences, halving", {1e-3, 2e-3, 4e-3}, false);
  print("orders 0.6 and 1.0, within the drift",
        {1e-3, 1.516e-3, 3.031e-3},
        true);
  print("a high order not confirmed by the run with 8h",
        {1.695e-4, 4.316e-4, 3.588e-3},
        true);
  print("orders that drift apart", {1e-3, 1.5e-3, 4.5e-3}, true);
  print("differences that change sign", {1e-3, -2e-3, 4e-3}, true);
  print("norms never change sign", {1e-3, 2e-3, 4e-3}, false);
  print("differences that do not shrink", {1.56e-2, 1.68e-2, 1.69e-2}, true);
  print("differences that grow", {2e-3, 1e-3}, true);
  print("an implausibly high order", {1e-5, 1e-3}, true);
  print("an implausibly low order", {1e-3, 1.3e-3}, true);
  print("equal on the finer runs", {0., 1e-3, 2e-3}, true);
  print("equal on all runs", {0., 0., 0.}, true);
  print("undefined on a run", {1e-3, 2e-3, std::nan("")}, true);
}
