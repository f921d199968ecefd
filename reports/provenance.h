// Provenance of a report: which code, built how, with which libraries, run where, when and by
// which command. Everything here is read at run time (git, /proc/cpuinfo, gnuplot --version)
// or baked in at compile time from CMake (compiler, flags, build type, library versions).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ivv::reports {

struct Provenance {
  std::string git_commit;  // `git rev-parse HEAD` of the source tree, or "unknown"
  bool git_dirty = false;  // the working tree had uncommitted changes to tracked files
  std::string compiler;    // CMAKE_CXX_COMPILER_ID and version
  std::string flags;       // CMAKE_CXX_FLAGS plus the flags of the build type
  std::string build_type;  // CMAKE_BUILD_TYPE
  std::vector<std::pair<std::string, std::string>> libraries;  // name, version
  std::string date_utc;      // ISO 8601, e.g. "2025-01-31T12:00:00Z"
  std::string cpu_model;     // /proc/cpuinfo "model name", or "unknown"
  int logical_cores = 0;     // std::thread::hardware_concurrency()
  std::string host;          // gethostname(), or "unknown"
  std::string command_line;  // as given by the caller
};

Provenance collect_provenance(const std::string& command_line);

// "model name" of /proc/cpuinfo, or "unknown".
std::string cpu_model();

}  // namespace ivv::reports
