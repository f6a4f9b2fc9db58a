/* The law 'slip rate weakening': the paper's (6.1). */

#include <core/friction_laws.h>

#include <cmath>

namespace Contact
{
  namespace FrictionLaws
  {
    namespace
    {
      // @sect3{Slip rate weakening}

      // mu(s) = (a - b) exp(-alpha s) + b, the paper's (6.1): mu falls from
      // a at rest to b at fast slip. Its one-sided Lipschitz constant
      // (H(mu)(c)) is lambda = (a - b) alpha, the steepest descent, at s = 0.
      class SlipRateWeakening : public Interface
      {
      public:
        // 'a' is read by the constant law too, and declared there alike.
        static void declare_parameters(ParameterHandler &prm)
        {
          prm.declare_entry("a", "1", Patterns::Double(0), "mu(0) = a >= 0.");
          prm.declare_entry("b",
                            "0.1",
                            Patterns::Double(0),
                            "mu(inf) = b, b <= a.");
          prm.declare_entry("alpha",
                            "200",
                            Patterns::Double(0),
                            "Decay rate alpha >= 0 [s/m] of (6.1).");
        }

        // b > a would make mu grow with s, outside the paper's setting; with
        // alpha = 0 mu would be the constant a, which contradicts
        // mu(inf) = b unless a = b.
        explicit SlipRateWeakening(ParameterHandler &prm)
          : a(prm.get_double("a"))
          , b(prm.get_double("b"))
          , alpha(prm.get_double("alpha"))
        {
          check_entry(b <= a, "b", b, "0 <= b <= a");
          check_entry(alpha > 0 || a == b,
                      "alpha",
                      alpha,
                      "alpha > 0, or alpha = 0 together with a = b");
        }

        double coefficient(const double slip_rate) const override
        {
          return (a - b) * std::exp(-alpha * slip_rate) + b;
        }

        double bound_derivative(const double S,
                                const double slip_rate) const override
        {
          return -S * (a - b) * alpha * std::exp(-alpha * slip_rate);
        }

        // j(s) = S (b s + (a - b) (1 - exp(-alpha s)) / alpha) of (3.8).
        double potential(const double S, const double slip_rate) const override
        {
          return S * (b * slip_rate +
                      (a - b) * (1. - std::exp(-alpha * slip_rate)) / alpha);
        }

        bool is_frictionless() const override
        {
          return a == 0. && b == 0.;
        }

        // With a = b or alpha = 0 the law is the constant a.
        bool is_rate_independent() const override
        {
          return a == b || alpha == 0.;
        }

        double one_sided_lipschitz_constant() const override
        {
          return (a - b) * alpha;
        }

      private:
        const double a;
        const double b;
        const double alpha;
      };

      const LawRegistration<SlipRateWeakening>
        registration("slip rate weakening",
                     30,
                     "mu(s) = (a - b) exp(-alpha s) + b, the paper's (6.1)");
    } // namespace
  }   // namespace FrictionLaws
} // namespace Contact
