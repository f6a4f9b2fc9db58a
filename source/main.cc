/* contact: dynamic frictional contact with a nonmonotone friction law.
   Usage: contact [--set 'Section/Entry=value']... scene.prm */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <run.h>

#include <exception>
#include <iostream>

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      Contact::run_from_command_line(argc, argv);
    }
  catch (const dealii::ExceptionBase &exc)
    {
      // Only the exception's own text: the user needs the message, not the
      // source location of the check.
      std::cerr << std::endl << "Error: ";
      exc.print_info(std::cerr);
      std::cerr << std::endl;
      return 1;
    }
  catch (const std::exception &exc)
    {
      std::cerr << std::endl << "Error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
