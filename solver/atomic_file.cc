#include "solver/atomic_file.h"

#include <unistd.h>

#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>

#include "scene/input_error.h"

namespace ivv {

namespace fs = std::filesystem;

namespace {

// Linux's own limit on links followed in one path resolution (MAXSYMLINKS).
constexpr int kMaxSymlinks = 40;

std::string describe(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

}  // namespace

fs::path resolve_output_path(const fs::path& path, const std::string& field, bool allow_stdout) {
  const std::string name = field.empty() ? path.string() : field;
  if (path.empty()) throw InputError(name, "an output path is required (got '')");
  if (path == "-") {
    if (allow_stdout) return path;
    throw InputError(name, "'-' (standard output) is not accepted here; give a file path");
  }
  fs::path target = path;
  for (int links = 0;; ++links) {
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(target, ec);
    if (!fs::is_symlink(st)) break;
    if (links == kMaxSymlinks)
      throw InputError(name, "'" + path.string() + "': too many levels of symbolic links");
    const fs::path next = fs::read_symlink(target, ec);
    if (ec)
      throw InputError(name, "cannot read the link '" + target.string() + "': " + ec.message());
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  std::error_code ec;
  const fs::file_status st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) {
    throw InputError(name, "'" + path.string() + "' is " + describe(st.type()) +
                               "; an output must be a regular file or a new path");
  }
  if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
    throw InputError(name, "'" + path.string() + "' names a directory, not a file");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw InputError(name, "directory '" + dir.string() + "' does not exist");
  return target;
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write,
                           const std::string& field, bool allow_stdout) {
  const fs::path target = resolve_output_path(path, field, allow_stdout);
  if (target == "-") {
    write(std::cout);
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("write to standard output failed");
    return;
  }
  const std::string name = field.empty() ? path.string() : field;
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::random_device rd;
  // built with += : GCC 12 warns falsely (-Wrestrict) on a chain of std::string operator+
  std::string tmp_name = ".";
  tmp_name += target.filename().string();
  tmp_name += ".tmp";
  tmp_name += std::to_string(getpid());
  tmp_name += "-";
  tmp_name += std::to_string(rd());
  const fs::path tmp = dir / tmp_name;
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw InputError(name, "cannot create a file in '" + dir.string() + "'");
      write(out);
      out.flush();
      if (!out) throw std::runtime_error("write to '" + tmp.string() + "' failed");
    }
    // an existing file keeps its permissions
    std::error_code ec;
    const fs::file_status old = fs::status(target, ec);
    if (!ec && fs::is_regular_file(old)) fs::permissions(tmp, old.permissions(), ec);
    fs::rename(tmp, target);
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

}  // namespace ivv
