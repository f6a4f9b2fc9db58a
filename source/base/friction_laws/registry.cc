/* The registry of the friction laws: the one list of the laws that the
   Selection 'Friction law', its help text and the parser are made of. */

#include <deal.II/base/exceptions.h>

#include <base/friction_laws.h>
#include <base/parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>

namespace Contact
{
  namespace FrictionLaws
  {
    // @sect3{The built-in laws}

    // Each is defined in the file of its law, source/base/friction_laws/.
    Registration none_law();
    Registration constant_law();
    Registration slip_rate_weakening_law();

    namespace
    {
      // The entry whose values are the names of the laws.
      const std::string law_entry = "Friction law";


      // @sect3{Entries that several laws read}

      // The entries that a law declares, each with its default, pattern and
      // help text, read back from a ParameterHandler that holds only them
      // (its printed form is the only list of entries ParameterHandler
      // gives).
      std::map<std::string, std::string>
      declared_entries(const Registration &law)
      {
        ParameterHandler alone;
        alone.enter_subsection(subsection);
        law.declare_parameters(alone);
        alone.leave_subsection();
        std::stringstream json;
        alone.print_parameters(json, ParameterHandler::JSON);
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(json, tree);
        std::map<std::string, std::string> entries;
        if (const auto declared = tree.get_child_optional(subsection))
          for (const auto &[name, entry] : *declared)
            entries[name] = entry.get<std::string>("default_value", "") + '\n' +
                            entry.get<std::string>("pattern_description", "") +
                            '\n' + entry.get<std::string>("documentation", "");
        return entries;
      }

      // An entry that several laws read ('a', 'b') is declared by each of
      // them. ParameterHandler keeps the last declaration without a word,
      // so that a law declaring it differently would change the default or
      // the help text of the other laws' entry: that is refused here.
      void check_declarations_agree(const std::vector<Registration> &laws)
      {
        // entry -> the first law that declares it, and its declaration
        std::map<std::string, std::pair<std::string, std::string>> first;
        for (const Registration &law : laws)
          for (const auto &[entry, declaration] : declared_entries(law))
            {
              const auto [earlier, is_first] =
                first.emplace(entry, std::make_pair(law.name, declaration));
              AssertThrow(is_first || earlier->second.second == declaration,
                          ExcMessage(
                            "The friction laws '" + earlier->second.first +
                            "' and '" + law.name + "' declare the entry '" +
                            entry_path(entry) +
                            "' differently: an entry that several laws read "
                            "needs the same default, pattern and help text in "
                            "each of them."));
            }
      }


      // @sect3{The registry}

      // The one registration point: a new law is one line here (and its
      // declaration above), in the order in which 'Friction law' lists it.
      std::vector<Registration> built_in_laws()
      {
        const std::vector<Registration> laws = {none_law(),
                                                constant_law(),
                                                slip_rate_weakening_law()};
        check_declarations_agree(laws);
        return laws;
      }

      // A function-local static, so that the list exists before any use
      // whatever the order in which the library's files are initialised.
      std::vector<Registration> &registry()
      {
        static std::vector<Registration> laws = built_in_laws();
        return laws;
      }

      // The law of the paper's scenes.
      const std::string default_law = "slip rate weakening";

      // 'none', 'constant', ...: the allowed names as a message lists them.
      std::string quoted_names()
      {
        std::string list;
        for (const Registration &law : registry())
          list += (list.empty() ? "'" : ", '") + law.name + "'";
        return list;
      }
    } // namespace


    // @sect3{Registering, declaring and creating a law}

    void register_law(const Registration &law)
    {
      AssertThrow(!law.name.empty() &&
                    law.name.find_first_of("|,") == std::string::npos,
                  ExcMessage("A friction law cannot be registered as '" +
                             law.name +
                             "': the name of a law is a value of the entry '" +
                             entry_path(law_entry) +
                             "', not empty and without '|' or ','."));
      AssertThrow(law.declare_parameters && law.create,
                  ExcMessage("The friction law '" + law.name +
                             "' is registered without a function that "
                             "declares or one that creates it."));
      const std::vector<std::string> registered = names();
      AssertThrow(std::find(registered.begin(), registered.end(), law.name) ==
                    registered.end(),
                  ExcMessage("The friction law '" + law.name +
                             "' is registered twice; registered are " +
                             quoted_names() + "."));
      std::vector<Registration> laws = registry();
      laws.push_back(law);
      check_declarations_agree(laws);
      registry() = std::move(laws);
    }

    std::vector<std::string> names()
    {
      std::vector<std::string> result;
      for (const Registration &law : registry())
        result.push_back(law.name);
      return result;
    }

    void declare_law_entry(ParameterHandler &prm)
    {
      std::string selection, documentation;
      for (const Registration &law : registry())
        {
          selection += (selection.empty() ? "" : "|") + law.name;
          documentation += (documentation.empty() ? "" : "; ") + law.name +
                           ": " + law.description;
        }
      prm.declare_entry(law_entry,
                        default_law,
                        Patterns::Selection(selection),
                        documentation + ".");
    }

    // In the order of the registry, so that the used parameters of a run
    // (printed in the order of declaration) keep their order when a law is
    // added; an entry that several laws read is declared again, alike, by
    // each of them, and keeps the place of its first declaration.
    void declare_parameters(ParameterHandler &prm)
    {
      for (const Registration &law : registry())
        law.declare_parameters(prm);
    }

    std::unique_ptr<const Interface> create(const std::string &name,
                                            ParameterHandler  &prm)
    {
      for (const Registration &law : registry())
        if (law.name == name)
          return law.create(prm);
      AssertThrow(false,
                  ExcMessage("Entry '" + entry_path(law_entry) + "' = '" +
                             name + "' is not a registered friction law; " +
                             "allowed: " + quoted_names() + "."));
      return nullptr;
    }


    // @sect3{Messages about a law's entries}

    std::string entry_path(const std::string &entry)
    {
      return subsection + "/" + entry;
    }

    void check_entry(const bool         condition,
                     const std::string &entry,
                     const double       value,
                     const std::string &allowed)
    {
      Contact::check_entry(condition, entry_path(entry), value, allowed);
    }
  } // namespace FrictionLaws
} // namespace Contact
