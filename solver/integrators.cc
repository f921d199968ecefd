#include "solver/integrators.h"

#include <array>
#include <stdexcept>

#include "solver/input_error.h"
#include "solver/stepper_traits.h"

namespace ivv {
namespace {

struct Table {
  std::array<IntegratorTraits, 9> rows;
  std::array<IntegratorKind, 9> kinds;
};

const Table& table() {
  static const Table t = [] {
    Table out{
        {detail::traits_odeint_dopri5(), detail::traits_odeint_rosenbrock4(), detail::traits_rk4(),
         detail::traits_dp45(), detail::traits_dop853(), detail::traits_gsl_rk8pd(),
         detail::traits_gsl_msbdf(), detail::traits_rodas4(), detail::traits_mp50()},
        {}};
    for (std::size_t i = 0; i < out.rows.size(); ++i) {
      out.kinds[i] = out.rows[i].kind;
      // the rows are in IntegratorKind order: traits() indexes by the enumerator
      if (static_cast<std::size_t>(out.rows[i].kind) != i)
        throw std::logic_error("integrator table order");
    }
    return out;
  }();
  return t;
}

}  // namespace

std::span<const IntegratorTraits> integrator_table() {
  return table().rows;
}

const IntegratorTraits& traits(IntegratorKind k) {
  return table().rows.at(static_cast<std::size_t>(k));
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
