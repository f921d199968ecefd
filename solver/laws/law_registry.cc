#include "solver/laws/law_registry.h"

#include <array>
#include <cmath>
#include <sstream>

#include "scene/input_error.h"

namespace ivv {

double parameter_value(const LawParameters& given, const ParameterSpec& spec,
                       const DerivedParameters& p) {
  if (auto it = given.find(spec.name); it != given.end()) return it->second;
  return spec.from_scene ? spec.from_scene(p) : spec.default_value;
}

namespace {

template <class Law>
constexpr LawInfo row(LawKind kind) {
  return {kind,
          Law::name,
          Law::summary,
          Law::rate_dependent,
          law_needs_yield_strength<Law>(),
          std::span<const ParameterSpec>(Law::parameters)};
}

// LawKind follows BuiltinLaws' order: entry I states (its member `kind`) that it is LawKind
// number I; a mismatch is a compile error here.
template <std::size_t... I>
constexpr bool kinds_follow_the_tuple(std::index_sequence<I...>) {
  return ((std::tuple_element_t<I, BuiltinLaws>::kind == static_cast<LawKind>(I)) && ...);
}
static_assert(std::tuple_size_v<BuiltinLaws> == static_cast<std::size_t>(LawKind::expression));
static_assert(kinds_follow_the_tuple(std::make_index_sequence<std::tuple_size_v<BuiltinLaws>>()));

template <std::size_t... I>
constexpr auto builtin_rows(std::index_sequence<I...>) {
  return std::array<LawInfo, sizeof...(I) + 1>{
      row<std::tuple_element_t<I, BuiltinLaws>>(static_cast<LawKind>(I))...,
      LawInfo{LawKind::expression,
              "expression",
              "F from --force [--unload] expressions in z, zdot, zmax, the scene's constants and "
              "--param names (muParser)",
              false,
              false,
              {}}};
}

const auto kRows = builtin_rows(std::make_index_sequence<std::tuple_size_v<BuiltinLaws>>());

std::string name_list() {
  std::string out;
  for (const LawInfo& l : kRows)
    if (l.kind != LawKind::expression) out += (out.empty() ? "" : ", ") + std::string(l.name);
  return out;
}

}  // namespace

std::span<const LawInfo> all_law_info() {
  return kRows;
}

const LawInfo& law_info(LawKind kind) {
  return kRows[static_cast<std::size_t>(kind)];
}

std::string_view to_string(LawKind k) {
  return law_info(k).name;
}

LawKind parse_law(const std::string& name, const std::string& field) {
  for (const LawInfo& l : kRows)
    if (l.kind != LawKind::expression && name == l.name) return l.kind;
  throw InputError(field, "unknown contact law '" + name + "'; valid names: " + name_list() +
                              " (or give --force EXPR for an expression law)");
}

void validate_parameters(LawKind kind, const LawParameters& given) {
  if (kind == LawKind::expression) return;
  const LawInfo& info = law_info(kind);
  for (const auto& [name, value] : given) {
    const ParameterSpec* spec = nullptr;
    for (const ParameterSpec& s : info.parameters)
      if (s.name == name) spec = &s;
    if (!spec) {
      std::string accepted;
      for (const ParameterSpec& s : info.parameters)
        accepted += (accepted.empty() ? "" : ", ") + std::string(s.name);
      throw InputError("--param " + name, "the " + std::string(info.name) +
                                              " law has no parameter '" + name + "'; it accepts " +
                                              (accepted.empty() ? "none" : accepted));
    }
    const bool above = spec->lower_open ? value > spec->lower : value >= spec->lower;
    if (!(std::isfinite(value) && above && value <= spec->upper)) {
      std::ostringstream range;
      range << "a finite number in " << (spec->lower_open ? "(" : "[") << spec->lower << ", "
            << spec->upper << "] " << spec->unit;
      require(false, "--param " + name, range.str(), value);
    }
  }
}

}  // namespace ivv
