/* The friction law (6.1), its bound, its potential j of (3.8) and its
   one-sided Lipschitz constant; the constant and the frictionless law. */

#include <core/friction.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace Contact;

// The law as a .prm file gives it: through the declaration and the parser
// of the subsection Friction.
FrictionParameters make_parameters(const std::string &law,
                                   const double       S,
                                   const double       a,
                                   const double       b,
                                   const double       alpha)
{
  ParameterHandler prm;
  FrictionParameters::declare_parameters(prm);
  prm.enter_subsection(FrictionLaws::subsection);
  prm.set("Friction law", law);
  prm.set("Friction bound S", S);
  prm.set("a", a);
  prm.set("b", b);
  prm.set("alpha", alpha);
  prm.leave_subsection();
  FrictionParameters parameters;
  parameters.parse_parameters(prm);
  return parameters;
}

void print_law(const std::string &name, const FrictionLaw &law)
{
  std::cout << name << ": frictionless " << law.is_frictionless()
            << ", rate independent " << law.is_rate_independent() << ", lambda "
            << law.one_sided_lipschitz_constant() << std::endl;
  double largest_derivative_error = 0, steepest_descent = 0;
  for (const double s : {0., 0.001, 0.005, 0.01, 0.1, 1.})
    {
      std::cout << "  mu(" << s << ") = " << law.coefficient(s)
                << "  bound = " << law.bound(s) << std::endl;
      // j'(s) = S mu(s) for s > 0, by a centred difference.
      if (s > 0)
        {
          const double h = 1e-7;
          const double derivative =
            (law.potential(s + h) - law.potential(s - h)) / (2 * h);
          largest_derivative_error =
            std::max(largest_derivative_error,
                     std::abs(derivative - law.bound(s)) /
                       std::max(1., law.bound(s)));
        }
    }
  // H(mu)(c): mu(s1) - mu(s2) >= -lambda (s1 - s2) for s1 > s2 >= 0.
  for (double s = 0; s < 0.05; s += 1e-4)
    steepest_descent =
      std::max(steepest_descent,
               -(law.coefficient(s + 1e-6) - law.coefficient(s)) / 1e-6);
  std::cout << "  j' = S mu: "
            << (largest_derivative_error < 1e-6 ? "yes" : "no")
            << ", steepest descent of mu within lambda: "
            << (steepest_descent <=
                    law.one_sided_lipschitz_constant() * (1 + 1e-6) ?
                  "yes" :
                  "no")
            << ", j(-0.01) = j(0.01): "
            << (law.potential(-0.01) == law.potential(0.01) ? "yes" : "no")
            << std::endl;
}

int main()
{
  std::cout << std::setprecision(8);
  print_law("slip rate weakening a = 1, b = 0.1, alpha = 200, S = 2",
            FrictionLaw(
              make_parameters("slip rate weakening", 2, 1, 0.1, 200)));
  print_law("constant a = 0.4, S = 3",
            FrictionLaw(make_parameters("constant", 3, 0.4, 0.1, 200)));
  print_law("slip rate weakening with a = b = 0.5, S = 1",
            FrictionLaw(
              make_parameters("slip rate weakening", 1, 0.5, 0.5, 200)));
  print_law("none", FrictionLaw(make_parameters("none", 3, 1, 0.1, 200)));
  print_law("slip rate weakening with S = 0",
            FrictionLaw(
              make_parameters("slip rate weakening", 0, 1, 0.1, 200)));
}
