/**
 * The one way a part of the program registers itself (ASPECT's plugins).
 *
 * A part is one implementation of a kind: a friction law, a geometry, a
 * postprocessor, a study, a method of a solver. Its file registers it once,
 * while the shared library is loaded, with a static
 *   const bool registered = PartRegistry<Kind>::add({name, description,
 *                                                   rank, entries, create});
 * and nothing else in the program names it:
 *  - the Selection of the entry that chooses a part of its kind, the help
 *    text of that entry and the parser are made of the registered names
 *    (selection(), help_text(), create()), in the order of the ranks;
 *  - its entries (PartEntries) are declared, parsed and checked by the part
 *    itself; Parameters keeps the value that its parse() returns under the
 *    part's name (Parameters::part<Value>(name)).
 *
 * A kind is the product's type and the arguments of its factory, e.g.
 * PartRegistry<FrictionLaws::Interface, ParameterHandler &>; a kind that
 * exists in every dimension is registered once per compiled dimension.
 */
#ifndef contact_parts_h
#define contact_parts_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <any>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  struct Parameters;

  /**
   * The entries of one part. declare() declares them in `subsection` (a
   * path "Output" or "Geometry", or "" for the top level, entered by the
   * caller) right after the entry or subsection `after` of it: their place
   * in the printed parameters, which stays where it was when parts are
   * added; another part may place its entries after `last`, the last entry
   * declared. parse(), if given, reads them in `subsection` once the
   * subsections before it are parsed, checks them (against the other
   * entries of `parameters` where needed, check_entry() naming the entry)
   * and returns the part's value. check(), if given, checks them against
   * entries parsed after them (e.g. Output's), once every entry is parsed.
   * A resumed run may change the entries `may_change_on_resume` (paths
   * "Subsection/Entry"): they do not define the discrete problem, and the
   * checkpoint does not compare them.
   */
  struct PartEntries
  {
    std::string                                                     subsection;
    std::string                                                     after;
    std::string                                                     last;
    std::function<void(ParameterHandler &)>                         declare;
    std::function<std::any(ParameterHandler &, const Parameters &)> parse;
    std::function<void(const Parameters &)>                         check{};
    std::vector<std::string> may_change_on_resume{};
  };

  namespace Parts
  {
    /** Adds the entries of the part `part` of rank `rank`, once: a part
     *  registered for each dimension declares its entries once. */
    void add_entries(const std::string &part,
                     const unsigned int rank,
                     const PartEntries &entries);

    /** Declares the entries of every part that follow the entry or
     *  subsection `after` of `subsection` (entered by the caller), in the
     *  order of their ranks, and after each of them those that follow
     *  it. */
    void declare_entries_after(ParameterHandler  &prm,
                               const std::string &subsection,
                               const std::string &after);

    /** Parses the entries of every part in `subsection` (entered by the
     *  caller), in the order of registration: part name -> value. */
    std::map<std::string, std::any> parse_entries(ParameterHandler  &prm,
                                                  const std::string &subsection,
                                                  const Parameters &parameters);

    /** Calls the check() of every part, in the order of registration,
     *  once all entries are parsed. */
    void check_entries(const Parameters &parameters);

    /** Whether a part says that a resumed run may change the entry
     *  `entry` ("Subsection/Entry"). */
    bool may_change_on_resume(const std::string &entry);

    /** Refuses a part name that a Selection cannot hold: empty, or with
     *  '|' or ',' (its separators). */
    void check_name(const std::string &name);

    /**
     * @name The parts that this build did not compile
     *
     * CMake writes what a build without a part must know of it from the
     * part's `source/parts/<part>/part.txt` (CMakeLists.txt,
     * CONTACT_PARTS): the values it adds to an entry that chooses among
     * parts, and its own entries, each with the value with which the part
     * would do nothing (its default, or `false` for an output that is on
     * by default). A .prm written for a full build reads in every build:
     * such an entry is declared with that value, and another value, or a
     * value of a part that is missing, is refused with a message that
     * names the entry, the part and the CMake option. A full build has
     * none.
     */
    /** @{ */
    /** Declares the entries of the parts not compiled (at the end of their
     *  subsections), which accept any value. */
    void declare_unbuilt_entries(ParameterHandler &prm);

    /** Refuses a value other than the default of an entry of a part not
     *  compiled. */
    void refuse_unbuilt_entries(ParameterHandler &prm);

    /** "|a|b": the values of `entry` ("Subsection/Entry") that parts not
     *  compiled would add to its Selection. */
    std::string unbuilt_values(const std::string &entry);

    /** If a part not compiled provides the value `value` of `entry`: "asks
     *  for the part '...', which this build did not compile (...)", the
     *  reason a message gives; else "". */
    std::string not_built(const std::string &entry, const std::string &value);
    /** @} */
  } // namespace Parts


  /**
   * The parts of one kind: a product made by create(arguments...).
   */
  template <class Product, class... Arguments>
  class PartRegistry
  {
  public:
    struct Part
    {
      /** Its value of the entry that chooses it. */
      std::string name;
      /** What that entry's help text says of it, e.g. "mu = a". */
      std::string description;
      /** The order among the parts of its kind: of the Selection, of the
       *  parts that a run creates all of (the postprocessors). */
      unsigned int rank;
      /** Its entries; none if `entries.declare` is empty. */
      PartEntries                                           entries;
      std::function<std::unique_ptr<Product>(Arguments...)> create;
    };

    /** What the messages call a part of this kind: "part", unless the
     *  kind names itself by specialising this function (e.g. "friction
     *  law", core/friction_laws.h). */
    static std::string noun();

    /** Adds a part; a name already registered for this kind is an error.
     *  Returns true, for the static variable of the registration. */
    static bool add(const Part &part)
    {
      Parts::check_name(part.name);
      AssertThrow(!is_registered(part.name),
                  ExcMessage("The " + noun() + " '" + part.name +
                             "' is registered twice; registered are " +
                             quoted_names() + "."));
      auto &all = registered();
      all.insert(std::upper_bound(all.begin(),
                                  all.end(),
                                  part,
                                  [](const Part &a, const Part &b) {
                                    return a.rank < b.rank;
                                  }),
                 part);
      if (part.entries.declare)
        Parts::add_entries(part.name, part.rank, part.entries);
      return true;
    }

    /** The registered parts, by rank. */
    static const std::vector<Part> &parts()
    {
      return registered();
    }

    static bool is_registered(const std::string &name)
    {
      for (const Part &part : registered())
        if (part.name == name)
          return true;
      return false;
    }

    /** "a|b|c": the pattern of the Selection of the parts. */
    static std::string selection()
    {
      std::string text;
      for (const Part &part : registered())
        text += (text.empty() ? "" : "|") + part.name;
      return text;
    }

    /** The pattern of the Selection of the entry `entry`
     *  ("Subsection/Entry") that chooses among the parts: the registered
     *  ones and those that this build did not compile, which parse
     *  refuses with a message that names the CMake option. */
    static std::string selection(const std::string &entry)
    {
      return selection() + Parts::unbuilt_values(entry);
    }

    /** "a: ...; b: ...": the parts as the help text lists them. */
    static std::string help_text()
    {
      std::string text;
      for (const Part &part : registered())
        text +=
          (text.empty() ? "" : "; ") + part.name + ": " + part.description;
      return text;
    }

    /** The part `name` made; a name not registered is an error that names
     *  the entry `entry` and the allowed names. */
    static std::unique_ptr<Product> create(const std::string &entry,
                                           const std::string &name,
                                           Arguments... arguments)
    {
      for (const Part &part : registered())
        if (part.name == name)
          return part.create(std::forward<Arguments>(arguments)...);
      AssertThrow(false, not_registered(entry, name));
      return nullptr;
    }

    /** `name`, the value of the entry `entry` that chooses a part of this
     *  kind, once it is checked to be registered (the error of create()
     *  otherwise): how such an entry is parsed. */
    static std::string parse(const std::string &entry, const std::string &name)
    {
      AssertThrow(is_registered(name), not_registered(entry, name));
      return name;
    }

  private:
    static ExcMessage not_registered(const std::string &entry,
                                     const std::string &name)
    {
      const std::string missing = Parts::not_built(entry, name);
      return ExcMessage(
        "Entry '" + entry + "' = '" + name + "' " +
        (missing.empty() ? "is not a registered " + noun() : missing) +
        "; allowed: " + quoted_names() + ".");
    }

    /** "'a', 'b', 'c'": the names as a message lists them. */
    static std::string quoted_names()
    {
      std::string names;
      for (const Part &part : registered())
        names += (names.empty() ? "'" : ", '") + part.name + "'";
      return names;
    }

    // A function-local static, so that the list exists before any
    // registration whatever the order in which files are initialised.
    static std::vector<Part> &registered()
    {
      static std::vector<Part> all;
      return all;
    }
  };


  template <class Product, class... Arguments>
  std::string PartRegistry<Product, Arguments...>::noun()
  {
    return "part";
  }
} // namespace Contact

#endif
