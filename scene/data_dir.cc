#include "scene/data_dir.h"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <system_error>

namespace ivv {
namespace {

struct Registered {
  std::mutex mutex;
  std::vector<std::filesystem::path> dirs;
};

Registered& registered() {
  static Registered r;
  return r;
}

}  // namespace

void add_data_directory(const std::filesystem::path& dir) {
  Registered& r = registered();
  std::lock_guard lock(r.mutex);
  if (std::find(r.dirs.begin(), r.dirs.end(), dir) == r.dirs.end()) r.dirs.push_back(dir);
}

std::vector<std::filesystem::path> data_directories() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("IVV_DATA_DIR"); env != nullptr && *env != '\0')
    dirs.emplace_back(env);
  {
    Registered& r = registered();
    std::lock_guard lock(r.mutex);
    dirs.insert(dirs.end(), r.dirs.begin(), r.dirs.end());
  }
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share" / "ivv");
  return dirs;
}

}  // namespace ivv
