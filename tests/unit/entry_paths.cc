/* Every entry that code outside parameters.cc names (Contact::Entry, in
   error messages, a convergence study's overrides and the checkpoint's
   list of entries that must not change) is declared: a renamed entry
   whose path in Entry was not renamed with it makes this test fail.
   The check itself must be able to fail: a path that is not declared is
   reported as such. */

#include <deal.II/base/parameter_handler.h>

#include <parameters.h>

#include <iostream>
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

  const std::vector<std::string> paths      = Contact::Entry::all();
  unsigned int                   undeclared = 0;
  for (const std::string &path : paths)
    if (!is_declared(prm, path))
      {
        std::cout << "not declared: " << path << std::endl;
        ++undeclared;
      }
  std::cout << paths.size() << " entry paths named outside parameters.cc, "
            << undeclared << " of them not declared" << std::endl;

  std::cout << "a path that is not declared, 'Solver/Convexification "
               "tolerence', is found: "
            << (is_declared(prm, "Solver/Convexification tolerence") ? "yes" :
                                                                       "no")
            << std::endl;
}
