// ivv verify: run the verification cases (all, or those matching a glob), write the results JSON
// (the same writer and shape as the report's results.json, reports/companions.h).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "app/command.h"
#include "reports/companions.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/parallel.h"
#include "verification/registry.h"

namespace ivv::app {
namespace {

// One line per case on a terminal, a line per tenth of the cases otherwise (CI logs).
void progress_line(bool tty, std::size_t done, std::size_t total, const verification::Case& c) {
  if (tty) {
    std::fprintf(stderr, "\r[%zu/%zu] %-70.70s", done, total, c.id.c_str());
    if (done == total) std::fprintf(stderr, "\n");
  } else if (done == total || done % std::max<std::size_t>(1, total / 10) == 0) {
    std::fprintf(stderr, "verify: %zu/%zu cases run\n", done, total);
  }
  std::fflush(stderr);
}

class Verify final : public Command {
 public:
  explicit Verify(CLI::App& app)
      : Command(app.add_subcommand("verify", "run the verification cases, write results JSON")) {
    cli().add_option("--filter", filter_, "only cases whose id matches this glob");
    cli().add_option("--out", out_, "results JSON file");
    add_threads_option(cli(), threads_, "worker threads (0 = all cores)");
    cli().add_flag("--list", list_, "list the matching cases instead of running them");
  }

  int run(const Invocation&) override {
    using namespace verification;
    const auto cases = select_cases(filter_);
    if (list_) {
      for (const Case* c : cases)
        std::cout << c->id << "\t" << to_string(c->tier) << (c->slow() ? "\tslow" : "") << "\t"
                  << c->title << "\n";
      return 0;
    }
    if (out_.empty()) throw InputError("--out", "required (the results JSON file)");
    validate_threads(threads_);
    resolve_output_path(out_, "--out", Stdout::allowed);
    const bool tty = isatty(fileno(stderr));
    const BatteryResult battery = run_battery(
        cases, threads_,
        [tty](auto done, auto total, const Case& c) { progress_line(tty, done, total, c); });
    for (const CaseRecord& r : battery.records)
      if (!r.outcome.passed) std::cerr << "FAILED " << r.c->id << ": " << r.outcome.detail << "\n";
    const std::string json = reports::results_json(battery.records);
    write_file_atomically(
        out_, [&](std::ostream& os) { os << json; }, "--out", Stdout::allowed);
    (out_ == "-" ? std::cerr : std::cout)
        << "verify: " << battery.passed() << " passed, " << battery.failed << " failed\n";
    return battery.failed ? kExitFailure : 0;
  }

 private:
  std::string filter_, out_;
  int threads_ = 0;
  bool list_ = false;
};

}  // namespace

std::unique_ptr<Command> make_verify(CLI::App& app) {
  return std::make_unique<Verify>(app);
}

}  // namespace ivv::app
