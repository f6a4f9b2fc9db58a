/* contact: dynamic frictional contact with a nonmonotone friction law.
   Usage: contact [--set 'Section/Entry=value']... scene.prm */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <run.h>

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
  // OpenBLAS, Debian's default BLAS, lets its threads spin while they wait.
  // The dense matrices of this program (Gamma_3, a few hundred rows) gain
  // nothing from threads, and on a machine loaded by other jobs the spinning
  // made the default scene 2.6 times slower (16.5 s against 6.3 s with one
  // thread, measured with two busy processes on the two cores). So: one
  // thread, if the BLAS in use is OpenBLAS.
  void use_one_blas_thread()
  {
    using SetThreads = void (*)(int);
    if (const auto set_threads = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set_threads(1);
  }

  // Started without mpirun, the program is an Open MPI singleton, which by
  // default spawns a runtime daemon and probes every network transport:
  // 0.35 s of the 0.85 s start-up measured on this machine, more than the
  // whole time stepping of small runs. One process needs neither, so unless
  // a launcher is present (or the user set these entries), the singleton is
  // made isolated and limited to the loopback transport. Other MPI
  // libraries ignore the variables.
  void quick_singleton_start()
  {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
        std::getenv("PMIX_RANK") != nullptr ||
        std::getenv("PMI_RANK") != nullptr)
      return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
  }
} // namespace

namespace
{
  // The message of a failure, and a non-zero exit. On several processes an
  // error may hit one process only (a file rank 0 cannot write) while the
  // others wait in a collective operation: MPI_Abort ends them all.
  int fail(const std::string &message)
  {
    const unsigned int n_processes = dealii::Utilities::MPI::n_mpi_processes(
                         MPI_COMM_WORLD),
                       this_process = dealii::Utilities::MPI::this_mpi_process(
                         MPI_COMM_WORLD);
    std::cerr << std::endl << "Error";
    if (n_processes > 1)
      std::cerr << " (process " << this_process << " of " << n_processes << ")";
    std::cerr << ": " << message << std::endl;
    if (n_processes > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace

int main(int argc, char *argv[])
{
  use_one_blas_thread();
  quick_singleton_start();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      Contact::run_from_command_line(argc, argv);
    }
  catch (const dealii::ExceptionBase &exc)
    {
      // Only the exception's own text: the user needs the message, not the
      // source location of the check.
      std::ostringstream message;
      exc.print_info(message);
      return fail(message.str());
    }
  catch (const std::exception &exc)
    {
      return fail(exc.what());
    }
  return 0;
}
