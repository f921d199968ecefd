// ivv report: run every verification case and write DIR/index.html (+ JSON, CSV, JUnit).
#include <iomanip>
#include <iostream>

#include "app/command.h"
#include "reports/report.h"

namespace ivv::app {
namespace {

class Report final : public Command {
 public:
  explicit Report(CLI::App& app)
      : Command(app.add_subcommand(
            "report",
            "run every verification case and write DIR/index.html (+ JSON, CSV, JUnit)")) {
    CLI::App& cmd = cli();
    cmd.add_option("--out", options_.out_dir, "report directory (created if missing)")->required();
    cmd.add_option("--filter", options_.filter, "only cases whose id matches this glob");
    add_threads_option(cmd, options_.threads, "worker threads (0 = all cores)");
    cmd.add_flag("--allow-failures", options_.allow_failures,
                 "exit 0 even when a case fails (the report shows it)");
    cmd.add_flag("--quick", options_.quick, "fewer sweep and timing points (smoke runs)");
    cmd.add_flag("-q,--quiet", quiet_, "no progress lines on stderr");
  }

  int run(const Invocation& inv) override {
    reports::ReportOptions opt = options_;
    opt.command_line = inv.command_line;
    if (!quiet_)
      opt.progress = [](const std::string& line) { std::cerr << "ivv report: " << line << "\n"; };
    const reports::ReportSummary s = reports::write_report(opt);
    std::cout << "report: " << s.passed << " passed, " << s.failed << " failed (" << s.plots
              << " plots";
    if (s.plot_errors) std::cout << ", " << s.plot_errors << " could not be drawn";
    if (s.section_errors) std::cout << ", " << s.section_errors << " sections failed";
    std::cout << ") in " << std::setprecision(3) << s.seconds << " s\n"
              << s.index_html.string() << "\n";
    const bool bad = s.failed > 0 || s.section_errors > 0 || s.plot_errors > 0;
    if (bad && !opt.allow_failures) {
      std::cerr << "ivv report: verification failed (the report was still written); "
                   "--allow-failures to exit 0\n";
      return kExitFailure;
    }
    return 0;
  }

 private:
  reports::ReportOptions options_;
  bool quiet_ = false;
};

}  // namespace

std::unique_ptr<Command> make_report(CLI::App& app) {
  return std::make_unique<Report>(app);
}

}  // namespace ivv::app
