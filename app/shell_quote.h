// A command line as a POSIX shell reads it back: what ivv echoes (a report's `command:` line, a
// sweep's sidecar) can be pasted into a shell and runs the same command.
#pragma once

#include <string>
#include <string_view>

namespace ivv::app {

// `arg` as it is when every character is one a shell never interprets (letters, digits and
// @%+=:,./_-), and not empty; otherwise in single quotes, each ' inside written as '\''
// (end the quote, an escaped quote, reopen). "K_h*z^1.5 - Fad" -> 'K_h*z^1.5 - Fad'.
std::string shell_quote(std::string_view arg);

// argv[0] .. argv[argc - 1], each shell_quote()d, joined by single spaces.
std::string shell_command_line(int argc, const char* const* argv);

}  // namespace ivv::app
