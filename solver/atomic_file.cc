#include "solver/atomic_file.h"

#include <unistd.h>

#include <fstream>
#include <random>
#include <stdexcept>

#include "solver/input_error.h"

namespace ivv {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) {
    throw InputError(path.string(), "directory '" + dir.string() + "' does not exist");
  }
  std::random_device rd;
  // built with += : GCC 12 warns falsely (-Wrestrict) on a chain of std::string operator+
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp";
  name += std::to_string(getpid());
  name += "-";
  name += std::to_string(rd());
  const fs::path tmp = dir / name;
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw InputError(path.string(), "cannot create a file in '" + dir.string() + "'");
      write(out);
      out.flush();
      if (!out) throw std::runtime_error("write to '" + tmp.string() + "' failed");
    }
    fs::rename(tmp, path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

}  // namespace ivv
