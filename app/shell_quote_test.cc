// shell_quote: a printed command line pasted back into /bin/sh gives the same arguments.
#include "app/shell_quote.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace ivv::app {
namespace {

TEST(ShellQuote, PlainArgumentsStayAsTheyAre) {
  EXPECT_EQ(shell_quote("check-law"), "check-law");
  EXPECT_EQ(shell_quote("--param"), "--param");
  EXPECT_EQ(shell_quote("Fad=3.1e-5"), "Fad=3.1e-5");
  EXPECT_EQ(shell_quote("reference_data/scenes/glass-bead.toml"),
            "reference_data/scenes/glass-bead.toml");
}

TEST(ShellQuote, ArgumentsAShellWouldReadAreSingleQuoted) {
  EXPECT_EQ(shell_quote("K_h*z^1.5 - Fad"), "'K_h*z^1.5 - Fad'");
  EXPECT_EQ(shell_quote("z < z1 ? a : b"), "'z < z1 ? a : b'");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
}

// The line through /bin/sh: printf prints each argument it is given on its own line.
TEST(ShellQuote, APastedLineGivesBackTheSameArguments) {
  const std::vector<std::string> args = {"printf", "%s\\n",     "K_h*z^1.5 - Fad*(1 - z/zmax)",
                                         "it's",   "",          "a\"b",
                                         "$x `y`", "--v0=1e-4", "tab\there"};
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  const std::string line = shell_command_line(static_cast<int>(argv.size()), argv.data());
  FILE* pipe = popen(line.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  std::array<char, 256> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  ASSERT_EQ(pclose(pipe), 0) << line;
  std::string expected;
  for (std::size_t i = 2; i < args.size(); ++i) expected += args[i] + "\n";
  EXPECT_EQ(out, expected) << line;
}

}  // namespace
}  // namespace ivv::app
