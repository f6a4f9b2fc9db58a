/* Every Selection entry of the .prm file is parsed by the table of its
   enum class or made of the registered parts of a kind (base/parts.h):
   the entry's pattern lists exactly the table's or the registered names (a
   Selection entry without either, or whose pattern differs from it, is
   printed), and the table or the kind refuses a name that is not among
   them, naming the entry and the allowed names (ParameterHandler's pattern
   check refuses such a name first; they are called directly here). The
   quantities of 'Accuracy/Target quantity' are parsed by their own table:
   the name of each quantity parses back to it, and an unknown name is
   refused. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <core/factorization.h>
#include <core/friction_method.h>
#include <core/friction_solver.h>
#include <core/geometry_base.h>
#include <core/parameters.h>
#include <parts/studies/study_parameters.h>

#include <iostream>
#include <map>
#include <sstream>
#include <string>

using namespace Contact;

namespace
{
  // ParameterHandler spells a character other than [a-zA-Z0-9] in a name
  // as _XX, its hexadecimal code.
  std::string demangle(const std::string &name)
  {
    std::string result;
    for (std::size_t i = 0; i < name.size(); ++i)
      if (name[i] == '_' && i + 2 < name.size())
        {
          result += static_cast<char>(std::stoi(name.substr(i + 1, 2), 0, 16));
          i += 2;
        }
      else
        result += name[i];
    return result;
  }

  // "Subsection/Entry" -> pattern description of every Selection entry.
  void collect_selections(const boost::property_tree::ptree  &tree,
                          const std::string                  &path,
                          std::map<std::string, std::string> &selections)
  {
    for (const auto &[key, child] : tree)
      {
        const std::string name = path + demangle(key);
        if (const auto pattern =
              child.get_optional<std::string>("pattern_description"))
          {
            if (pattern->rfind("[Selection", 0) == 0)
              selections[name] = *pattern;
          }
        else
          collect_selections(child, name + "/", selections);
      }
  }

  // The pattern against the table's, and an unknown name.
  template <typename Enum>
  void check(const ChoiceTable<Enum>            &table,
             std::map<std::string, std::string> &selections)
  {
    const auto declared = selections.find(table.entry());
    std::cout << table.entry() << ": "
              << (declared == selections.end() ?
                    "not a declared Selection" :
                  declared->second == table.pattern().description() ?
                    "the pattern lists the table's names" :
                    "the pattern " + declared->second + " differs from " +
                      table.pattern().description())
              << std::endl;
    if (declared != selections.end())
      selections.erase(declared);
    for (const std::string &name : table.names())
      if (table.name(table.parse(name)) != name)
        std::cout << "  '" << name << "' does not parse back" << std::endl;
    try
      {
        table.parse("no such choice");
        std::cout << "  an unknown name is accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        exc.print_info(std::cout);
      }
  }

  // The pattern against the registered names of a kind, and an unknown
  // name, which create() refuses (`arguments` are those of the kind's
  // parts, not used for an unknown name).
  template <class Registry, class... Arguments>
  void check_parts(const std::string                  &entry,
                   std::map<std::string, std::string> &selections,
                   Arguments &&...arguments)
  {
    const auto        declared = selections.find(entry);
    const std::string pattern =
      Patterns::Selection(Registry::selection()).description();
    std::cout << entry << ": "
              << (declared == selections.end() ?
                    "not a declared Selection" :
                  declared->second == pattern ?
                    "the pattern lists the registered names" :
                    "the pattern " + declared->second + " differs from " +
                      pattern)
              << std::endl;
    if (declared != selections.end())
      selections.erase(declared);
    try
      {
        Registry::create(entry,
                         "no such choice",
                         std::forward<Arguments>(arguments)...);
        std::cout << "  an unknown name is accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        exc.print_info(std::cout);
      }
  }

  // The same for an entry whose Selection is 'auto' (resolved by the core)
  // before the registered names, and whose parts are made with arguments
  // that a unit test lacks: the unknown name is refused by parse(), with
  // the words of create().
  template <class Registry>
  void check_parts_after_auto(const std::string                  &entry,
                              std::map<std::string, std::string> &selections,
                              const std::string                  &before)
  {
    const auto        declared = selections.find(entry);
    const std::string pattern =
      Patterns::Selection(before + Registry::selection()).description();
    std::cout << entry << ": "
              << (declared == selections.end() ?
                    "not a declared Selection" :
                  declared->second == pattern ?
                    "the pattern lists the registered names" :
                    "the pattern " + declared->second + " differs from " +
                      pattern)
              << std::endl;
    if (declared != selections.end())
      selections.erase(declared);
    try
      {
        Registry::parse(entry, "no such choice");
        std::cout << "  an unknown name is accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        exc.print_info(std::cout);
      }
  }
} // namespace

int main()
{
  ParameterHandler prm;
  Parameters::declare_parameters(prm);
  std::stringstream json;
  prm.print_parameters(json, ParameterHandler::JSON);
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(json, tree);
  std::map<std::string, std::string> selections;
  collect_selections(tree, "", selections);
  std::cout << selections.size() << " Selection entries" << std::endl;

  check_parts<GeometryBaseRegistry>(Entry::domain, selections, Parameters());
  check(GeometryParameters::cell_shapes(), selections);
  check(GeometryParameters::mass_matrices(), selections);
  check(MaterialParameters::plane_models(), selections);
  check_parts_after_auto<LinearSolverRegistry>(Entry::linear_solver,
                                               selections,
                                               "auto|");
  check_parts_after_auto<ContactPathRegistry<2>>(Entry::contact_solver,
                                                 selections,
                                                 "auto|");
  check_parts_after_auto<FrictionMethodRegistry<2>>(Entry::friction_method,
                                                    selections,
                                                    "");
  check(VerificationParameters::solutions(), selections);
  check(ConvergenceStudyParameters::refinements(), selections);
  check(AccuracyParameters::target_error_types(), selections);
  check(AccuracyParameters::cost_models(), selections);
  check_parts<FrictionLaws::LawRegistry>(
    FrictionLaws::entry_path(FrictionLaws::law_entry), selections, prm);
  for (const auto &[entry, pattern] : selections)
    std::cout << entry << ": a Selection without a table, " << pattern
              << std::endl;

  for (const Quantity &quantity : Quantity::of_scene(2, 3))
    if (Quantity::parse(quantity.name(), Entry::target_quantity).name() !=
        quantity.name())
      std::cout << "'" << quantity.name() << "' does not parse back"
                << std::endl;
  std::cout << Quantity::of_scene(2, 3).size()
            << " quantities of a 3D scene with two probes" << std::endl;
  for (const std::string name : {"probe 0 u_x", "probe 1 u_w", "V-norm"})
    try
      {
        Quantity::parse(name, Entry::target_quantity);
        std::cout << "'" << name << "' is accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        exc.print_info(std::cout);
      }
}
