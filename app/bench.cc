// ivv bench: speed against error with its peers and targets (bench/speed_bench.h), or with
// --gbench [--benchmark_*] the Google Benchmark timings (bench/benchmarks.h).
#include <filesystem>
#include <iostream>

#include "app/command.h"
#include "bench/benchmarks.h"
#include "bench/speed_bench.h"
#include "scene/input_error.h"

namespace ivv::app {
namespace {

class Bench final : public Command {
 public:
  explicit Bench(CLI::App& app)
      : Command(app.add_subcommand(
            "bench",
            "speed against error, peers and targets: ivv bench [--json] [--quick]; Google "
            "Benchmark timings: ivv bench --gbench [--benchmark_*]")) {
    cli().allow_extras();
    cli().prefix_command();
  }

  int run(const Invocation& inv) override {
    std::vector<std::string> extras = cli().remaining();
    bool gbench = false, json = false, quick = false;
    for (const auto& e : extras) {
      gbench = gbench || e == "--gbench" || e.rfind("--benchmark_", 0) == 0;
      json = json || e == "--json";
      quick = quick || e == "--quick";
    }
    if (gbench) {
      std::vector<char*> args{inv.argv[0]};
      for (auto& e : extras)
        if (e != "--gbench") args.push_back(e.data());
      int n = static_cast<int>(args.size());
      return bench::run_benchmarks(n, args.data());
    }
    for (const auto& e : extras)
      if (e != "--json" && e != "--quick")
        throw InputError(e,
                         "unknown flag; ivv bench takes --json, --quick, or --gbench "
                         "[--benchmark_*]");
    // this executable, for callgrind's instruction counts (a child ivv sweep)
    std::error_code ec;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    const bench::BenchReport rep =
        bench::run_bench({.quick = quick, .ivv_executable = self},
                         [](const std::string& line) { std::cerr << line << "\n"; });
    std::cout << (json ? bench::to_json(rep) + "\n" : bench::to_text(rep));
    return 0;
  }
};

}  // namespace

std::unique_ptr<Command> make_bench(CLI::App& app) {
  return std::make_unique<Bench>(app);
}

}  // namespace ivv::app
