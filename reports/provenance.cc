#include "reports/provenance.h"

#include <gsl/gsl_version.h>
#include <unistd.h>

#include <toml++/impl/version.h>
#include <Eigen/Core>
#include <array>
#include <boost/version.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "reports/gnuplot_svg.h"

namespace ivv::reports {
namespace {

// Output of a shell command (trailing newline removed); empty on failure.
std::string command_output(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 256> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  if (pclose(pipe) != 0) return {};
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

std::string boost_version() {
  std::string v = BOOST_LIB_VERSION;  // "1_81"
  for (char& ch : v)
    if (ch == '_') ch = '.';
  return v;
}

// "gnuplot 5.4 patchlevel 4" -> "5.4 patchlevel 4"
std::string version_number(std::string v) {
  if (v.rfind("gnuplot ", 0) == 0) v.erase(0, 8);
  return v;
}

}  // namespace

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t"));
        return v;
      }
    }
  }
  return "unknown";
}

Provenance collect_provenance(const std::string& command_line) {
  Provenance p;
  // the directory of these sources, symbolic links resolved (git needs the real tree)
  std::error_code ec;
  std::filesystem::path tree = std::filesystem::canonical(IVV_SOURCE_DIR, ec);
  if (ec) tree = IVV_SOURCE_DIR;
  const std::string git = "git -C " + shell_quoted(tree.string());
  p.git_commit = command_output(git + " rev-parse HEAD 2>/dev/null");
  if (p.git_commit.empty()) {
    p.git_commit = "unknown";
  } else {
    p.git_dirty =
        !command_output(git + " status --porcelain --untracked-files=no 2>/dev/null").empty();
  }
  p.compiler = IVV_CXX_COMPILER;
  p.flags = IVV_CXX_FLAGS;
  p.build_type = IVV_BUILD_TYPE;
  p.libraries = {
      {"Boost", boost_version()},
      {"GSL", GSL_VERSION},
      {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                    "." + std::to_string(EIGEN_MINOR_VERSION)},
      {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
      {"toml++", std::to_string(TOML_LIB_MAJOR) + "." + std::to_string(TOML_LIB_MINOR) + "." +
                     std::to_string(TOML_LIB_PATCH)},
      {"gnuplot", version_number(gnuplot_version())},
  };
#ifdef __GLIBCXX__
  p.libraries.emplace_back("libstdc++", std::to_string(__GLIBCXX__));
#endif
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  p.date_utc = date;
  p.cpu_model = cpu_model();
  p.logical_cores = static_cast<int>(std::thread::hardware_concurrency());
  char host[256] = {};
  p.host = gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
  p.command_line = command_line;
  return p;
}

}  // namespace ivv::reports
