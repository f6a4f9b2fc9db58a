/* Parameters as a run prints them: their reader and the setter of an entry
 * by its path (include/base/printed_entries.h). */

#include <deal.II/base/utilities.h>

#include <base/printed_entries.h>

#include <sstream>
#include <vector>

namespace Contact
{
  // @sect3{Printed parameters}

  std::map<std::string, std::string>
  read_printed_entries(const std::string &text)
  {
    std::map<std::string, std::string> entries;
    // The subsections entered, as "A/B/".
    std::string        section;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      {
        line                    = Utilities::trim(line);
        const std::size_t equal = line.find('=');
        if (line.rfind("subsection ", 0) == 0)
          section += Utilities::trim(line.substr(11)) + '/';
        else if (line == "end" && !section.empty())
          section.erase(section.rfind('/', section.size() - 2) + 1);
        else if (line.rfind("set ", 0) == 0 && equal != std::string::npos)
          entries[section + Utilities::trim(line.substr(4, equal - 4))] =
            Utilities::trim(line.substr(equal + 1));
      }
    return entries;
  }


  void set_entry(ParameterHandler  &prm,
                 const std::string &path,
                 const std::string &value)
  {
    const std::vector<std::string> names =
      Utilities::split_string_list(path, '/');
    for (unsigned int i = 0; i + 1 < names.size(); ++i)
      prm.enter_subsection(names[i]);
    prm.set(names.back(), value);
    for (unsigned int i = 0; i + 1 < names.size(); ++i)
      prm.leave_subsection();
  }
} // namespace Contact
