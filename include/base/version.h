/**
 * Which program wrote a result: its version, the commit of its source
 * (where the build knew it) and the deal.II it was built with, as
 * `contact --version` prints it and every parameters.prm states it.
 */
#ifndef contact_version_h
#define contact_version_h

#include <string>

namespace Contact
{
  /** "contact 0.1.0 (commit 1a2b3c4d5e6f, deal.II 9.4.0)". */
  std::string version_text();

  /** The first line of a parameters.prm: the version_text() and the time
   *  of writing (UTC), as a .prm comment. */
  std::string parameter_file_header();
} // namespace Contact

#endif
