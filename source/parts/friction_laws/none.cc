/* The law 'none': a frictionless Gamma_3. */

#include <core/friction_laws.h>

namespace Contact
{
  namespace FrictionLaws
  {
    namespace
    {
      // @sect3{No friction}

      // mu = 0: Gamma_3 carries no tangential force, and the friction solver
      // leaves out the friction problem. The law has no entries; the friction
      // bound S is then not used.
      class None : public Interface
      {
      public:
        static void declare_parameters(ParameterHandler &)
        {}

        explicit None(ParameterHandler &)
        {}

        double coefficient(const double) const override
        {
          return 0.;
        }

        double bound_derivative(const double, const double) const override
        {
          return 0.;
        }

        double potential(const double, const double) const override
        {
          return 0.;
        }

        bool is_frictionless() const override
        {
          return true;
        }

        bool is_rate_independent() const override
        {
          return true;
        }

        double one_sided_lipschitz_constant() const override
        {
          return 0.;
        }
      };

      const LawRegistration<None>
        registration("none", 10, "frictionless Gamma_3");
    } // namespace
  }   // namespace FrictionLaws
} // namespace Contact
