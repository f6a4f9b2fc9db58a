/* What the friction laws share: the rule for the entries that several laws
   read, and the messages about a law's entries. */

#include <deal.II/base/exceptions.h>

#include <core/friction_laws.h>
#include <core/parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <map>
#include <sstream>

namespace Contact
{
  namespace FrictionLaws
  {
    namespace
    {
      // @sect3{Entries that several laws read}

      // The entries that a law declares, each with its default, pattern and
      // help text, read back from a ParameterHandler that holds only them
      // (its printed form is the only list of entries ParameterHandler
      // gives).
      std::map<std::string, std::string>
      declared_entries(const std::function<void(ParameterHandler &)> &declare)
      {
        ParameterHandler alone;
        alone.enter_subsection(subsection);
        declare(alone);
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
    } // namespace


    // Against every law registered before it, by rank: the message names
    // the first law that declares the entry. The laws of the library are
    // checked as they register while it is loaded, a law of a test or of
    // another library when it registers.
    void check_declarations_agree(
      const std::string                             &name,
      const std::function<void(ParameterHandler &)> &declare)
    {
      const std::map<std::string, std::string> own = declared_entries(declare);
      for (const auto &law : LawRegistry::parts())
        for (const auto &[entry, declaration] :
             declared_entries(law.entries.declare))
          AssertThrow(own.count(entry) == 0 || own.at(entry) == declaration,
                      ExcMessage(
                        "The friction laws '" + law.name + "' and '" + name +
                        "' declare the entry '" + entry_path(entry) +
                        "' differently: an entry that several laws read "
                        "needs the same default, pattern and help text in "
                        "each of them."));
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
