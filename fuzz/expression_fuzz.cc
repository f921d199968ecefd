// Fuzz target: the expression compiler (solver/laws/expression.h) for --force and --expect-cor.
// The first byte picks which; the rest is the expression text (the paper scene's constants).
// Contract (a NaN claim, a decimal comma and 1e400 each once got through as something else):
// any text either compiles into one expression (never
// muParser's comma list, whose earlier parts would be ignored), whose evaluation is a finite
// number or is recorded as non-finite by the law, or is rejected with an InputError naming the
// flag; nothing else escapes (no muParser exception, no crash).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "fuzz/fuzz_targets.h"
#include "scene/input_error.h"
#include "solver/laws/expression.h"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "expression_fuzz: broken postcondition: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool claim = data[0] & 1;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const ivv::Scene scene = ivv::paper_scene();
  const ivv::DerivedParameters p = ivv::derive(scene);
  try {
    if (claim) {
      const auto cor = ivv::compile_cor_claim(text, {}, scene);
      (void)cor(1.0);  // any double: run_conformance judges the range
    } else {
      const auto law = std::make_shared<const ivv::CompiledExpressions>(
          ivv::ExpressionLawSpec{text, "", false}, ivv::LawParameters{}, scene, p);
      for (double z : {-1e-6, 0.0, 1e-6, 1e-4}) {
        const double F = law->loading(z, 0.1);
        expect(std::isfinite(F) || law->non_finite().has_value(),
               "a non-finite force is recorded by the law");
      }
    }
  } catch (const ivv::InputError& e) {
    expect(e.field() == (claim ? "--expect-cor" : "--force") || e.field().rfind("--param", 0) == 0,
           "the InputError names the flag");
  }
  return 0;
}
