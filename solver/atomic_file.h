// Output files appear whole or not at all (docs/design.md §7): content is written to a temporary
// file in the destination's directory and renamed over the destination (rename is atomic on POSIX
// within one file system). On any error the temporary is removed and InputError/runtime_error
// is thrown, leaving no partial file.
//
// What the destination may be (checked before anything is written):
//   - a new path in an existing directory, or an existing regular file: written atomically;
//   - a symbolic link (chains included): resolved, and its final target written atomically,
//     so the link stays a link and the file it names gets the content (a dangling link
//     creates its target);
//   - "-" (where the caller allows it): standard output, written directly;
//   - anything else (empty path, a directory, a device, a FIFO, a socket, a link cycle):
//     InputError naming `field` (the flag the user typed, e.g. "--out").
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace ivv {

// Whether an output path "-" means standard output (a command that can stream its result) or is
// refused (a command whose output must be a file).
enum class Stdout { refused, allowed };

// Where the content of `path` will land: the final target of any symbolic links, or "-" for
// standard output when Stdout::allowed. Throws InputError(field, ...) unless that is a regular
// file or a new path in an existing directory. Call it before a long computation so that a
// bad output path fails first.
std::filesystem::path resolve_output_path(const std::filesystem::path& path,
                                          const std::string& field, Stdout dash = Stdout::refused);

// The check of an output directory (a report's DIR), the same for every command: DIR is an
// existing directory, or a new path whose nearest existing ancestor is a directory this process
// may write in. Nothing is created (create it when the output is written, so that a run that
// fails leaves no empty directory behind). Throws InputError(field, ...) naming what DIR, or the
// ancestor, is instead. Call it before a long computation, as resolve_output_path.
void check_output_directory(const std::filesystem::path& dir, const std::string& field);

// Creates DIR (and missing parents) for writing; InputError(field, ...) when it cannot.
void create_output_directory(const std::filesystem::path& dir, const std::string& field);

// `write` fills the stream; throws InputError(field, ...) for a destination that cannot be
// written (see above) and std::runtime_error naming the path if the write itself fails. An
// empty `field` names the path instead.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write,
                           const std::string& field = {}, Stdout dash = Stdout::refused);

// A file written to its temporary (".NAME.tmpPID-N" beside the destination) but not yet in
// place: files that belong together (a sweep's CSV and its sidecar) are all written first and
// then committed one after another, so that an error while writing any of them leaves none.
// The destination is checked as for write_file_atomically ("-" is not accepted). The destructor
// removes the temporary unless commit() renamed it into place.
class StagedFile {
 public:
  StagedFile(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
             const std::string& field = {});
  // A file written already: `source` becomes the temporary by a rename (no copy; the source is
  // gone), or is copied to it where the rename fails (another file system).
  struct FromFile {
    std::filesystem::path source;
  };
  StagedFile(const std::filesystem::path& path, const FromFile& from,
             const std::string& field = {});
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  // How commit() replaces an existing destination.
  //   atomically: renamed over it; a reader sees the old file or the new one, never neither.
  //   after_removing: the old file removed first, then the temporary renamed into place; a reader
  //     may find no file for that moment (never a partial one). For large files on ext4: a
  //     rename over an existing file makes the kernel allocate the new file's blocks at once
  //     (auto_da_alloc), in the committing process: 15-23 ms for a 20 MB sweep CSV (strace -T of
  //     rename), where a file renamed to a free name has them allocated later by the kernel's
  //     writeback, as any new file does.
  enum class Replace { atomically, after_removing };
  // Renames the temporary into place, keeping an existing file's permissions.
  void commit(Replace how = Replace::atomically);
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_, tmp_;
  bool committed_ = false;
};

// Removes the temporaries of `path` (".NAME.tmpPID-N" in its directory) left by a process that
// no longer runs (a sweep killed by SIGKILL while copying its CSV left tens of MB behind).
// A temporary of a live process, or of a PID that this process cannot probe, is kept. Returns
// how many were removed.
std::size_t remove_stale_temporaries(const std::filesystem::path& path);

}  // namespace ivv
