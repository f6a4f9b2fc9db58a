/**
 * The friction laws mu(s) of the slip rate s = |w_tau| in the slip threshold
 * mu(s) S of (3.6), and the one registry that knows them.
 *
 * A law is one file in source/base/friction_laws/: a class derived from
 * FrictionLaws::Interface that declares, reads and checks its own entries of
 * the subsection Friction, and a function that returns its Registration. The
 * registry (source/base/friction_laws/registry.cc) lists these functions in
 * the order in which the Selection 'Friction law' names the laws; the
 * Selection, its help text and the parser are made from that one list, so
 * that they cannot differ, and a name that is not registered is an error
 * that names the entry. doc/tutorial.md ("Adding a friction law") lists the
 * files to touch.
 *
 * The laws live in base, not in gamma3, because the parameters are parsed
 * here and a layer uses only the layers below it; the friction solver sees
 * a law through FrictionLaw (gamma3/friction.h), which multiplies by S.
 */
#ifndef contact_friction_laws_h
#define contact_friction_laws_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  namespace FrictionLaws
  {
    /** The subsection of the .prm file that holds 'Friction law', the
     *  friction bound S and the entries of every law. */
    inline const std::string subsection = "Friction";

    /**
     * A friction law: the coefficient mu(s) >= 0 of the slip rate s >= 0 and
     * what the friction solver needs of it. The friction solver evaluates
     * these functions per node of Gamma_3 and per iteration: they must not
     * allocate. Every property is computed from the law's own data; there
     * are no defaults to inherit, so a law that forgets one does not compile.
     */
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /** mu(s), s >= 0. */
      virtual double coefficient(const double slip_rate) const = 0;

      /**
       * d/ds S mu(s), s >= 0: the tangent of the bound in the Newton method.
       * S is an argument rather than a factor applied by the caller so that
       * the law fixes the order of its products (floating point products
       * are not associative, and the results of a run must not depend on
       * how the law is called). Only asked of a law that is not rate
       * independent; FrictionLaw uses 0 otherwise.
       */
      virtual double bound_derivative(const double S,
                                      const double slip_rate) const = 0;

      /**
       * j(s) = S int_0^s mu(r) dr of (3.8), s >= 0, for the energy of a
       * step. Only asked of a law that is not rate independent; FrictionLaw
       * uses S mu(0) s otherwise.
       */
      virtual double potential(const double S,
                               const double slip_rate) const = 0;

      /** mu(s) = 0 for every s: no friction term at all. */
      virtual bool is_frictionless() const = 0;

      /** mu does not depend on s: one Tresca problem per step suffices, and
       *  the convexification and the Newton method are skipped. */
      virtual bool is_rate_independent() const = 0;

      /** lambda of H(mu)(c): mu(s1) - mu(s2) >= -lambda (s1 - s2) for all
       *  s1 > s2 >= 0, the rate at which mu may decrease. */
      virtual double one_sided_lipschitz_constant() const = 0;
    };


    /** A law as the registry holds it. */
    struct Registration
    {
      /** Its value of 'Friction law'. */
      std::string name;
      /** What 'Friction law' says about it in its help text,
       *  e.g. "mu = a". */
      std::string description;
      /** Declares its entries in the subsection Friction (entered by the
       *  caller). An entry that several laws read ('a', 'b') is declared by
       *  each of them, with the same default, pattern and help text
       *  (register_law() refuses a law that declares it differently). */
      std::function<void(ParameterHandler &prm)> declare_parameters;
      /** Reads and checks its entries there and returns the law. */
      std::function<std::unique_ptr<const Interface>(ParameterHandler &prm)>
        create;
    };

    /** The Registration of a law class Law with a static
     *  declare_parameters(prm) and a constructor from prm that reads and
     *  checks its entries. */
    template <class Law>
    Registration registration(const std::string &name,
                              const std::string &description)
    {
      return {name,
              description,
              &Law::declare_parameters,
              [](ParameterHandler &prm) -> std::unique_ptr<const Interface> {
                return std::make_unique<const Law>(prm);
              }};
    }

    /**
     * Adds a law after the built-in ones, e.g. from a test, before the
     * parameters are declared. A name that is empty, contains '|' or ','
     * (the separators of a Selection and of its list) or is already
     * registered is refused with an error.
     */
    void register_law(const Registration &law);

    /** The registered names, in the order of the Selection. */
    std::vector<std::string> names();

    /** Declares 'Friction law': the Selection of the registered names, its
     *  default and its help text made of the laws' descriptions. */
    void declare_law_entry(ParameterHandler &prm);

    /** Declares the entries of every registered law. */
    void declare_parameters(ParameterHandler &prm);

    /** The law registered as `name`, its entries read and checked in the
     *  subsection Friction (entered by the caller). A name that is not
     *  registered is an error that names the entry and the allowed names. */
    std::unique_ptr<const Interface> create(const std::string &name,
                                            ParameterHandler  &prm);

    /** "Friction/<entry>": how a message names an entry of a law. */
    std::string entry_path(const std::string &entry);

    /** The check of one entry of a law: the words of check_entry() in
     *  parameters.cc, i.e. the entry, the value read and what is
     *  allowed. */
    void check_entry(const bool         condition,
                     const std::string &entry,
                     const double       value,
                     const std::string &allowed);
  } // namespace FrictionLaws
} // namespace Contact

#endif
