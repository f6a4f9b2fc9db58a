/* Every entry that code outside the files that declare the entries names
   (a constant of a namespace Entry, in error messages, the scene variants'
   overrides and the checkpoint's list of entries that must not change) is
   declared: a renamed entry whose constant was not renamed with it makes
   this test fail. The constants are read from the text of every header of
   include/, from each of its namespaces Entry (the core's in
   core/parameters.h, a part's in the part's own header), so that a
   constant added in any of them is checked; one whose value is not a
   single string literal is printed. The check itself must be able to
   fail: a path that is not declared is reported as such. No source file
   other than one that declares entries (a *parameters.cc) may spell an
   entry path as a literal ('Subsection/Entry' of a declared subsection):
   such lines are printed. */

#include <deal.II/base/parameter_handler.h>

#include <core/parameters.h>
#include <parts/shell/shell.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
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


  // The constants of the namespaces Entry in the headers under
  // `directory`: their values, and the names of those whose value is not
  // one string literal.
  void read_entry_constants(const std::filesystem::path &directory,
                            std::vector<std::string>    &paths,
                            std::vector<std::string>    &not_literal)
  {
    const std::regex constant(
      "inline const std::string\\s+(\\w+)\\s*=\\s*(\"([^\"]*)\"\\s*;)?");
    for (const auto &file :
         std::filesystem::recursive_directory_iterator(directory))
      {
        if (!file.is_regular_file() || file.path().extension() != ".h")
          continue;
        std::ifstream     in(file.path());
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        for (std::size_t begin = text.find("namespace Entry\n");
             begin != std::string::npos;
             begin = text.find("namespace Entry\n", begin + 1))
          {
            const std::size_t end   = text.find("} // namespace Entry", begin);
            const std::string block = text.substr(begin, end - begin);
            for (std::sregex_iterator match(block.begin(),
                                            block.end(),
                                            constant);
                 match != std::sregex_iterator();
                 ++match)
              if ((*match)[2].matched)
                paths.push_back((*match)[3].str());
              else
                not_literal.push_back((*match)[1].str());
          }
      }
  }
} // namespace

int main()
{
  dealii::ParameterHandler prm;
  Contact::Parameters::declare_parameters(prm);

  std::vector<std::string> paths, not_literal;
  read_entry_constants(CONTACT_SOURCE_ROOT "/include", paths, not_literal);
  for (const std::string &name : not_literal)
    std::cout << "not a string literal: Entry::" << name << std::endl;
  unsigned int undeclared = 0;
  for (const std::string &path : paths)
    if (!is_declared(prm, path))
      {
        std::cout << "not declared: " << path << std::endl;
        ++undeclared;
      }
  std::cout << paths.size() + not_literal.size()
            << " constants in the namespaces Entry of include/, " << undeclared
            << " of them not declared" << std::endl;

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
        name.size() >= 13 && name.substr(name.size() - 13) == "parameters.cc";
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
               "*parameters.cc"
            << std::endl;

  std::cout << "a path that is not declared, 'Solver/Convexification "
               "tolerence', is found: "
            << (is_declared(prm, "Solver/Convexification tolerence") ? "yes" :
                                                                       "no")
            << std::endl;
}
