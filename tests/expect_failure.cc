/* Runs `contact <file.prm>` on a .prm that must be rejected, prints what the
   program printed (with the directory of the .prm removed, so that the
   output holds no absolute path) and whether it exited non-zero. Exits 0
   only if the program failed without crashing, as a rejected input must. */

#include <array>
#include <cstdio>
#include <iostream>
#include <string>
#include <sys/wait.h>

int main(int argc, char *argv[])
{
  if (argc != 2)
    {
      std::cerr << "Usage: expect_failure file.prm" << std::endl;
      return 2;
    }
  const std::string file      = argv[1];
  const std::string directory = file.substr(0, file.rfind('/') + 1);
  const std::string command =
    std::string(CONTACT_EXECUTABLE) + " '" + file + "' 2>&1";

  FILE *pipe = popen(command.c_str(), "r");
  if (pipe == nullptr)
    return 2;
  std::string            text;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    text += buffer.data();
  const int status = pclose(pipe);

  for (std::size_t at = text.find(directory); at != std::string::npos;
       at             = text.find(directory))
    text.erase(at, directory.size());
  std::cout << text;
  // A rejected input ends with an error message and exit status 1; a
  // signal (the shell reports 128 + its number) or an uncaught C++
  // exception is a crash, not a rejection.
  const int  code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  const bool crashed =
    code >= 128 || text.find("terminate called") != std::string::npos;
  if (crashed)
    std::cout << "exit status: crashed (" << code << ")" << std::endl;
  else
    std::cout << (code != 0 ? "exit status: non-zero" : "exit status: zero")
              << std::endl;
  return (code != 0 && !crashed) ? 0 : 1;
}
