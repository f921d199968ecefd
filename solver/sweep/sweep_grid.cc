#include "solver/sweep/sweep_grid.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "scene/scene_values.h"
#include "solver/format.h"
#include "solver/plate/plate_impact.h"

namespace ivv {

// ---- grids ---------------------------------------------------------------------------------

namespace {

// value = mantissa 10^exponent
struct Decimal {
  std::int64_t mantissa = 0;
  int exponent = 0;
};

// The shortest decimal that reads back as x (std::to_chars, scientific: at most 17 digits, so
// the mantissa fits in 64 bits).
std::optional<Decimal> shortest_decimal(double x) {
  if (!std::isfinite(x)) return std::nullopt;
  char buf[kMaxNumberChars];
  const char* end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific).ptr;
  const char* p = buf;
  const bool negative = *p == '-';
  if (negative) ++p;
  Decimal d;
  int fraction_digits = 0;
  bool after_point = false;
  for (; p < end && *p != 'e'; ++p) {
    if (*p == '.') {
      after_point = true;
      continue;
    }
    d.mantissa = d.mantissa * 10 + (*p - '0');
    fraction_digits += after_point;
  }
  if (p == end) return std::nullopt;
  ++p;  // 'e'
  const bool negative_exponent = *p == '-';
  if (*p == '-' || *p == '+') ++p;
  int e = 0;
  if (std::from_chars(p, end, e).ec != std::errc()) return std::nullopt;
  d.exponent = (negative_exponent ? -e : e) - fraction_digits;
  if (negative) d.mantissa = -d.mantissa;
  return d;
}

// x 10^k, or nullopt past 10^18 (k >= 0)
constexpr std::int64_t kDecimalLimit = 1'000'000'000'000'000'000;
std::optional<std::int64_t> times_power_of_ten(std::int64_t x, int k) {
  for (int i = 0; i < k; ++i) {
    if (x > kDecimalLimit / 10 || x < -kDecimalLimit / 10) return std::nullopt;
    x *= 10;
  }
  return x;
}

// The double nearest to the decimal m 10^e (as std::from_chars reads "me+e").
std::optional<double> decimal_value(std::int64_t m, int e) {
  char buf[48];
  char* p = std::to_chars(buf, buf + 24, m).ptr;
  *p++ = 'e';
  p = std::to_chars(p, buf + sizeof buf, e).ptr;
  double x = 0.0;
  if (std::from_chars(buf, p, x).ec != std::errc()) return std::nullopt;
  return x;
}

// linear_grid's decimal construction (sweep_grid.h); nullopt where it does not apply.
std::optional<std::vector<double>> decimal_linear_grid(double lo, double hi, int n) {
  const auto a = shortest_decimal(lo), b = shortest_decimal(hi);
  if (!a || !b) return std::nullopt;
  const int s = std::min(a->exponent, b->exponent);
  const auto L = times_power_of_ten(a->mantissa, a->exponent - s);
  const auto H = times_power_of_ten(b->mantissa, b->exponent - s);
  if (!L || !H) return std::nullopt;
  const std::int64_t intervals = n - 1;
  for (int j = 0; j <= 18; ++j) {
    const auto Lj = times_power_of_ten(*L, j), Hj = times_power_of_ten(*H, j);
    if (!Lj || !Hj) return std::nullopt;
    const std::int64_t span = *Hj - *Lj;  // both within 10^18: no overflow
    if (span % intervals != 0) continue;
    const std::int64_t step = span / intervals;
    std::vector<double> g(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const auto x = decimal_value(*Lj + i * step, s - j);
      if (!x) return std::nullopt;
      g[static_cast<std::size_t>(i)] = *x;
    }
    return g;
  }
  return std::nullopt;
}

}  // namespace

std::vector<double> linear_grid(double lo, double hi, int n) {
  if (n <= 0) return {};
  if (n == 1) return {lo};
  if (auto g = decimal_linear_grid(lo, hi, n)) return *g;
  std::vector<double> g(n);
  if (std::isfinite(hi - lo)) {
    for (int i = 0; i < n; ++i) g[i] = lo + (hi - lo) * i / (n - 1);
  } else {  // -1.5e308:1.7e308: the span overflows, the weighted ends do not
    for (int i = 0; i < n; ++i) g[i] = lo / (n - 1) * (n - 1 - i) + hi / (n - 1) * i;
  }
  g.front() = lo;
  g.back() = hi;
  return g;
}

std::vector<double> log_grid(double lo, double hi, int n) {
  if (n <= 0) return {};
  std::vector<double> g(n);
  const double a = std::log(lo), b = std::log(hi);
  for (int i = 0; i < n; ++i) g[i] = n == 1 ? lo : std::exp(a + (b - a) * i / (n - 1));
  g.front() = lo;
  g.back() = hi;
  return g;
}

// ---- points --------------------------------------------------------------------------------

namespace {

// Points per velocity and zeta: the product of the scene axes' sizes (1 without).
std::size_t axis_points(const SweepRequest& req) {
  std::size_t n = 1;
  for (const SceneAxis& a : req.axes) n *= a.values.size();
  return n;
}

// Zeta values: the grid's, or 1 when every point keeps the scene's own dashpot.
std::size_t zeta_count(const SweepRequest& req) {
  return req.scene_dashpot ? 1 : req.zetas.size();
}

// The value of every scene axis at the mixed-radix index `rest` (last axis fastest).
std::vector<double> axis_values(const SweepRequest& req, std::size_t rest) {
  std::vector<double> values(req.axes.size());
  for (std::size_t k = req.axes.size(); k-- > 0;) {
    const std::vector<double>& v = req.axes[k].values;
    values[k] = v[rest % v.size()];
    rest /= v.size();
  }
  return values;
}

void apply_axes(const SweepRequest& req, const std::vector<double>& values, Scene& scene) {
  for (std::size_t k = 0; k < req.axes.size(); ++k)
    set_scene_value(scene, req.axes[k].key, values[k]);
}

}  // namespace

GridPosition grid_position(const SweepRequest& req, std::size_t index) {
  const std::size_t na = axis_points(req), per_velocity = zeta_count(req) * na;
  return {index / per_velocity, index % per_velocity / na, index % na};
}

std::size_t point_count(const SweepRequest& req) {
  return req.velocities.size() * zeta_count(req) * axis_points(req);
}

SimulationRequest point_request(const SweepRequest& req, std::size_t index) {
  const GridPosition at = grid_position(req, index);
  SimulationRequest r = req.base;
  r.scene.velocity = req.velocities[at.velocity];
  if (!req.scene_dashpot) {
    const double zeta = req.zetas[at.zeta];
    r.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  }
  if (!req.axes.empty()) apply_axes(req, axis_values(req, at.axes), r.scene);
  return r;
}

void assign_point_request(const SweepRequest& req, std::size_t index, SimulationRequest& r) {
  if (!req.axes.empty()) {
    r = point_request(req, index);
    return;
  }
  const GridPosition at = grid_position(req, index);
  r.scene.velocity = req.velocities[at.velocity];
  if (!req.scene_dashpot) {
    const double zeta = req.zetas[at.zeta];
    r.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  }
}

PointInputs point_inputs(const SweepRequest& req, std::size_t index) {
  const GridPosition at = grid_position(req, index);
  PointInputs p{req.velocities[at.velocity], 0.0, axis_values(req, at.axes)};
  if (!req.scene_dashpot) {
    p.zeta = req.zetas[at.zeta];
    return p;
  }
  Scene s = req.base.scene;  // the scene dashpot's zeta depends on v0 and on the axes
  s.velocity = p.v0;
  apply_axes(req, p.axes, s);
  // a finite plate has no dashpot: no zeta (derive() gives the infinite plate's)
  p.zeta = has_finite_plate(s) ? std::numeric_limits<double>::quiet_NaN() : derive(s).zeta;
  return p;
}

ValidatedRequest ValidatedRequest::grid_point(const SweepRequest& /*grid: validated*/,
                                              const SimulationRequest& point) {
  return ValidatedRequest(point, Trusted{});
}

ValidatedRequest ValidatedRequest::grid_point(const SweepRequest& /*grid: validated*/,
                                              const SimulationRequest& point,
                                              const DerivedParameters& derived) {
  return ValidatedRequest(point, derived, Trusted{});
}

SweepPointRequests::SweepPointRequests(const SweepRequest& req) : request_(&req) {
  if (!req.axes.empty() || req.scene_dashpot || has_finite_plate(req.base.scene)) return;
  shared_.emplace(req.base.scene);
  velocity_factors_.reserve(req.velocities.size());
  for (double v0 : req.velocities) velocity_factors_.push_back(zener_velocity_factor(v0));
}

DerivedParameters SweepPointRequests::derived(std::size_t index,
                                              const SimulationRequest& point) const {
  if (!shared_) return derive(point.scene);
  const GridPosition at = grid_position(*request_, index);
  return shared_->at(velocity_factors_[at.velocity], request_->zetas[at.zeta]);
}

ValidatedRequest SweepPointRequests::validated(std::size_t index,
                                               const SimulationRequest& point) const {
  if (!shared_) return ValidatedRequest::grid_point(*request_, point);
  return ValidatedRequest::grid_point(*request_, point, derived(index, point));
}

}  // namespace ivv
