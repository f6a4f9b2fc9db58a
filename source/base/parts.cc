/* The entries of the parts: declared where each part places them, parsed
   and checked in the order the parts were registered. */

#include <base/parts.h>

#include <algorithm>
#include <utility>

namespace Contact
{
  namespace Parts
  {
    namespace
    {
      // A function-local static: parts register while the shared library
      // is loaded, in an order that the files' initialisation decides.
      struct Added
      {
        std::string  part;
        unsigned int rank;
        PartEntries  entries;
      };

      std::vector<Added> &registered()
      {
        static std::vector<Added> entries;
        return entries;
      }
    } // namespace


    void add_entries(const std::string &part,
                     const unsigned int rank,
                     const PartEntries &entries)
    {
      for (const Added &added : registered())
        if (added.part == part &&
            added.entries.subsection == entries.subsection)
          return;
      registered().push_back({part, rank, entries});
    }


    // A part may place its entries after another part's last one. Parts
    // that follow the same entry are declared in the order of their ranks,
    // not in the order in which the files of the library registered them.
    void declare_entries_after(ParameterHandler  &prm,
                               const std::string &subsection,
                               const std::string &after)
    {
      std::vector<Added> following;
      for (const Added &added : registered())
        if (added.entries.subsection == subsection &&
            added.entries.after == after)
          following.push_back(added);
      std::stable_sort(following.begin(),
                       following.end(),
                       [](const Added &a, const Added &b) {
                         return a.rank < b.rank;
                       });
      for (const Added &added : following)
        {
          added.entries.declare(prm);
          if (!added.entries.last.empty())
            declare_entries_after(prm, subsection, added.entries.last);
        }
    }


    std::map<std::string, std::any> parse_entries(ParameterHandler  &prm,
                                                  const std::string &subsection,
                                                  const Parameters  &parameters)
    {
      std::map<std::string, std::any> values;
      for (const Added &added : registered())
        if (added.entries.subsection == subsection && added.entries.parse)
          values[added.part] = added.entries.parse(prm, parameters);
      return values;
    }


    void check_entries(const Parameters &parameters)
    {
      for (const Added &added : registered())
        if (added.entries.check)
          added.entries.check(parameters);
    }


    bool may_change_on_resume(const std::string &entry)
    {
      for (const Added &added : registered())
        for (const std::string &path : added.entries.may_change_on_resume)
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
