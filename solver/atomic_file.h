// Output files appear whole or not at all (SPEC §7): content is written to a temporary file
// in the destination's directory and renamed over the destination (rename is atomic on POSIX
// within one file system). On any error the temporary is removed and InputError/runtime_error
// is thrown, leaving no partial file.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace ivv {

// `write` fills the stream; throws std::runtime_error naming the path if it cannot be written.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace ivv
