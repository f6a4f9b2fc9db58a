/* The entries of the parts: declared where each part places them, parsed
   and checked in the order the parts were registered. */

#include <base/parts.h>

#include <utility>

namespace Contact
{
  namespace Parts
  {
    namespace
    {
      // A function-local static: parts register while the shared library
      // is loaded, in an order that the files' initialisation decides.
      std::vector<std::pair<std::string, PartEntries>> &registered()
      {
        static std::vector<std::pair<std::string, PartEntries>> entries;
        return entries;
      }
    } // namespace


    void add_entries(const std::string &part, const PartEntries &entries)
    {
      for (const auto &[name, added] : registered())
        if (name == part && added.subsection == entries.subsection)
          return;
      registered().emplace_back(part, entries);
    }


    // A part may place its entries after another part's last one.
    void declare_entries_after(ParameterHandler  &prm,
                               const std::string &subsection,
                               const std::string &after)
    {
      for (const auto &[part, entries] : registered())
        if (entries.subsection == subsection && entries.after == after)
          {
            entries.declare(prm);
            if (!entries.last.empty())
              declare_entries_after(prm, subsection, entries.last);
          }
    }


    std::map<std::string, std::any> parse_entries(ParameterHandler  &prm,
                                                  const std::string &subsection,
                                                  const Parameters  &parameters)
    {
      std::map<std::string, std::any> values;
      for (const auto &[part, entries] : registered())
        if (entries.subsection == subsection && entries.parse)
          values[part] = entries.parse(prm, parameters);
      return values;
    }


    void check_entries(const Parameters &parameters)
    {
      for (const auto &[part, entries] : registered())
        if (entries.check)
          entries.check(parameters);
    }


    bool may_change_on_resume(const std::string &entry)
    {
      for (const auto &[part, entries] : registered())
        for (const std::string &path : entries.may_change_on_resume)
          if (path == entry)
            return true;
      return false;
    }


    void check_name(const std::string &name)
    {
      AssertThrow(!name.empty() &&
                    name.find_first_of("|,") == std::string::npos,
                  ExcMessage("A part cannot be registered as '" + name +
                             "': the name of a part is a value of the entry "
                             "that chooses it, not empty and without '|' "
                             "or ','."));
    }
  } // namespace Parts
} // namespace Contact
