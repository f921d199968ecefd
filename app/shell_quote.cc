#include "app/shell_quote.h"

#include <cctype>

namespace ivv::app {

std::string shell_quote(std::string_view arg) {
  const auto plain = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("@%+=:,./_-").find(c) != std::string_view::npos;
  };
  bool needs_quotes = arg.empty();
  for (char c : arg) needs_quotes = needs_quotes || !plain(c);
  if (!needs_quotes) return std::string(arg);
  std::string out(1, '\'');
  for (char c : arg) {
    if (c == '\'')
      out.append("'\\''");  // end the quote, an escaped quote, reopen
    else
      out.push_back(c);
  }
  out.push_back('\'');
  return out;
}

std::string shell_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) line.push_back(' ');
    line.append(shell_quote(argv[i]));
  }
  return line;
}

}  // namespace ivv::app
