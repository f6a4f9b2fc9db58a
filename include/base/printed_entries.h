/**
 * Parameters as a run prints them (Parameters::used_parameters, a run's
 * parameters.prm): the one reader of that text and the one way to set an
 * entry by its path, for the reader of a .prm file, the checkpoint's
 * comparison of entries and the scene variants of the drivers.
 */
#ifndef contact_printed_entries_h
#define contact_printed_entries_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>

namespace Contact
{
  using namespace dealii;

  /** 'Section/Entry' -> value of every entry of a parameter text as
   *  ParameterHandler prints it ("subsection X", "set a = b", "end"; other
   *  lines, such as comments, are skipped). Entries outside subsections
   *  are keyed by their name alone. */
  std::map<std::string, std::string>
  read_printed_entries(const std::string &text);

  /** Sets the entry 'Section/Entry' of prm to value. Throws
   *  ParameterHandler's exception for an entry that is not declared or a
   *  value that does not fit its pattern. */
  void set_entry(ParameterHandler  &prm,
                 const std::string &path,
                 const std::string &value);
} // namespace Contact

#endif
