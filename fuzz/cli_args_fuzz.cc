// Fuzz target: the command line's value lists (app/cli_args.h parse_grid), "LO:HI:N" ranges and
// "a,b,c" lists, linear and logarithmic. The first byte picks log spacing; the rest is the text.
// Contract: a grid of finite numbers (LO:HI:N gives N points from LO to HI, never decreasing,
// N <= 1e6; a log range only positive points), or an InputError naming the flag; nothing else
// escapes. The same text as the range of `--set KEY=RANGE` (parse_set_axis) keeps the contract.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/cli_args.h"
#include "fuzz/fuzz_targets.h"
#include "scene/input_error.h"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "cli_args_fuzz: broken postcondition: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool log = data[0] & 1;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const std::vector<double> grid = ivv::parse_grid(text, "--v0", ivv::spacing_of(log));
    expect(!grid.empty(), "a grid has at least one point");
    expect(grid.size() <= 1'000'000, "at most 1e6 points");
    for (double v : grid) expect(std::isfinite(v), "every point finite");
    // --log spaces a LO:HI:N range; a list is taken as given (found by this fuzzer: "-1"
    // with log set is a valid list, the sweep's own validation judges its values)
    if (log && text.find(':') != std::string::npos)
      for (double v : grid) expect(v > 0, "log range points > 0");
    // a LO:HI:N range (HI >= LO) never decreases, linear (decimal or not) or logarithmic
    if (text.find(':') != std::string::npos)
      for (std::size_t i = 1; i < grid.size(); ++i)
        expect(grid[i - 1] <= grid[i], "a range never decreases");
  } catch (const ivv::InputError& e) {
    expect(e.field() == "--v0", "the InputError names the flag");
  }
  // the same text as the RANGE of `--set impactor.mass=RANGE`, with "log:" when log is set
  try {
    const ivv::SetAxisSpec axis =
        ivv::parse_set_axis("impactor.mass=" + std::string(log ? "log:" : "") + text);
    expect(axis.key == "impactor.mass" && !axis.values.empty(), "an axis has its key and values");
    for (double v : axis.values) expect(std::isfinite(v), "every axis point finite");
  } catch (const ivv::InputError& e) {
    expect(e.field() == "--set impactor.mass", "the InputError names --set KEY");
  }
  try {
    const double v = ivv::parse_number(text, "--v0");
    expect(std::isfinite(v), "a parsed number is finite");
  } catch (const ivv::InputError& e) {
    expect(e.field() == "--v0", "the InputError names the flag");
  }
  return 0;
}
