/* The program's version (include/base/version.h); contact_version.h is
   written at every build by source/base/version.cmake. */

#include <deal.II/base/config.h>

#include <base/version.h>
#include <contact_version.h>

#include <ctime>

namespace Contact
{
  std::string version_text()
  {
    return std::string("contact ") + CONTACT_VERSION + " (commit " +
           CONTACT_COMMIT + ", deal.II " + DEAL_II_PACKAGE_VERSION + ")";
  }


  std::string parameter_file_header()
  {
    const std::time_t now = std::time(nullptr);
    char              date[32];
    std::strftime(date,
                  sizeof(date),
                  "%Y-%m-%d %H:%M:%S UTC",
                  std::gmtime(&now));
    return "# Written by " + version_text() + " on " + date +
           ". Run it again with: contact <this file>\n";
  }
} // namespace Contact
