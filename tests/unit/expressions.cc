/* Which .prm expressions depend on time (a body force that does not is
   assembled once), and that a muparser error names the entry. */

#include <deal.II/base/exceptions.h>

#include <core/parameters.h>

#include <iostream>

using namespace Contact;

int main()
{
  for (const std::string expression : {"0; -1e-5",
                                       "0; -600*t",
                                       "t; 0",
                                       "sqrt(t)*x; 0",
                                       "0; tan(x)",
                                       "theta*2; t2",
                                       "0; exp(-t)",
                                       "x*y; _t"})
    std::cout << "'" << expression
              << "' uses t: " << expression_uses_variable(expression, "t")
              << std::endl;

  try
    {
      parse_vector_function<2>("Loads and initial values/Body force",
                               "0; 1 +* y",
                               true);
    }
  catch (const ExceptionBase &exc)
    {
      exc.print_info(std::cout);
    }
}
