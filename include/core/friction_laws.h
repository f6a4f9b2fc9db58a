/**
 * The friction laws mu(s) of the slip rate s = |w_tau| in the slip threshold
 * mu(s) S of (3.6), a kind of part of the program (base/parts.h).
 *
 * A law is one file in source/base/friction_laws/: a class derived from
 * FrictionLaws::Interface that declares, reads and checks its own entries of
 * the subsection Friction, and the one statement that registers it
 * (LawRegistration). The Selection 'Friction law', its help text and the
 * parser are made of the registered laws, so that they cannot differ, and a
 * name that is not registered is an error that names the entry.
 * doc/tutorial.md ("Adding a friction law"): one file and one test.
 *
 * The laws live in base, not in gamma3, because the parameters are parsed
 * here and a layer uses only the layers below it; the friction solver sees
 * a law through FrictionLaw (core/friction.h), which multiplies by S.
 */
#ifndef contact_friction_laws_h
#define contact_friction_laws_h

#include <deal.II/base/parameter_handler.h>

#include <base/parts.h>

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


    /** The entry whose values are the names of the laws. */
    inline const std::string law_entry = "Friction law";

    /** The kind of the friction laws (base/parts.h): a law made from the
     *  subsection Friction (entered by the caller), its entries read and
     *  checked. The Selection 'Friction law', its help text and the parser
     *  are made of the registered laws, by rank. */
    using LawRegistry = PartRegistry<const Interface, ParameterHandler &>;

    /**
     * Refuses the law `name` if it declares with `declare` an entry that a
     * registered law declares with another default, pattern or help text.
     * An entry that several laws read ('a', 'b') is declared by each of
     * them; ParameterHandler keeps the last declaration without a word, so
     * that a law declaring it differently would change the other laws'
     * entry.
     */
    void check_declarations_agree(
      const std::string                             &name,
      const std::function<void(ParameterHandler &)> &declare);

    /**
     * The registration of a law, one statement in its file:
     *   const LawRegistration<Class> registration(name, rank, description);
     * Class derives from Interface, with a static declare_parameters(prm)
     * that declares its entries of the subsection Friction and a
     * constructor from prm that reads and checks them. `rank` orders the
     * Selection 'Friction law', `description` is what its help text says
     * of the law (e.g. "mu = a"). Its entries follow 'Friction bound S'.
     */
    template <class Law>
    struct LawRegistration
    {
      LawRegistration(const std::string &name,
                      const unsigned int rank,
                      const std::string &description)
      {
        check_declarations_agree(name, &Law::declare_parameters);
        LawRegistry::add(
          {name,
           description,
           rank,
           {subsection, "Friction bound S", "", &Law::declare_parameters, {}},
           [](ParameterHandler &prm) -> std::unique_ptr<const Interface> {
             return std::make_unique<const Law>(prm);
           }});
      }
    };

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


  /** The messages name a part of this kind a friction law. */
  template <>
  inline std::string
  PartRegistry<const FrictionLaws::Interface, ParameterHandler &>::noun()
  {
    return "friction law";
  }
} // namespace Contact

#endif
