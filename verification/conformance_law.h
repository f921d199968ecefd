// A C++ contact law as the conformance checks see it.
//
//   auto law = ivv::conformance::law_under_test<MyLaw>(
//       "my-law", "F = ...", [](const ivv::Scene& s) { return MyLaw{...}; });
//   ivv::conformance::Report r = run_conformance(law, claims, default_grid(ivv::paper_scene()));
//
// `make_law(scene)` builds the law for one scene (its constants may depend on E*, R, m, v0).
// A law templated on its scalar gets its stiffness checked by automatic differentiation and
// its dynamic results compared with the 50-digit reference.
#pragma once

#include <boost/math/differentiation/autodiff.hpp>
#include <memory>
#include <string>
#include <utility>

#include "solver/simulate_law.h"
#include "verification/conformance.h"

namespace ivv::conformance {

template <class Law>
class TypedProbe final : public LawProbe {
 public:
  explicit TypedProbe(Law law) : law_(std::move(law)) {}

  double force(double z, double v) const override { return law_.force(h_, z, v); }
  double stiffness(double z, double v) const override { return law_.stiffness(h_, z, v); }
  double rate_stiffness(double z, double v) const override { return law_.rate_stiffness(h_, z, v); }
  std::optional<std::pair<double, double>> autodiff_slopes(double z, double v) const override {
    using Ad = boost::math::differentiation::autodiff_v1::detail::fvar<double, 1>;
    if constexpr (law_supports_scalar<Law, Ad>) {
      // replay the history on the autodiff scalar (z_max a constant), then differentiate
      history_t<Law, Ad> h{};
      for (int k = 0; k < segments_; ++k) law_next_segment(law_, h);
      if (unloading_) law_begin_unloading(law_, h, Ad(z_max_));
      const Ad dz = law_.force(h, boost::math::differentiation::make_fvar<double, 1>(z), Ad(v));
      const Ad dv = law_.force(h, Ad(z), boost::math::differentiation::make_fvar<double, 1>(v));
      return std::pair{dz.derivative(1), dv.derivative(1)};
    } else {
      return std::nullopt;
    }
  }
  std::optional<double> segment_end() const override { return law_segment_end(law_, h_); }
  void next_segment() override {
    law_next_segment(law_, h_);
    ++segments_;
  }
  void begin_unloading(double z_max) override {
    law_begin_unloading(law_, h_, z_max);
    unloading_ = true;
    z_max_ = z_max;
  }
  double permanent_set() const override { return static_cast<double>(h_.z_perm); }
  double stored_energy(double z) const override { return law_.stored_energy(h_, z); }
  bool stored_energy_is_quadrature() const override {
    return !law_supports_scalar<Law, long double>;  // expression laws integrate it themselves
  }
  std::optional<double> onset_force() const override { return declared_onset_force(law_); }
  void reset() override {
    h_ = {};
    segments_ = 0;
    unloading_ = false;
  }

 private:
  Law law_;
  history_t<Law, double> h_{};
  int segments_ = 0;
  bool unloading_ = false;
  double z_max_ = 0.0;
};

// Wraps a C++ law: `make_law(const Scene&) -> Law`. A Law that does not model ContactLaw is a
// compile error naming the member at fault (solver/laws/law.h).
template <class Law, class MakeLaw>
LawUnderTest law_under_test(std::string name, std::string description, MakeLaw make_law) {
  static_assert(assert_contact_law_everywhere<Law>());
  LawUnderTest t;
  t.name = std::move(name);
  t.description = std::move(description);
  t.rate_dependent = Law::rate_dependent;
  t.runs_in_reference = law_supports_scalar<Law, mp50>;
  const Scene probe_scene = paper_scene();
  t.allows_tension = law_allows_tension(make_law(probe_scene));
  t.probe = [make_law](const Scene& s) -> std::unique_ptr<LawProbe> {
    return std::make_unique<TypedProbe<Law>>(make_law(s));
  };
  t.simulate = [make_law](const Scene& s, IntegratorKind k, const IntegratorOptions& o) {
    return ivv::simulate(make_law(s), s, k, o);
  };
  t.trajectory = [make_law](const Scene& s, const IntegratorOptions& o) {
    std::vector<TrajectoryPoint> points;
    ivv::simulate(make_law(s), s, IntegratorKind::dp45, o, &points);
    return points;
  };
  return t;
}

}  // namespace ivv::conformance
