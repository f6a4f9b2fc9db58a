/**
 * The reader of a scene's .prm file: 'include' relative to the including
 * file, --set overrides, and for a misspelled entry or subsection the
 * declared names closest to it (prm_reader.cc).
 */
#ifndef contact_prm_reader_h
#define contact_prm_reader_h

#include <deal.II/base/parameter_handler.h>

#include <core/parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  /** The scene of `file` (empty: the defaults) with the overrides
   *  ('Section/Entry', value) applied, read and checked; `prm` (declared by
   *  Parameters::declare_parameters) holds its entries afterwards. User
   *  errors are thrown as dealii::ExceptionBase. */
  Parameters
  read_scene(ParameterHandler                                       &prm,
             const std::string                                      &file,
             const std::vector<std::pair<std::string, std::string>> &overrides);
} // namespace Contact

#endif
