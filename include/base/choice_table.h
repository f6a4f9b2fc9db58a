/**
 * The choices of a Selection entry of the .prm file as an enum class: one
 * table of names and enumerators per entry, which gives both the entry's
 * Patterns::Selection and the parser of its value, so that the names the
 * pattern allows and the names the parser knows cannot differ.
 */
#ifndef contact_choice_table_h
#define contact_choice_table_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /**
   * The names of the enumerators of `Enum` for one entry. ParameterHandler's
   * pattern check refuses an unknown name before parse() sees it; parse()
   * refuses it too (naming the entry and the allowed names), so that no
   * name falls through to some enumerator.
   */
  template <typename Enum>
  class ChoiceTable
  {
  public:
    /** `entry_name` as "Subsection/Entry", for the messages. */
    ChoiceTable(const std::string                               &entry_name,
                const std::vector<std::pair<std::string, Enum>> &table)
      : entry_path(entry_name)
      , choices(table)
    {}

    const std::string &entry() const
    {
      return entry_path;
    }

    /** The names, in the order of the table. */
    std::vector<std::string> names() const
    {
      std::vector<std::string> result;
      for (const auto &choice : choices)
        result.push_back(choice.first);
      return result;
    }

    /** The pattern of the entry: the names separated by '|'. */
    Patterns::Selection pattern() const
    {
      std::string text;
      for (const auto &choice : choices)
        text += (text.empty() ? "" : "|") + choice.first;
      return Patterns::Selection(text);
    }

    /** The enumerator called `text`. */
    Enum parse(const std::string &text) const
    {
      for (const auto &[choice_name, value] : choices)
        if (choice_name == text)
          return value;
      std::string allowed;
      for (const auto &choice : choices)
        allowed += (allowed.empty() ? "'" : ", '") + choice.first + "'";
      AssertThrow(false,
                  ExcMessage(
                    "Entry '" + entry_path + "' = '" + text +
                    "' is not one of its choices; allowed: " + allowed + "."));
      return choices.front().second;
    }

    /** The name of `value`, as the .prm file spells it. */
    const std::string &name(const Enum value) const
    {
      for (const auto &choice : choices)
        if (choice.second == value)
          return choice.first;
      AssertThrow(false,
                  ExcInternalError("An enumerator without a name in the "
                                   "table of '" +
                                   entry_path + "'."));
      return choices.front().first;
    }

  private:
    const std::string                               entry_path;
    const std::vector<std::pair<std::string, Enum>> choices;
  };
} // namespace Contact

#endif
