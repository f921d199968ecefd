// Fuzz target: the calibration-file reader (validation/calibration_file.h read_calibration), as
// `ivv predict --calibration` meets a hand-edited file. Contract under test: any JSON text is
// either a model predict can draw from (one entry per parameter, finite values, a covariance
// that is symmetric with non-negative variances, zero rows for unidentifiable entries), or an
// InputError naming --calibration; nothing else escapes. Text that is not JSON is skipped (the
// file reader refuses it before read_calibration).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz/fuzz_targets.h"
#include "scene/input_error.h"
#include "validation/calibration_file.h"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "calibration_file_fuzz: broken postcondition: %s\n", what);
  std::abort();
}

void expect_drawable(const ivv::validation::CalibratedModel& m) {
  const std::size_t p = m.names.size();
  expect(p > 0 && m.values.size() == p && m.identifiable.size() == p, "one entry per name");
  expect(m.covariance.size() == p, "p x p covariance");
  for (std::size_t i = 0; i < p; ++i) {
    expect(std::isfinite(m.values[i]), "finite values");
    expect(m.covariance[i].size() == p, "p x p covariance");
    expect(m.covariance[i][i] >= 0, "variances >= 0");
    for (std::size_t k = 0; k < i; ++k) {
      expect(m.names[i] != m.names[k], "each parameter once");
      const double scale = std::sqrt(m.covariance[i][i] * m.covariance[k][k]);
      expect(std::abs(m.covariance[i][k] - m.covariance[k][i]) <= 1e-9 * scale, "symmetric");
      expect(std::abs(m.covariance[i][k]) <= (1 + 1e-9) * scale, "|correlation| <= 1");
    }
    if (!m.identifiable[i])
      for (std::size_t k = 0; k < p; ++k)
        expect(m.covariance[i][k] == 0, "an unidentifiable entry is not drawn");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return 0;
  try {
    expect_drawable(ivv::validation::read_calibration(j, "fuzz.json"));
  } catch (const ivv::InputError& e) {
    expect(e.field() == "--calibration", "an InputError names --calibration");
  }
  return 0;
}
