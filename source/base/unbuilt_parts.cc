/* The parts that this build did not compile, as CMake lists them from
   their part.txt files (include/base/parts.h): their entries keep the
   meaning a .prm gives them, and asking for one is refused with a message
   that names the part and the CMake option. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <base/parts.h>

#include <string>
#include <vector>

namespace Contact
{
  namespace Parts
  {
    namespace
    {
      // One line of a part's part.txt: a value that the part adds to the
      // entry that chooses among parts, or one of its own entries with its
      // default.
      struct Unbuilt
      {
        const char *part;
        bool        is_value;
        const char *entry;
        const char *text;
      };

      // Written by CMakeLists.txt: CONTACT_PARTS_OPTION (the option's
      // value) and CONTACT_UNBUILT_PARTS (the lines, or nothing).
#include <unbuilt_parts.h>

      const std::vector<Unbuilt> unbuilt = {CONTACT_UNBUILT_PARTS};


      std::string not_compiled(const Unbuilt &line)
      {
        return "asks for the part '" + std::string(line.part) +
               "', which this build did not compile (CMake option "
               "CONTACT_PARTS = \"" CONTACT_PARTS_OPTION "\"; every part "
               "is compiled with the default \"all\")";
      }


      // Enters the subsections of `path` ("A/B/Entry") and returns the
      // entry's name.
      std::string enter_path(ParameterHandler  &prm,
                             const std::string &path,
                             unsigned int      &depth)
      {
        std::string rest = path;
        depth            = 0;
        for (std::size_t slash; (slash = rest.find('/')) != std::string::npos;
             ++depth)
          {
            prm.enter_subsection(rest.substr(0, slash));
            rest = rest.substr(slash + 1);
          }
        return rest;
      }
    } // namespace


    void declare_unbuilt_entries(ParameterHandler &prm)
    {
      for (const Unbuilt &line : unbuilt)
        if (!line.is_value)
          {
            unsigned int      depth = 0;
            const std::string name  = enter_path(prm, line.entry, depth);
            // An entry that the core declares too (Geometry/Mesh file)
            // takes this declaration; its value is refused all the same.
            prm.declare_entry(name,
                              line.text,
                              Patterns::Anything(),
                              "An entry of the part '" +
                                std::string(line.part) +
                                "', which this build did not compile (CMake "
                                "option CONTACT_PARTS); a value other than "
                                "its default is refused.");
            // The entries of compiled parts that follow it (PartEntries).
            const std::string path(line.entry);
            declare_entries_after(prm, path.substr(0, path.rfind('/')), name);
            for (; depth > 0; --depth)
              prm.leave_subsection();
          }
    }


    void refuse_unbuilt_entries(ParameterHandler &prm)
    {
      for (const Unbuilt &line : unbuilt)
        if (!line.is_value)
          {
            unsigned int      depth = 0;
            const std::string name  = enter_path(prm, line.entry, depth);
            const std::string value = prm.get(name);
            for (; depth > 0; --depth)
              prm.leave_subsection();
            AssertThrow(value == line.text,
                        ExcMessage("Entry '" + std::string(line.entry) +
                                   "' = '" + value + "' " + not_compiled(line) +
                                   "; allowed here is its default '" +
                                   line.text + "', or a build with the part."));
          }
    }


    std::string unbuilt_values(const std::string &entry)
    {
      std::string values;
      for (const Unbuilt &line : unbuilt)
        if (line.is_value && entry == line.entry)
          values += "|" + std::string(line.text);
      return values;
    }


    std::string not_built(const std::string &entry, const std::string &value)
    {
      for (const Unbuilt &line : unbuilt)
        if (line.is_value && entry == line.entry && value == line.text)
          return not_compiled(line);
      return "";
    }
  } // namespace Parts
} // namespace Contact
