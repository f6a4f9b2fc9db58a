/* A second weakening law, mu(s) = b + (a - b) / (1 + s/s0), defined and
   registered in this file alone: the path of a new friction law (the law,
   its registration, its test; doc/tutorial.md, "Adding a friction law").
   - its one registration statement adds it: the registered laws list it,
     the Selection 'Friction law' accepts it and its help text describes
     it, and the whole parameters parse with it;
   - through FrictionLaw: mu(0) = a and mu(s) -> b; the derivative of the
     bound S mu against centred differences of the bound, the potential j
     of (3.8) against the bound (j' = S mu); lambda bounds the steepest
     descent of mu; j is even in the slip velocity;
   - rate independence and frictionlessness come from the law's data
     (a = b, a = b = 0), not from defaults;
   - its own check names its entry ('Friction/s0');
   - a name that is not registered is refused with the entry
     'Friction/Friction law' and the allowed names; a law registered twice,
     or one that declares a shared entry differently, is refused. */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <core/friction_laws.h>
#include <core/parameters.h>
#include <core/friction.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace Contact;

namespace
{
  // @sect3{The law}

  // mu(s) = b + (a - b) / (1 + s/s0): like (6.1) it falls from a at rest to
  // b, but algebraically, halfway at s = s0. Its steepest descent is at
  // s = 0: lambda = (a - b) / s0.
  class RationalWeakening : public FrictionLaws::Interface
  {
  public:
    // 'a' and 'b' as the built-in laws declare them (the registration
    // refuses a different declaration); 's0' is new.
    static void declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("a", "1", Patterns::Double(0), "mu(0) = a >= 0.");
      prm.declare_entry("b",
                        "0.1",
                        Patterns::Double(0),
                        "mu(inf) = b, b <= a.");
      prm.declare_entry("s0",
                        "0.005",
                        Patterns::Double(0),
                        "s0 > 0 [m/s]: the slip rate at which mu is halfway "
                        "from a to b.");
    }

    explicit RationalWeakening(ParameterHandler &prm)
      : a(prm.get_double("a"))
      , b(prm.get_double("b"))
      , s0(prm.get_double("s0"))
    {
      FrictionLaws::check_entry(b <= a, "b", b, "0 <= b <= a");
      FrictionLaws::check_entry(s0 > 0, "s0", s0, "s0 > 0");
    }

    double coefficient(const double slip_rate) const override
    {
      return b + (a - b) / (1. + slip_rate / s0);
    }

    double bound_derivative(const double S,
                            const double slip_rate) const override
    {
      const double q = 1. + slip_rate / s0;
      return -S * (a - b) / (s0 * q * q);
    }

    // j(s) = S (b s + (a - b) s0 log(1 + s/s0)).
    double potential(const double S, const double slip_rate) const override
    {
      return S * (b * slip_rate + (a - b) * s0 * std::log1p(slip_rate / s0));
    }

    bool is_frictionless() const override
    {
      return a == 0. && b == 0.;
    }

    bool is_rate_independent() const override
    {
      return a == b;
    }

    double one_sided_lipschitz_constant() const override
    {
      return (a - b) / s0;
    }

  private:
    const double a;
    const double b;
    const double s0;
  };

  // A law that declares 'a' with another default than the built-in laws.
  class OtherDefault : public RationalWeakening
  {
  public:
    static void declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("a", "2", Patterns::Double(0), "mu(0) = a >= 0.");
    }

    using RationalWeakening::RationalWeakening;
  };


  // @sect3{Registration}

  // The one statement of a law's file: fourth in 'Friction law'.
  const FrictionLaws::LawRegistration<RationalWeakening>
    registration("rational weakening", 40, "mu(s) = b + (a - b) / (1 + s/s0)");


  // @sect3{Helpers}

  std::string message_of(const dealii::ExceptionBase &exc)
  {
    std::ostringstream message;
    exc.print_info(message);
    std::string text = message.str();
    text.erase(0, text.find_first_not_of(' '));
    while (!text.empty() && text.back() == '\n')
      text.pop_back();
    return text;
  }

  // The default parameters with the given entries of the subsection
  // Friction, through the parser of the whole parameters.
  Parameters
  parse(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.enter_subsection(FrictionLaws::subsection);
    for (const auto &[entry, value] : entries)
      prm.set(entry, value);
    prm.leave_subsection();
    Parameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }

  void print_law(const std::string &name, const FrictionLaw &law)
  {
    std::cout << name << ": frictionless " << law.is_frictionless()
              << ", rate independent " << law.is_rate_independent()
              << ", lambda " << law.one_sided_lipschitz_constant() << std::endl;
    double derivative_error = 0, potential_error = 0, steepest_descent = 0;
    for (const double s : {0., 0.001, 0.005, 0.01, 0.1, 1., 1e6})
      {
        std::cout << "  mu(" << s << ") = " << law.coefficient(s)
                  << "  bound = " << law.bound(s) << std::endl;
        if (s > 0)
          {
            // Centred differences with a step relative to s: truncation
            // and round-off both stay below 1e-7 from s = 1e-3 to 1e6.
            const double h     = 1e-5 * s;
            const double scale = std::max(1., law.bound(s));
            derivative_error =
              std::max(derivative_error,
                       std::abs((law.bound(s + h) - law.bound(s - h)) /
                                  (2 * h) -
                                law.bound_derivative(s)) /
                         scale);
            potential_error =
              std::max(potential_error,
                       std::abs((law.potential(s + h) - law.potential(s - h)) /
                                  (2 * h) -
                                law.bound(s)) /
                         scale);
          }
      }
    for (double s = 0; s < 0.05; s += 1e-4)
      steepest_descent =
        std::max(steepest_descent,
                 -(law.coefficient(s + 1e-6) - law.coefficient(s)) / 1e-6);
    std::cout << "  bound' by differences: "
              << (derivative_error < 1e-6 ? "yes" : "no")
              << ", j' = S mu: " << (potential_error < 1e-6 ? "yes" : "no")
              << ", steepest descent of mu within lambda: "
              << (steepest_descent <=
                      law.one_sided_lipschitz_constant() * (1 + 1e-6) ?
                    "yes" :
                    "no")
              << ", j(-0.01) = j(0.01): "
              << (law.potential(-0.01) == law.potential(0.01) ? "yes" : "no")
              << std::endl;
  }
} // namespace


int main(int argc, char *argv[])
{
  // Parameters::parse_parameters() asks MPI for the number of processes.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(8);

  std::cout << "registered laws:";
  for (const auto &law : FrictionLaws::LawRegistry::parts())
    std::cout << " '" << law.name << "'";
  std::cout << std::endl;

  // The subsection Friction as --print-parameters would print it with the
  // law compiled in.
  {
    ParameterHandler prm;
    FrictionParameters::declare_parameters(prm);
    prm.print_parameters(std::cout, ParameterHandler::PRM);
  }

  // @sect3{The law through the parameters}

  print_law("rational weakening a = 1, b = 0.1, s0 = 0.005, S = 2",
            FrictionLaw(parse({{"Friction law", "rational weakening"},
                               {"Friction bound S", "2"},
                               {"a", "1"},
                               {"b", "0.1"},
                               {"s0", "0.005"}})
                          .friction));
  print_law("rational weakening a = b = 0.5, S = 1",
            FrictionLaw(parse({{"Friction law", "rational weakening"},
                               {"Friction bound S", "1"},
                               {"a", "0.5"},
                               {"b", "0.5"}})
                          .friction));
  print_law("rational weakening a = b = 0",
            FrictionLaw(parse({{"Friction law", "rational weakening"},
                               {"a", "0"},
                               {"b", "0"}})
                          .friction));

  // @sect3{What is refused}

  try
    {
      parse({{"Friction law", "rational weakening"}, {"s0", "0"}});
      std::cout << "s0 = 0: accepted" << std::endl;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      std::cout << "s0 = 0: " << message_of(exc) << std::endl;
    }

  try
    {
      ParameterHandler prm;
      FrictionParameters::declare_parameters(prm);
      prm.enter_subsection(FrictionLaws::subsection);
      FrictionLaws::LawRegistry::create(
        FrictionLaws::entry_path(FrictionLaws::law_entry), "coulomb", prm);
      std::cout << "'coulomb': accepted" << std::endl;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      std::cout << "'coulomb': " << message_of(exc) << std::endl;
    }

  try
    {
      const FrictionLaws::LawRegistration<RationalWeakening> twice("constant",
                                                                   50,
                                                                   "mu = a");
      std::cout << "'constant' registered twice: accepted" << std::endl;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      std::cout << "'constant' registered twice: " << message_of(exc)
                << std::endl;
    }

  try
    {
      const FrictionLaws::LawRegistration<OtherDefault> other("other default",
                                                              60,
                                                              "mu = a");
      std::cout << "'a' declared with another default: accepted" << std::endl;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      std::cout << "'a' declared with another default: " << message_of(exc)
                << std::endl;
    }

  std::cout << "registered laws after the refusals:";
  for (const auto &law : FrictionLaws::LawRegistry::parts())
    std::cout << " '" << law.name << "'";
  std::cout << std::endl;
}
