// Fuzz target: the measured-data reader (validation/measured_data.h parse_measured_data).
// Contract under test (docs/design.md §7): any text is either data whose every value lies in its
// stated range (v0 finite > 0, e finite >= 0, uncertainties finite > 0, F_max and t_contact finite
// > 0), with a column marked present only when some row measured it, and which writes and
// reads back unchanged; or an InputError naming the file; nothing else escapes.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_targets.h"
#include "scene/input_error.h"
#include "validation/measured_data.h"

namespace {

using namespace ivv::validation;

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "measured_data_fuzz: broken postcondition: %s\n", what);
  std::abort();
}

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

void expect_in_range(const MeasuredData& d) {
  expect(!d.points.empty(), "at least one row");
  for (const auto& m : d.points) {
    expect(positive(m.v0), "v0 finite > 0");
    expect(m.value[0] && std::isfinite(*m.value[0]) && *m.value[0] >= 0, "e finite >= 0");
    for (Quantity q : kQuantities) {
      const auto qi = static_cast<std::size_t>(q);
      if (q != Quantity::e && m.value[qi]) expect(positive(*m.value[qi]), "F_max, t_c > 0");
      if (m.uncertainty[qi]) expect(positive(*m.uncertainty[qi]), "uncertainty > 0");
      if (m.value[qi]) expect(d.has_quantity[qi], "a measured quantity has its column");
      if (m.value[qi] && d.has_uncertainty[qi]) expect(m.uncertainty[qi].has_value(), "u given");
    }
  }
  for (Quantity q : kQuantities)
    expect(!d.has_quantity[static_cast<std::size_t>(q)] || d.count(q) > 0,
           "a column marked present was measured somewhere");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const MeasuredData d = parse_measured_data(text, "fuzz.csv");
    expect_in_range(d);
    const MeasuredData again = parse_measured_data(to_csv(d), "fuzz.csv");
    expect(to_csv(again) == to_csv(d), "the data write and read back unchanged");
  } catch (const ivv::InputError& e) {
    expect(e.field().rfind("fuzz.csv", 0) == 0, "an InputError names the file");
  }
  return 0;
}
