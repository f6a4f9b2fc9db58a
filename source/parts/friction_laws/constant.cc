/* The law 'constant': mu = a, Tresca friction with the bound a S. */

#include <core/friction_laws.h>

namespace Contact
{
  namespace FrictionLaws
  {
    namespace
    {
      // @sect3{A constant coefficient}

      // mu(s) = a for every slip rate: each step is one Tresca problem with
      // the bound a S of (3.6).
      class Constant : public Interface
      {
      public:
        // The entry 'a' is read by the slip rate weakening law too, and
        // declared there with the same default, pattern and help text.
        static void declare_parameters(ParameterHandler &prm)
        {
          prm.declare_entry("a", "1", Patterns::Double(0), "mu(0) = a >= 0.");
        }

        explicit Constant(ParameterHandler &prm)
          : a(prm.get_double("a"))
        {}

        double coefficient(const double) const override
        {
          return a;
        }

        double bound_derivative(const double, const double) const override
        {
          return 0.;
        }

        double potential(const double S, const double slip_rate) const override
        {
          return S * a * slip_rate;
        }

        bool is_frictionless() const override
        {
          return a == 0.;
        }

        bool is_rate_independent() const override
        {
          return true;
        }

        double one_sided_lipschitz_constant() const override
        {
          return 0.;
        }

      private:
        const double a;
      };

      const LawRegistration<Constant> registration("constant", 20, "mu = a");
    } // namespace
  }   // namespace FrictionLaws
} // namespace Contact
