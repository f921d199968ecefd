#include "solver/atomic_file.h"

#include <dirent.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string_view>

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

fs::path resolve_output_path(const fs::path& path, const std::string& field, Stdout dash) {
  const std::string name = field.empty() ? path.string() : field;
  if (path.empty()) throw InputError(name, "an output path is required (got '')");
  if (path == "-") {
    if (dash == Stdout::allowed) return path;
    throw InputError(name, "'-' (standard output) is not accepted here; give a file path");
  }
  // What the kernel itself opens (it also follows /proc's magic links, e.g. /dev/stdout to a
  // pipe, which read_symlink below cannot: their targets are names like "pipe:[123]").
  {
    std::error_code ec;
    const fs::file_status opened = fs::status(path, ec);
    if (fs::exists(opened) && !fs::is_regular_file(opened))
      throw InputError(name, "'" + path.string() + "' is " + describe(opened.type()) +
                                 "; an output must be a regular file or a new path");
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

void check_output_directory(const fs::path& dir, const std::string& field) {
  if (dir.empty()) throw InputError(field, "a directory is required (got '')");
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  fs::path existing = dir;
  if (fs::exists(st)) {
    if (!fs::is_directory(st))
      throw InputError(field, "'" + dir.string() + "' is " + describe(st.type()) +
                                  "; an output directory must be a directory or a new path");
  } else {
    // the nearest ancestor that exists is where the new directory will be made
    existing = fs::absolute(dir, ec).parent_path();
    while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.root_path())
      existing = existing.parent_path();
    if (!fs::is_directory(existing, ec))
      throw InputError(field, "'" + dir.string() + "' cannot be created: '" + existing.string() +
                                  "' is " + describe(fs::status(existing, ec).type()));
  }
  if (access(existing.c_str(), W_OK | X_OK) != 0)
    throw InputError(field, "'" + existing.string() + "' is not writable (" +
                                std::string(std::strerror(errno)) + ")");
}

void create_output_directory(const fs::path& dir, const std::string& field) {
  check_output_directory(dir, field);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(field, "cannot create the directory '" + dir.string() + "': " + ec.message());
}

namespace {
std::string temporary_prefix(const fs::path& target) {
  // built with += : GCC 12 warns falsely (-Wrestrict) on a chain of std::string operator+
  std::string prefix = ".";
  prefix += target.filename().string();
  prefix += ".tmp";
  return prefix;
}
}  // namespace

namespace {
// ".NAME.tmpPID-N" beside the resolved destination
fs::path temporary_for(const fs::path& target) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::random_device rd;
  std::string tmp_name = temporary_prefix(target);
  tmp_name += std::to_string(getpid());
  tmp_name += "-";
  tmp_name += std::to_string(rd());
  return dir / tmp_name;
}
}  // namespace

StagedFile::StagedFile(const fs::path& path, const FromFile& from, const std::string& field)
    : target_(resolve_output_path(path, field, Stdout::refused)), tmp_(temporary_for(target_)) {
  std::error_code ec;
  fs::rename(from.source, tmp_, ec);
  if (!ec) return;
  // not on the destination's file system: copied instead
  try {
    std::ifstream in(from.source, std::ios::binary);
    std::ofstream out(tmp_, std::ios::binary | std::ios::trunc);
    if (!in || !out)
      throw InputError(field.empty() ? path.string() : field,
                       "cannot stage " + from.source.string() + " as " + tmp_.string());
    out << in.rdbuf();
    out.flush();
    if (!out) throw std::runtime_error("write to '" + tmp_.string() + "' failed");
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp_, ignored);
    throw;
  }
}

StagedFile::StagedFile(const fs::path& path, const std::function<void(std::ostream&)>& write,
                       const std::string& field)
    : target_(resolve_output_path(path, field, Stdout::refused)), tmp_(temporary_for(target_)) {
  const std::string name = field.empty() ? path.string() : field;
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  try {
    std::ofstream out(tmp_, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(name, "cannot create a file in '" + dir.string() + "'");
    write(out);
    out.flush();
    if (!out) throw std::runtime_error("write to '" + tmp_.string() + "' failed");
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp_, ignored);
    throw;
  }
}

StagedFile::~StagedFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(tmp_, ignored);
}

void StagedFile::commit(Replace how) {
  // an existing file keeps its permissions
  std::error_code ec;
  const fs::file_status old = fs::status(target_, ec);
  if (!ec && fs::is_regular_file(old)) {
    fs::permissions(tmp_, old.permissions(), ec);
    if (how == Replace::after_removing) fs::remove(target_);  // throws if it cannot
  }
  fs::rename(tmp_, target_);
  committed_ = true;
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write,
                           const std::string& field, Stdout dash) {
  const fs::path target = resolve_output_path(path, field, dash);
  if (target == "-") {
    write(std::cout);
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("write to standard output failed");
    return;
  }
  StagedFile staged(target, write, field.empty() ? path.string() : field);
  staged.commit();
}

std::size_t remove_stale_temporaries(const fs::path& path) {
  const fs::path target = path.has_parent_path() ? path : fs::path(".") / path;
  const std::string prefix = temporary_prefix(target);
  // readdir's names, compared before any path is built: a directory_iterator made a path (and
  // a filename string) for every entry, ~6,600 instructions an entry; in a /tmp of 626 entries
  // the two scans of a sweep's set-up took 4.1M instructions, serial (callgrind)
  const std::unique_ptr<DIR, int (*)(DIR*)> dir(opendir(target.parent_path().c_str()), closedir);
  if (!dir) return 0;
  std::size_t removed = 0;
  while (const dirent* entry = readdir(dir.get())) {
    const std::string_view name(entry->d_name);
    if (!name.starts_with(prefix)) continue;
    // ".NAME.tmp" PID "-" N
    const std::string_view rest = name.substr(prefix.size());
    const std::size_t dash = rest.find('-');
    if (dash == std::string_view::npos || dash == 0) continue;
    if (rest.find_first_not_of("0123456789") != dash) continue;
    if (rest.find_first_not_of("0123456789", dash + 1) != std::string_view::npos) continue;
    long pid = 0;
    if (std::from_chars(rest.data(), rest.data() + dash, pid).ec != std::errc()) continue;
    if (pid <= 0 || pid == static_cast<long>(getpid())) continue;
    // kill(pid, 0) fails with ESRCH only when no such process exists
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    const fs::path file = target.parent_path() / std::string(name);
    if (fs::is_regular_file(file, ignored) && fs::remove(file, ignored)) ++removed;
  }
  return removed;
}

}  // namespace ivv
