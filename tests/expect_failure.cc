/* Runs `contact <file.prm>` on a .prm that must be rejected, prints what the
   program printed (with the directory of the .prm removed, so that the
   output holds no absolute path) and whether it exited non-zero. Exits 0
   only if the program failed, as a rejected input must. */

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
  const bool failed = !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  std::cout << (failed ? "exit status: non-zero" : "exit status: zero")
            << std::endl;
  return failed ? 0 : 1;
}
