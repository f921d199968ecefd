// Internals of simulate(): the typed run for one stepper and its conversion to SI units.
// Included by one translation unit per integrator (generated from
// solver/steppers/integrator_list.h, see solver/steppers/integrator_instance_impl.h) to spread
// compile time.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/driver/capture_end_state.h"
#include "solver/driver/impact_driver.h"
#include "solver/driver/impact_system.h"
#include "solver/laws/expression.h"
#include "solver/laws/law_registry.h"
#include "solver/simulate.h"
#include "solver/steppers/dop853.h"
#include "solver/steppers/dop853_fma.h"

namespace ivv::detail {

// `event_storage`: an event list whose memory the result's events reuse (its contents are
// dropped), so that a caller that keeps its results (a sweep's batch) allocates none per impact.
template <class System>
ImpactResult to_physical(const NormalisedRun<System>& run, const System& sys, const Scene& scene,
                         const Scales& k, std::vector<ImpactEvent>&& event_storage = {}) {
  // the 50-digit reference reports in double, like everything else
  auto d = [](const auto& v) { return static_cast<double>(v); };
  const double L = sys.length, V = scene.velocity, Fs = sys.force_scale;
  const double Ts = k.time;
  const double E = k.energy;             // m* v0^2
  const double momentum = k.energy / V;  // m* v0
  ImpactResult r;
  r.events = std::move(event_storage);
  r.events.clear();
  r.status = run.status;
  r.failure = run.failure;
  r.reason = run.reason;
  r.e_bound = run.e_bound;
  r.steps = run.steps;
  r.rhs_evaluations = sys.rhs_evaluations;
  r.events.reserve(run.events.size());
  for (const auto& ev : run.events) {
    r.events.push_back(
        {ev.kind, d(ev.tau) * Ts, d(sys.z(ev.x)) * L, d(ev.x[System::A]) * L, d(ev.force) * Fs});
  }
  const auto& x = run.x_end;
  r.t_contact = d(run.tau_end) * Ts;
  r.rebound_velocity = d(x[System::W]) * V;
  const BodyVelocities bodies = body_velocities_after(scene, r.rebound_velocity);
  r.impactor_velocity_after = bodies.impactor;
  r.target_velocity_after = bodies.target;
  r.z_max = d(run.branch.z_max);
  r.t_z_max = d(run.tau_z_max) * Ts;
  r.F_max = d(run.F_max) * Fs;
  r.t_F_max = d(run.tau_F_max) * Ts;
  r.z_perm = d(run.branch.z_perm);
  r.y_final = d(sys.y(x)) * L;
  if (run.has_max_displacement) {
    r.alpha_max = d(run.x_alpha_max[System::A]) * L;
    r.t_alpha_max = d(run.tau_alpha_max) * Ts;
  } else {
    r.alpha_max = d(x[System::A]) * L;
    r.t_alpha_max = r.t_contact;
  }
  r.impulse = d(x[System::J]) * momentum;
  r.pull_off_work = sys.pull_off_work * E;
  if (run.status == ImpactStatus::failed) return r;

  const double w_f = d(x[System::W]);
  r.e = run.status == ImpactStatus::separated ? -w_f : 0.0;
  if (run.has_max_displacement) {
    // differences taken in T before rounding
    const auto J_c = run.x_alpha_max[System::J];
    const auto Wa_c = run.x_alpha_max[System::WA];
    r.impulse_compression = d(J_c) * momentum;
    r.e_poisson = d((x[System::J] - J_c) / J_c);
    r.e_energetic = std::sqrt(std::max(0.0, d((Wa_c - x[System::WA]) / Wa_c)));
  }
  EnergyLedger& led = r.energy;
  led.initial = 0.5 * E;
  led.final = 0.5 * E * w_f * w_f;
  led.stored = d(sys.law.stored_energy(run.branch, sys.z(x) * L));
  if constexpr (System::has_dashpot) led.viscous = d(x[System::WV]) * E;
  if (auto closed = sys.law.hysteresis_work(run.branch)) {
    led.plastic = *closed;
  } else {
    led.plastic = d(x[System::WA]) * E - led.viscous - led.stored;
    led.plastic_integrated = true;
  }
  led.residual = led.initial - led.final - led.stored - led.plastic - led.viscous;
  // a captured impact reports where it ends, not the state when capture was declared
  if (run.status == ImpactStatus::captured) {
    const double m = momentum / V;
    // m* omega/c = two_zeta with omega = 1/Ts, so c = m*/(two_zeta Ts)
    const double c =
        System::has_dashpot ? m / (sys.two_zeta * Ts) : std::numeric_limits<double>::infinity();
    // without a dashpot a rate-independent law is captured only by its well (capture.h): the
    // impactor keeps what it has as a bound oscillation, not dissipated
    settle_captured(
        r, scene,
        {m, c, run.has_max_displacement, !System::has_dashpot && !System::rate_dependent});
  }
  return r;
}

// The scales a law normalises with: its own Law::scale_basis; a law that states none uses the
// yield scales when the scene has a yield strength and the Hertz scales otherwise.
template <class Law>
ScaleBasis scale_basis_for(const DerivedParameters& p) {
  if constexpr (requires { Law::scale_basis; })
    return Law::scale_basis;
  else
    return p.has_yield() ? ScaleBasis::yield : ScaleBasis::hertz;
}

// The normalised system of one impact of `law` in the scales k (scales_for).
template <class System>
void set_up_system(System& sys, const typename System::law_type& law, const DerivedParameters& p,
                   const Scales& k) {
  sys.law = law;
  sys.length = k.length;
  sys.velocity = k.velocity;
  sys.force_scale = k.force;
  sys.inverse_force_scale = 1.0 / k.force;
  // m* omega/c for the chosen omega (= 2 zeta when omega = omega0)
  sys.two_zeta = System::has_dashpot ? p.effective_mass / (k.time * p.c) : 0.0;
}

// The law's own scales, so that a tolerance means the same for every law and no law depends on
// a parameter it does not use (Hertz and Hunt-Crossley: no yield strength).
template <class Law>
Scales scales_for(const Scene& scene, const DerivedParameters& p) {
  return scales(scene, p, scale_basis_for<Law>(p));
}

template <template <class> class Stepper, class Law, bool Dashpot, class T = double>
ImpactResult run_typed(const Law& law, const Scene& scene, const IntegratorOptions& options,
                       const DerivedParameters& p, std::vector<TrajectoryPoint>* trajectory) {
  using System = ImpactSystem<Law, Dashpot, T>;
  const Scales k = scales_for<Law>(scene, p);
  System sys;
  set_up_system(sys, law, p, k);
  SampleObserver<System> observer;
  if (trajectory) {
    observer = [trajectory, k](double tau, const typename System::state_type& x, const System& s) {
      auto d = [](const auto& v) { return static_cast<double>(v); };
      const double F = d(s.force(x));
      const double shown = s.tension ? F : std::max(0.0, F);  // clamped unless tension
      TrajectoryPoint pt;
      pt.tau = tau;
      pt.t = tau * k.time;
      pt.alpha = d(x[System::A]) * k.length;
      pt.alpha_dot = d(x[System::W]) * k.velocity;
      pt.y = d(s.y(x)) * k.length;
      pt.z = d(s.z(x)) * k.length;
      pt.force = shown * k.force;
      pt.alpha_bar = d(x[System::A]);
      pt.force_bar = shown;
      trajectory->push_back(pt);
    };
  }
  const auto run = run_impact<Stepper<System>>(sys, options, trajectory ? &observer : nullptr);
  return to_physical(run, sys, scene, k);
}

// Whether run_law has the AVX2 + FMA copy of solver/steppers/dop853_fma.h for this stepper, law
// and scalar.
template <template <class> class Stepper, class Law, class T>
constexpr bool has_fma_clone() {
  using System = ImpactSystem<Law, true, double>;
  if constexpr (kHasFmaCopy<Law> && std::is_same_v<T, double>)
    return std::is_same_v<Stepper<System>, Dop853Stepper<System>>;
  else
    return false;
}

// One impact of `law` with stepper `Stepper` on scalar T: the dashpot (or its absence) chosen
// once here, and the machine code (solver/steppers/machine_code.h) where there is a choice. A law
// that does not run on T (an expression law in the 50-digit reference) is a failed result that says
// so, never a compile error.
template <template <class> class Stepper, class T = double, class Law>
ImpactResult run_law(const Law& law, const Scene& scene, const IntegratorOptions& options,
                     const DerivedParameters& p, std::vector<TrajectoryPoint>* trajectory) {
  if constexpr (!law_supports_scalar<Law, T>) {
    ImpactResult r;
    r.failure = FailureKind::law_domain;
    r.reason = std::string("the ") + std::string(Law::name) +
               " law runs in double precision only, so the 50-digit reference (mp50) cannot "
               "run it; compare with the tightest double-precision integrator instead";
    return r;
  } else if constexpr (Law::rate_dependent) {
    return run_typed<Stepper, Law, false, T>(law, scene, options, p, trajectory);
  } else {
    if constexpr (has_fma_clone<Stepper, Law, T>()) {
      if (machine_code_in_use(options.machine_code) == MachineCode::fastest)
        return run_dop853_fma(law, scene, options, p, trajectory);
    }
    return p.has_dashpot() ? run_typed<Stepper, Law, true, T>(law, scene, options, p, trajectory)
                           : run_typed<Stepper, Law, false, T>(law, scene, options, p, trajectory);
  }
}

// The expression law of a request, compiled (throws ExpressionError for a malformed one).
std::shared_ptr<const CompiledExpressions> compile_expression_law(const SimulationRequest& req,
                                                                  const DerivedParameters& p);

// Runs the expression law and turns a non-finite evaluation into a failure naming it.
template <class F>
ImpactResult run_expression_law(const ValidatedRequest& v, F&& run) {
  const SimulationRequest& req = v.request();
  const auto& compiled = v.expression();
  const bool tension = req.expression.allow_tension;
  ImpactResult r;
  try {
    r = compiled->uses_rate() ? run(ExpressionLaw<true>{compiled, tension})
                              : run(ExpressionLaw<false>{compiled, tension});
  } catch (const std::exception&) {
    // a NaN force reaches the root finders, which throw: the NaN is the reason to report
    if (!compiled->non_finite()) throw;
  }
  if (compiled->non_finite()) {
    r.status = ImpactStatus::failed;
    r.failure =
        compiled->non_finite_at_onset() ? FailureKind::law_domain : FailureKind::law_non_finite;
    r.reason = *compiled->non_finite();
  }
  return r;
}

template <template <class> class Stepper, class T = double>
ImpactResult simulate_with(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  const SimulationRequest& req = v.request();
  const DerivedParameters& p = v.derived();
  auto run = [&](const auto& law) {
    return run_law<Stepper, T>(law, req.scene, req.options, p, trajectory);
  };
  if (req.law == LawKind::expression) return run_expression_law(v, run);
  return with_builtin_law(req.law, req.parameters, p, run);
}

}  // namespace ivv::detail
