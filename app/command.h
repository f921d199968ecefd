// The shape of every `ivv` subcommand: one file per subcommand under app/, each a Command that
// declares its flags on the parser and runs when the user names it. A command parses and
// prints; what it prints is computed by the libraries (solver, oracles, verification, reports).
//
// Exit codes (docs/design.md §5): 0 success; 1 a computation or a check failed (with the reason);
// 2 bad input (the message names the field and the accepted range; InputError).
#pragma once

#include <CLI/CLI.hpp>

#include <cctype>
#include <memory>
#include <string>

namespace ivv::app {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// --threads N (0: all cores), one definition for every command that runs in parallel. The text
// must be a whole number in [0, kMaxThreads]: CLI11 alone reads '' as 0 (all cores), and
// '' is bad input like '2x' (exit 2, through CLI11's validation error).
inline constexpr int kMaxThreads = 1024;
inline CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& help) {
  auto whole_number = [](std::string& text) -> std::string {
    bool digits = !text.empty() && text.size() <= 4;
    for (char ch : text) digits = digits && std::isdigit(static_cast<unsigned char>(ch));
    if (digits && std::stoi(text) <= kMaxThreads) return {};
    return "must be a whole number in [0, " + std::to_string(kMaxThreads) +
           "] (0: all cores), got '" + text + "'";
  };
  return cmd.add_option("--threads", threads, help)
      ->check(CLI::Validator(whole_number, "N in [0, " + std::to_string(kMaxThreads) + "]"))
      ->capture_default_str();
}

// The process's command line, for the commands that record or repeat it.
struct Invocation {
  int argc = 0;
  char** argv = nullptr;
  std::string command_line;  // argv, each argument shell-quoted where needed (app/shell_quote.h)
};

class Command {
 public:
  virtual ~Command() = default;
  // The parser node that says whether the user named this command.
  CLI::App& cli() const { return *cli_; }
  virtual int run(const Invocation& invocation) = 0;

 protected:
  explicit Command(CLI::App* cli) : cli_(cli) {}

 private:
  CLI::App* cli_;
};

// Each adds its subcommand (and its flags) to `app`; defined in app/<name>.cc.
std::unique_ptr<Command> make_simulate(CLI::App& app);
std::unique_ptr<Command> make_sweep(CLI::App& app);
std::unique_ptr<Command> make_scene_show(CLI::App& app);
std::unique_ptr<Command> make_integrators(CLI::App& app);
std::unique_ptr<Command> make_laws(CLI::App& app);
std::unique_ptr<Command> make_fit_hc(CLI::App& app);
std::unique_ptr<Command> make_verify(CLI::App& app);
std::unique_ptr<Command> make_report(CLI::App& app);
std::unique_ptr<Command> make_check_law(CLI::App& app);
std::unique_ptr<Command> make_bench(CLI::App& app);
std::unique_ptr<Command> make_calibrate(CLI::App& app);
std::unique_ptr<Command> make_predict(CLI::App& app);

}  // namespace ivv::app
