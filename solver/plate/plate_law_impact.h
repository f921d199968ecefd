// A finite-plate impact (plate_impact.h) of any rate-independent contact law given as a C++ object:
// an expression law, a law of a user, or a built-in law. simulate_plate_impact(scene, LawKind,
// ...) is this path for the built-in law of that kind: one setup per scene (the plate, the scales,
// omega_s, C_static; detail::plate_setup), one run per cut-off (detail::plate_impact_at_cutoff),
// one choice of the stepper (detail::run_plate_driver). plate_law_test.cc holds the two front
// doors to the same result, mode count included.
//
// The law must model ContactLaw (solver/laws/law.h), be rate-independent (the plate's contact
// force solves F = f(z_kin - C_res F) at zdot = 0) and clamp its force at F >= 0 (contacts end at
// F = 0, then the flight is free): InputError("--law") otherwise. The energy ledger is checked
// by the driver at every event for a law with a closed-form hysteresis_work; for one without (an
// expression law) the plastic work W_p is computed once at the end from the law itself,
//   W_p = int_0^{z_M} F_loading(s) ds - int_{z_f}^{z_M} F_unloading(s; z_M) ds
// (adaptive Gauss-Kronrod to 1e-13; the law's own stored_energy may be a coarser quadrature),
// z_M the largest spring deformation (reloading below z_M retraces the unloading curve, so the
// spring's net work is that one loop), and the ledger closed there (energy.checks = 1).
#pragma once

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "solver/driver/event_locator.h"
#include "solver/laws/law.h"
#include "solver/plate/exponential_stepper.h"
#include "solver/plate/odeint_dense_stepper.h"
#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_impact_driver.h"
#include "solver/plate/plate_modes.h"
#include "solver/plate/plate_truncation.h"
#include "solver/steppers/dop853.h"

namespace ivv {

namespace detail {

// The law's own scale basis, else the yield scales when the scene has a yield strength.
template <class Law>
ScaleBasis plate_scale_basis(const DerivedParameters& p) {
  if constexpr (requires { Law::scale_basis; })
    return Law::scale_basis;
  else
    return p.has_yield() ? ScaleBasis::yield : ScaleBasis::hertz;
}

// W_p of a law without a closed-form hysteresis work, at the largest deformation z_M [m] (header).
template <class Law>
double plate_plastic_work(const Law& law, double z_M) {
  history_t<Law, double> h{};
  double loading = 0.0, from = 0.0;
  auto area = [&](double a, double b) {  // under the current branch of h
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double s) { return std::max(law.force(h, s, 0.0), 0.0); }, a, b, 15, 1e-13);
  };
  while (auto end = law_segment_end(law, h)) {  // each loading segment on its own branch
    if (*end >= z_M) break;
    loading += area(from, *end);
    from = *end;
    law_next_segment(law, h);
  }
  loading += area(from, z_M);
  law_begin_unloading(law, h, z_M);
  return loading - area(static_cast<double>(h.z_perm), z_M);
}

template <class Law>
void close_plate_ledger(const Law& law, PlateImpactResult& out) {
  if (!out.ok || out.energy.checks > 0 || !std::isfinite(out.z_max)) return;
  out.energy.plastic = plate_plastic_work(law, out.z_max);
  const PlateEnergy& e = out.energy;
  out.energy.max_error = std::abs(e.initial - e.kinetic - e.plate - e.plastic) / e.initial;
  out.energy.checks = 1;
}

}  // namespace detail

// Throws InputError("structure") for a scene without a finite plate (or with a free target).
inline void require_finite_plate(const Scene& scene) {
  if (scene.damping.kind != Damping::Kind::structure || !scene.damping.structure.finite_plate())
    throw InputError("structure",
                     "a finite plate impact needs [structure] kind = \"plate\" with length_x, "
                     "length_y and edges");
  if (scene.free_target())
    throw InputError("target.mass", "a free target sphere and a finite plate are two targets");
}

// Throws InputError for a law the plate does not model (header) or a scene without a finite plate.
template <class Law>
void require_plate_law(const Law& law, const Scene& scene) {
  require_finite_plate(scene);
  if (Law::rate_dependent)
    throw InputError("--law", std::string(Law::name) +
                                  ": a rate-dependent law is not modelled on a finite plate "
                                  "(its contact force is solved at zdot = 0); accepted: "
                                  "rate-independent laws");
  if (law_allows_tension(law))
    throw InputError("--allow-tension",
                     "a law with tension is not modelled on a finite plate (its contacts end "
                     "at F = 0, then the flight is free)");
}

namespace detail {

// What the runs of one impact at different cut-offs share, computed once per scene: the plate,
// the law's scales, the rate omega_s the cut-off multiplies (plate_impact.h: max(1/T,
// sqrt(k_H g_max))) and C_static.
struct PlateSetup {
  FinitePlate plate;
  Scales scales;
  double omega_s = 0.0;  // [rad/s]
  StaticCompliance static_compliance;
};

template <class Law>
PlateSetup plate_setup(const Scene& scene, const DerivedParameters& p) {
  PlateSetup s{finite_plate(scene.damping.structure, scene.target_youngs_modulus,
                            scene.target_poisson_ratio),
               scales(scene, p, plate_scale_basis<Law>(p)),
               0.0,
               {}};
  const double z_mH =
      std::pow(5.0 * p.effective_mass * scene.velocity * scene.velocity / (4.0 * p.K_h), 0.4);
  const double k_H = 1.5 * p.K_h * std::sqrt(z_mH);
  s.omega_s = std::max(1.0 / s.scales.time, std::sqrt(k_H * 4.0 / s.plate.mass()));
  s.static_compliance = plate_static_compliance(s.plate);
  return s;
}

// The driver on the stepper opt.stepper names: the one place a plate run chooses its stepper.
template <class Law>
void run_plate_driver(const Law& law, const Scales& k, const PlateModes& modes, double m,
                      const PlateImpactOptions& opt, PlateImpactResult& out) {
  using System = PlateSystem<Law>;
  switch (opt.stepper) {
    case PlateImpactOptions::Stepper::dop853:
      PlateImpactDriver<Law, Dop853Stepper<System>>(law, k, modes, m, opt).run(out);
      return;
    case PlateImpactOptions::Stepper::odeint_dopri5:
      PlateImpactDriver<Law, OdeintDenseDopri5<System>>(law, k, modes, m, opt).run(out);
      return;
    case PlateImpactOptions::Stepper::exponential:
      // No mode kept (cut-off 0, the quasi-static plate): nothing to propagate exactly, and the
      // stepper's modal tables would be empty; the impactor against C_static alone is a
      // two-state ODE, stepped by dop853.
      if (modes.modes.empty())
        PlateImpactDriver<Law, Dop853Stepper<System>>(law, k, modes, m, opt).run(out);
      else
        PlateImpactDriver<Law, PlateExponentialStepper<System>>(law, k, modes, m, opt).run(out);
      return;
  }
}

// One impact at the cut-off `cutoff` (multiples of omega_s; 0: no modes, static compliance).
template <class Law>
PlateImpactResult plate_impact_at_cutoff(const Law& law, const PlateSetup& setup,
                                         const DerivedParameters& p, const PlateImpactOptions& opt,
                                         double cutoff) {
  PlateModes modes;
  // no mode kept: the plate is static (plate_regime.h's quasi-static model), whatever opt.dropped
  PlateImpactOptions run = opt;
  DroppedModes dropped = opt.dropped.value_or(DroppedModes::static_compliance);
  if (cutoff == 0.0) {
    modes = static_plate_modes(setup.plate);
    if (dropped == DroppedModes::oscillator) dropped = DroppedModes::static_compliance;
  } else {
    PlateModeOptions mo;
    mo.omega_cut = cutoff * setup.omega_s;
    mo.max_modes = opt.max_modes;
    mo.static_compliance = setup.static_compliance;
    mo.residual_moment = dropped == DroppedModes::oscillator;
    modes = plate_modes(setup.plate, mo);
  }
  run.dropped = dropped;
  PlateImpactResult out;
  out.dropped = dropped;
  out.mode_count = modes.modes.size();
  out.cutoff = cutoff;
  out.omega_cut = modes.omega_cut;
  out.static_compliance = modes.static_compliance.value;
  out.residual_compliance = dropped == DroppedModes::truncated ? 0.0 : modes.residual_compliance;
  if (dropped == DroppedModes::oscillator) out.residual_omega = residual_oscillator(modes).omega;
  out.plate_mass = setup.plate.mass();
  catching_plate_failures(out, [&] {
    if constexpr (!Law::rate_dependent)
      run_plate_driver(law, setup.scales, modes, p.effective_mass, run, out);
    close_plate_ledger(law, out);
  });
  return out;
}

// The impact at opt.cutoff, or with opt.truncation_tol > 0 at the cut-off the rule of
// plate_truncation.h chooses for it.
template <class Law>
PlateImpactResult plate_impact(const Law& law, const Scene& scene, const DerivedParameters& p,
                               const PlateImpactOptions& opt) {
  if (!(opt.truncation_tol >= 0.0 && std::isfinite(opt.truncation_tol)))
    throw std::invalid_argument("PlateImpactOptions::truncation_tol must be finite and >= 0");
  const PlateSetup setup = plate_setup<Law>(scene, p);
  PlateImpactOptions run = opt;  // the dropped modes: the options', else the scene's
  if (!run.dropped)
    run.dropped = scene.damping.structure.dropped_modes.value_or(DroppedModes::static_compliance);
  if (!(run.truncation_tol > 0.0 && run.cutoff > 0.0))
    return plate_impact_at_cutoff(law, setup, p, run, run.cutoff);
  return run_to_truncation_tolerance(
      run, [&](double c) { return plate_impact_at_cutoff(law, setup, p, run, c); },
      [&](double c) { return count_plate_modes(setup.plate, c * setup.omega_s); });
}

}  // namespace detail

// One impact of `law` on the scene's finite plate (header); with opt.truncation_tol > 0 the
// cut-off is chosen for it by the rule of plate_truncation.h, as for a built-in law.
template <class Law>
PlateImpactResult simulate_plate_impact_of(const Law& law, const Scene& scene,
                                           const PlateImpactOptions& opt = {}) {
  static_assert(assert_contact_law<Law, double>());
  validate(scene);
  require_plate_law(law, scene);
  return detail::plate_impact(law, scene, derive(scene), opt);
}

}  // namespace ivv
