/* Every .prm of tests/bad_input run on two processes (mpirun -np 2): each
   must be refused as in the serial run, with exit status 1 and an error
   message, and none may end in a signal or an uncaught C++ exception
   (main.cc reports the error of each process and ends the job with
   MPI_Abort instead of unwinding one process alone). */

#include <array>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

int main()
{
  std::set<fs::path> scenes;
  for (const auto &entry : fs::directory_iterator(CONTACT_BAD_INPUT_DIR))
    if (entry.path().extension() == ".prm" &&
        fs::exists(fs::path(entry.path()).replace_extension(".output")))
      scenes.insert(entry.path());

  unsigned int refused = 0;
  for (const fs::path &scene : scenes)
    {
      const std::string command =
        "mpirun --allow-run-as-root --oversubscribe -np 2 " +
        std::string(CONTACT_BINARY) + " '" + scene.string() + "' 2>&1";
      FILE                  *pipe = popen(command.c_str(), "r");
      std::string            text;
      std::array<char, 4096> buffer;
      while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
        text += buffer.data();
      const int  status  = pclose(pipe);
      const int  code    = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      const bool crashed = text.find("terminate called") != std::string::npos ||
                           text.find("on signal") != std::string::npos ||
                           text.find("Segmentation") != std::string::npos;
      const bool with_message = text.find("Error") != std::string::npos;
      if (code == 1 && !crashed && with_message)
        ++refused;
      else
        std::cout << scene.filename().string() << ": exit status " << code
                  << (crashed ? ", crashed" : "")
                  << (with_message ? "" : ", no error message") << std::endl;
    }
  // Not the count, so that a new bad input needs no new output here.
  std::cout << (refused == scenes.size() && refused > 0 ? "every" : "NOT every")
            << " bad input of tests/bad_input refused on two processes with "
               "exit status 1, an error message and no crash"
            << std::endl;
}
