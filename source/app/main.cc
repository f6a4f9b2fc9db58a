/* contact: dynamic frictional contact with a nonmonotone friction law.
   Usage: contact [--set 'Section/Entry=value']... scene.prm */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <app/run.h>

#include <dlfcn.h>

#include <csignal>
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
  // threads take the cores from the program's own work. So: one thread, if
  // the BLAS in use is OpenBLAS.
  void use_one_blas_thread()
  {
    using SetThreads = void (*)(int);
    if (const auto set_threads = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set_threads(1);
  }

  // Started without mpirun, the program is an Open MPI singleton, which by
  // default spawns a runtime daemon and probes every network transport,
  // which can take longer than the whole time stepping of a small run. One
  // process needs neither, so unless a launcher is present (or the user set
  // these entries), the singleton is made isolated and limited to the
  // loopback transport. Other MPI libraries ignore the variables.
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
  // A failure's text, without the source location of the check (the user
  // needs the message).
  std::string message_of(const std::exception_ptr &failure)
  {
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const dealii::ExceptionBase &exc)
      {
        std::ostringstream message;
        exc.print_info(message);
        return message.str();
      }
    catch (const std::exception &exc)
      {
        return exc.what();
      }
    catch (...)
      {
        return "an unknown exception";
      }
  }

  void report(const std::exception_ptr &failure)
  {
    const unsigned int n_processes = dealii::Utilities::MPI::n_mpi_processes(
                         MPI_COMM_WORLD),
                       this_process = dealii::Utilities::MPI::this_mpi_process(
                         MPI_COMM_WORLD);
    std::cerr << std::endl << "Error";
    if (n_processes > 1)
      std::cerr << " (process " << this_process << " of " << n_processes << ")";
    std::cerr << ": " << message_of(failure) << std::endl;
  }
} // namespace

int main(int argc, char *argv[])
{
  // Beyond a file size limit (ulimit -f) a write then fails with EFBIG,
  // which the program reports with the file like a full disk, instead of
  // the signal killing it mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  use_one_blas_thread();
  quick_singleton_start();
  // One thread per process for deal.II's task-based loops, which are then
  // serial. (The VTU output's std::async thread is a thread of its own,
  // outside this limit.)
  // (More threads did not shorten the self-checks' cell loop, the largest
  // loop of a step.)
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    {
      // On several processes a failure may hit one process only while the
      // others wait in a collective operation, and the destructors of the
      // distributed objects (MUMPS, Trilinos maps) communicate: unwinding
      // the stack on that process alone waits forever (measured: an
      // unwritable output directory hung a 2-process run). So nothing
      // catches here: an uncaught exception ends in std::terminate before
      // any unwinding, which reports it and ends all processes.
      std::set_terminate([]() {
        report(std::current_exception());
        MPI_Abort(MPI_COMM_WORLD, 1);
        std::abort();
      });
      Contact::run_from_command_line(argc, argv);
      return 0;
    }
  try
    {
      Contact::run_from_command_line(argc, argv);
    }
  catch (...)
    {
      report(std::current_exception());
      return 1;
    }
  return 0;
}
