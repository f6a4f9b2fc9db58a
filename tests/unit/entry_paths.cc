/* Every entry that code outside parameters.cc names (Contact::Entry, in
   error messages, a convergence study's overrides and the checkpoint's
   list of entries that must not change) is declared: a renamed entry
   whose path in Entry was not renamed with it makes this test fail.
   The check itself must be able to fail: a path that is not declared is
   reported as such. The list Entry::all() (the core's entries, in
   include/base/parameters.h) and the lists of the parts whose headers add
   their own constants to the namespace (the shell's, below) must hold
   every constant of the namespace, counted in every header of include/,
   and no source file other than parameters.cc may spell an entry path as
   a literal ('Subsection/Entry' of a declared subsection): such lines are
   printed. */

#include <deal.II/base/parameter_handler.h>

#include <base/parameters.h>
#include <geometry/shell.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

namespace
{
  // Whether 'Subsection/.../Entry' is declared in prm.
  bool is_declared(dealii::ParameterHandler &prm, const std::string &path)
  {
    const std::vector<std::string> names =
      dealii::Utilities::split_string_list(path, '/');
    unsigned int entered = 0;
    bool         found   = true;
    try
      {
        for (; entered + 1 < names.size(); ++entered)
          prm.enter_subsection(names[entered]);
        // get() only asserts in debug mode; set() checks in every build
        // (it is what --set uses). The current value passes the pattern.
        prm.set(names.back(), prm.get(names.back()));
      }
    catch (const dealii::ExceptionBase &)
      {
        found = false;
      }
    for (; entered > 0; --entered)
      prm.leave_subsection();
    return found;
  }
} // namespace

int main()
{
  dealii::ParameterHandler prm;
  Contact::Parameters::declare_parameters(prm);

  namespace Entry                = Contact::Entry;
  std::vector<std::string> paths = Entry::all();
  // The parts' own constants.
  for (const std::string &path : {Entry::inner_radius,
                                  Entry::outer_radius,
                                  Entry::shell_length,
                                  Entry::cells_around})
    paths.push_back(path);
  unsigned int undeclared = 0;
  for (const std::string &path : paths)
    if (!is_declared(prm, path))
      {
        std::cout << "not declared: " << path << std::endl;
        ++undeclared;
      }
  std::cout << paths.size() << " entry paths named outside parameters.cc, "
            << undeclared << " of them not declared" << std::endl;

  // The constants of namespace Entry in the headers, against the lists.
  unsigned int constants = 0;
  for (const auto &file : std::filesystem::recursive_directory_iterator(
         CONTACT_SOURCE_ROOT "/include"))
    {
      std::ifstream header(file.path());
      bool          in_entry = false;
      for (std::string line; std::getline(header, line);)
        {
          if (line.find("} // namespace Entry") != std::string::npos)
            in_entry = false;
          else if (line.find("namespace Entry") != std::string::npos)
            in_entry = true;
          else if (in_entry &&
                   line.find("inline const std::string") != std::string::npos)
            ++constants;
        }
    }
  std::cout << constants << " constants in namespace Entry, "
            << (constants == paths.size() ? "all" : "not all")
            << " of them in Entry::all()" << std::endl;

  // Literal entry paths (inside a string literal) outside the files that
  // declare the entries.
  const std::regex literal(
    "\"[^\"]*(Geometry|Boundary conditions|Material|Loads and initial values|"
    "Friction|Time|Solver|Verification|Convergence study|Accuracy|Output)/"
    "[A-Z]");
  unsigned int literals = 0;
  for (const auto &file : std::filesystem::recursive_directory_iterator(
         CONTACT_SOURCE_ROOT "/source"))
    {
      const std::string name = file.path().filename().string();
      const bool        declares_entries =
        file.path().parent_path().filename() == "base" && name.size() >= 13 &&
        name.substr(name.size() - 13) == "parameters.cc";
      if (!file.is_regular_file() || declares_entries)
        continue;
      std::ifstream in(file.path());
      for (std::string line; std::getline(in, line);)
        if (line.find("//") == std::string::npos &&
            std::regex_search(line, literal) &&
            line.find("--set") == std::string::npos)
          {
            std::cout << "literal entry path in " << file.path().filename()
                      << ": " << line << std::endl;
            ++literals;
          }
    }
  std::cout << literals
            << " literal entry paths in source files other than "
               "base/*parameters.cc"
            << std::endl;

  std::cout << "a path that is not declared, 'Solver/Convexification "
               "tolerence', is found: "
            << (is_declared(prm, "Solver/Convexification tolerence") ? "yes" :
                                                                       "no")
            << std::endl;
}
