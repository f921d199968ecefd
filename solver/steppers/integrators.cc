#include "solver/steppers/integrators.h"

#include <array>
#include <utility>

#include "scene/input_error.h"
#include "solver/steppers/integrator_instance.h"

namespace ivv {
namespace {

template <std::size_t... I>
std::array<IntegratorTraits, kIntegratorKinds> rows(std::index_sequence<I...>) {
  return {detail::IntegratorInstance<I>::traits()...};
}

struct Table {
  std::array<IntegratorTraits, kIntegratorKinds> rows;
  std::array<IntegratorKind, kIntegratorKinds> kinds;
};

// Row i is entry i of the list, whose kind is enumerator i (static_asserts in
// solver/steppers/integrator_list.h): traits() indexes by the enumerator.
const Table& table() {
  static const Table t = [] {
    Table out{rows(std::make_index_sequence<kIntegratorKinds>{}), {}};
    for (std::size_t i = 0; i < out.rows.size(); ++i) out.kinds[i] = out.rows[i].kind;
    return out;
  }();
  return t;
}

}  // namespace

std::span<const IntegratorTraits> integrator_table() {
  return table().rows;
}

const IntegratorTraits& traits(IntegratorKind k) {
  return table().rows.at(static_cast<std::size_t>(k));  // std::out_of_range for a bad number
}

std::span<const IntegratorKind> all_integrators() {
  return table().kinds;
}

std::vector<IntegratorKind> production_integrators() {
  std::vector<IntegratorKind> out;
  for (const IntegratorTraits& t : integrator_table())
    if (!t.reference) out.push_back(t.kind);
  return out;
}

std::string_view to_string(IntegratorKind k) {
  return traits(k).name;
}

std::string_view describe(IntegratorKind k) {
  return traits(k).description;
}

IntegratorKind parse_integrator(const std::string& name, const std::string& field) {
  std::string valid;
  for (const IntegratorTraits& t : integrator_table()) {
    if (name == t.name) return t.kind;
    valid += (valid.empty() ? "" : ", ") + std::string(t.name);
  }
  throw InputError(field, "unknown integrator '" + name + "'; valid names: " + valid);
}

}  // namespace ivv
