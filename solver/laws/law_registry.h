// The registry of built-in contact laws: one row per law, read by the command line (names,
// `--param`), the JSON output, the verification cases and the report.
//
// A row is generated from the law's own header (its `name`, `summary`, `parameters`,
// `rate_dependent`, `needs_yield_strength` and `make`). Adding a built-in law is its header,
// its test, its enumerator in `LawKind` (solver/laws/law_kind.h) named by its member `kind`, and
// one entry in `BuiltinLaws` in the same order (checked at compile time in law_registry.cc).
//
// Laws are templates in the hot loop: `with_builtin_law` dispatches once per impact.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "scene/scene.h"
#include "solver/laws/elastoplastic.h"
#include "solver/laws/hertz.h"
#include "solver/laws/hunt_crossley.h"
#include "solver/laws/law_kind.h"
#include "solver/laws/law_parameters.h"
#include "solver/laws/linearized.h"

namespace ivv {

// The built-in laws (this order is LawKind's), then `expression`: a law typed on the command
// line (solver/laws/expression.h), which has no fixed parameters.
using BuiltinLaws = std::tuple<HertzLaw, ElastoplasticLaw, LinearizedLaw, HuntCrossleyLaw>;

struct LawInfo {
  LawKind kind;
  std::string_view name;
  std::string_view summary;  // equation and source, one line
  bool rate_dependent = false;
  bool needs_yield_strength = false;
  std::span<const ParameterSpec> parameters;
};

// Every law, built-in first, `expression` last.
std::span<const LawInfo> all_law_info();
const LawInfo& law_info(LawKind kind);
std::string_view to_string(LawKind k);
// Parse a name; throws InputError(field, "unknown contact law ...; valid names: ...").
LawKind parse_law(const std::string& name, const std::string& field = "--law");

// Throws InputError("--param NAME", ...) for a name the law does not accept or a value outside
// its range. (Expression laws accept any name: their parameters are variables.)
void validate_parameters(LawKind kind, const LawParameters& given);

// Calls f(law) with the built-in law of `kind` made from the parameters and the scene
// (kind != expression).
template <std::size_t I = 0, class F>
decltype(auto) with_builtin_law(LawKind kind, const LawParameters& given,
                                const DerivedParameters& p, F&& f) {
  using Law = std::tuple_element_t<I, BuiltinLaws>;
  if constexpr (I + 1 < std::tuple_size_v<BuiltinLaws>) {
    if (static_cast<std::size_t>(kind) != I)
      return with_builtin_law<I + 1>(kind, given, p, std::forward<F>(f));
  }
  return f(Law::make(given, p));
}

}  // namespace ivv
