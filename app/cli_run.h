// Runs the `ivv` binary under test (IVV_BINARY, set by CMake per test target) with a command
// line as a user types it, and returns its exit code, stdout and stderr. Shared by the CLI tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace ivv::testing {

struct CliRun {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

inline CliRun ivv(const std::string& args) {
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() / ("ivv_cli_test_" + std::to_string(getpid()));
  const std::string cmd = std::string(IVV_BINARY) + " " + args + " 2>" + err_file.string();
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  std::ifstream in(err_file);
  std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, err};
}

}  // namespace ivv::testing
