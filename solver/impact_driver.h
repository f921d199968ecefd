// The phase loop shared by every integrator: integrate one smooth branch at a time, locate
// every event on the step's interpolant, restart at each event.
//
// Events (SPEC §1), all located by the shared locator of event_locator.h:
//   yield             z = end of the loading segment (elastoplastic: z_y)     rising
//   max_compression   dz/dt = 0: switch to unloading, record z_m and F_max    falling
//   max_displacement  dalpha/dt = 0: record alpha_c (after z_m when damped)   falling
//   peak_force        dF/dt = 0 (rate-dependent laws only, where F_max is not
//                     at z_m)                                                 falling
//   separation        F = 0 on the unloading branch: end of contact           falling
//                     (z = 0 instead for a law that allows tension)
// Onset is the initial state (alpha = 0, alpha_dot = v0). Capture is not an event but a
// criterion checked after each unloading step: when the rebound the remaining energy could
// still produce, sqrt(w^2 + 2 U), is below `capture_cor`, the impact ends with e = 0.
//
// Steppers with dense output are located on it directly. Steppers with a Hermite interpolant
// (dense_output == false) have the estimate refined by re-stepping to it and re-interpolating
// on the shrinking bracket until the time is converged to ~1e-14 relative.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "solver/event_locator.h"
#include "solver/hermite.h"
#include "solver/integrator_options.h"
#include "solver/law.h"
#include "solver/result.h"
#include "solver/steppers/step_result.h"

namespace ivv {

// A trajectory sample in normalised variables (tau, state); observers get these.
template <class System>
using SampleObserver =
    std::function<void(double tau, const typename System::state_type& x, const System& sys)>;

template <class System>
struct NormalisedRun {
  using T = typename System::value_type;
  using state_type = typename System::state_type;
  ImpactStatus status = ImpactStatus::failed;
  FailureKind failure = FailureKind::none;
  std::string reason;
  T tau_end = 0;
  state_type x_end{};
  typename System::history_type branch;  // final history (z_max, z_perm, ...)
  T tau_z_max = 0, F_max = 0, tau_F_max = 0;
  bool has_max_displacement = false;
  T tau_alpha_max = 0;
  state_type x_alpha_max{};  // state at alpha_dot = 0 (compression/restitution split)
  struct Event {
    EventKind kind;
    T tau;
    state_type x;
    T force;  // normalised force on the branch in force when the event happened
  };
  std::vector<Event> events;
  long steps = 0;
};

// Refines an event time found on a Hermite interpolant: re-step exactly to the estimate,
// keep the sub-bracket that still contains the crossing, re-interpolate on it, repeat.
template <class Stepper, class System, class EventValue>
typename System::value_type refine_on_restep(Stepper& stepper, const System& sys, EventKind kind,
                                             Direction dir, typename System::value_type te,
                                             typename System::state_type& xe,
                                             const EventValue& event_value,
                                             const LocatorOptions& locator) {
  using T = typename System::value_type;
  using state_type = typename System::state_type;
  T lo = stepper.t0(), hi = stepper.t1();
  state_type x_lo = stepper.x0(), f_lo = stepper.f0(), x_hi = stepper.x1(), f_hi = stepper.f1();
  LocatorOptions single = locator;
  single.samples = 1;
  state_type s;
  for (int iteration = 0; iteration < 12; ++iteration) {
    stepper.restep(sys, te, xe);
    const T ge = event_value(kind, xe);
    if (is_pre_event(ge, dir)) {
      lo = te;
      x_lo = xe;
      sys(x_lo, f_lo, lo);
    } else {
      hi = te;
      x_hi = xe;
      sys(x_hi, f_hi, hi);
      if (ge == 0) return te;
    }
    auto g = [&](T t) {
      hermite_interpolate(lo, x_lo, f_lo, hi, x_hi, f_hi, t, s);
      return event_value(kind, s);
    };
    const auto next = locate_first_crossing(g, lo, hi, event_value(kind, x_lo), dir, single);
    if (!next) break;
    const T change = *next - te;
    te = *next;
    // converged to a few ulps of T (1e-14 in double, 1e-48 in the 50-digit reference)
    const T ulps = 64 * std::numeric_limits<T>::epsilon();
    if ((change < 0 ? -change : change) <= ulps * (1 + (te < 0 ? -te : te))) break;
  }
  stepper.restep(sys, te, xe);
  return te;
}

template <class Stepper, class System>
NormalisedRun<System> run_impact(System& sys, const IntegratorOptions& opt,
                                 const SampleObserver<System>* observer = nullptr,
                                 int samples_per_step = 4) {
  using T = typename System::value_type;
  using state_type = typename System::state_type;
  NormalisedRun<System> run;
  Stepper stepper(opt);
  state_type x = System::initial_state();
  T tau = 0;
  sys.branch = typename System::history_type{};
  sys.tension = law_allows_tension(sys.law);
  stepper.start(sys, tau, x);
  // one allocation per impact: onset, yield, max_compression, max_displacement, peak_force and
  // separation or capture, with room for a law with more segments
  run.events.reserve(8);
  run.events.push_back({EventKind::onset, tau, x, sys.force(x)});
  if (observer) (*observer)(0.0, x, sys);
  bool peak_fired = false;

  // `monotone`: the event function cannot return to its pre-event side within a phase, so
  // the signs at the step's ends decide whether it crossed and no probing is needed:
  //   max_displacement  w' = -F <= 0 during contact
  //   max_compression   while z' > 0, z'' = -F - 2 zeta F_z z' < 0 (and z' = w without dashpot)
  //   separation        rate-independent laws: F falls with z, and z' < 0 on unloading (no
  //                     reloading during one contact, SPEC §1); not so for Hunt-Crossley
  // z - z_y (the spring may pass z_y and come back within one step near maximum compression)
  // and dF/dt are not monotone and are probed.
  struct Active {
    EventKind kind;
    Direction dir;
    bool monotone;
  };
  auto event_value = [&sys](EventKind k, const state_type& s) -> T {
    switch (k) {
      case EventKind::yield:
        return sys.z(s) - T(*sys.law.segment_end(sys.branch) / sys.length);
      case EventKind::max_compression:
        return sys.z_rate(s);
      case EventKind::max_displacement:
        return s[System::W];
      case EventKind::peak_force:
        return sys.force_rate(s);
      default:  // separation: F = 0, or z = 0 for a law that allows tension
        return sys.tension ? sys.z(s) : sys.force(s);
    }
  };
  auto fail = [&](FailureKind kind, std::string why) {
    run.status = ImpactStatus::failed;
    run.failure = kind;
    run.reason = std::move(why);
    run.tau_end = stepper.t1();
    run.x_end = stepper.x1();
    run.branch = sys.branch;
    run.steps = stepper.steps();
    return run;
  };
  auto emit_samples = [&](T a, T b) {
    if (!observer) return;
    state_type s;
    for (int k = 1; k <= samples_per_step; ++k) {
      const T t = a + (b - a) * k / samples_per_step;
      stepper.interpolate(sys, t, s);
      (*observer)(static_cast<double>(t), s, sys);
    }
  };

  for (;;) {
    if (stepper.steps() >= opt.max_steps) {
      std::ostringstream os;
      os << Stepper::name << ": no separation after max_steps = " << opt.max_steps
         << " steps (tau = " << static_cast<double>(stepper.t1())
         << "); a stiff scene (large zeta) needs an implicit integrator "
            "(odeint-rosenbrock4, gsl-msbdf)";
      return fail(FailureKind::integrator, os.str());
    }
    if (stepper.t1() > opt.tau_max) {
      std::ostringstream os;
      os << Stepper::name << ": no separation before tau_max = " << opt.tau_max;
      return fail(FailureKind::integrator, os.str());
    }
    const StepResult step = stepper.step(sys);
    if (!step.ok) return fail(FailureKind::integrator, step.reason);
    const T t0 = stepper.t0(), t1 = stepper.t1();

    // events active on this branch
    std::array<Active, 4> active{};
    int n_active = 0;
    const bool loading = sys.branch.phase == Phase::loading;
    // z - z_y is monotone over a loading step on which dz/dtau > 0 at both ends: while z' > 0,
    // z'' < 0 (see `monotone` above), so z' cannot dip below 0 and come back within the step.
    // Only a step that also reaches maximum compression needs the yield event probed (and,
    // for a dense-output stepper, its interpolant built on every loading step otherwise).
    if (loading && sys.law.segment_end(sys.branch)) {
      const bool z_rising = sys.z_rate(stepper.x0()) > 0 && sys.z_rate(stepper.x1()) > 0;
      active[n_active++] = {EventKind::yield, Direction::rising, z_rising};
    }
    if (loading) active[n_active++] = {EventKind::max_compression, Direction::falling, true};
    if (!run.has_max_displacement)
      active[n_active++] = {EventKind::max_displacement, Direction::falling, true};
    if (System::rate_dependent && !peak_fired)
      active[n_active++] = {EventKind::peak_force, Direction::falling, false};
    if (!loading)
      active[n_active++] = {EventKind::separation, Direction::falling,
                            !System::rate_dependent && !sys.tension};

    // Earliest crossing among them. When a non-monotone function is active the step is probed
    // at `samples` equal subintervals (so that a function returning to its pre-event side
    // within the step is not missed); each probe state is interpolated once and shared by all
    // event functions. Only the earliest bracketing subinterval is then solved, for the
    // functions that cross in it.
    bool probe = false;
    for (int i = 0; i < n_active; ++i) probe = probe || !active[i].monotone;
    const int n = opt.locate_events && probe
                      ? std::clamp(opt.locator.samples, 1, LocatorOptions::max_samples)
                      : 1;
    std::array<T, LocatorOptions::max_samples + 1> tp;
    std::array<std::array<T, 4>, LocatorOptions::max_samples + 1> gp;
    std::optional<T> t_event;
    int first = -1;
    std::array<std::optional<T>, 4> found{};
    std::array<bool, 4> armed{};
    state_type s;
    int first_sub = n + 1;
    std::array<int, 4> sub{};
    for (int k = 0; k <= n; ++k) {
      tp[k] = k == 0 ? t0 : k == n ? t1 : T(t0 + (t1 - t0) * k / n);
      const state_type* xk = &s;
      if (k == 0)
        xk = &stepper.x0();
      else if (k == n)
        xk = &stepper.x1();
      else
        stepper.interpolate(sys, tp[k], s);
      for (int i = 0; i < n_active; ++i) gp[k][i] = event_value(active[i].kind, *xk);
    }
    for (int i = 0; i < n_active; ++i) {
      armed[i] = is_pre_event(gp[0][i], active[i].dir);
      sub[i] = n + 1;
      if (!armed[i]) continue;
      for (int k = 1; k <= n; ++k)
        if (!is_pre_event(gp[k][i], active[i].dir)) {
          sub[i] = k;
          break;
        }
      first_sub = std::min(first_sub, sub[i]);
    }
    for (int i = 0; i < n_active; ++i) {
      if (sub[i] != first_sub || first_sub > n) continue;
      const int k = sub[i];
      if (opt.locate_events) {
        auto g = [&](T t) {
          stepper.interpolate(sys, t, s);
          return event_value(active[i].kind, s);
        };
        found[i] =
            solve_crossing(g, tp[k - 1], tp[k], gp[k - 1][i], gp[k][i], active[i].dir, opt.locator);
      } else {
        found[i] = t1;  // naive detection at the end of the step
      }
      if (!t_event || *found[i] < *t_event) {
        t_event = found[i];
        first = i;
      }
    }

    if (!t_event) {
      emit_samples(t0, t1);
      if (!loading) {
        const T bound2 = 2 * sys.recoverable_energy(stepper.x1());
        if (bound2 < T(opt.capture_cor) * T(opt.capture_cor)) {
          run.status = ImpactStatus::captured;
          run.tau_end = t1;
          run.x_end = stepper.x1();
          run.branch = sys.branch;
          run.events.push_back({EventKind::capture, t1, stepper.x1(), sys.force(stepper.x1())});
          run.steps = stepper.steps();
          return run;
        }
      }
      continue;
    }

    // state at the event
    T te = *t_event;
    state_type xe;
    if (!opt.locate_events) {
      xe = stepper.x1();
    } else if constexpr (Stepper::dense_output) {
      stepper.interpolate(sys, te, xe);
    } else {
      te = refine_on_restep(stepper, sys, active[first].kind, active[first].dir, te, xe,
                            event_value, opt.locator);
      // events of other kinds are judged at the refined state (same step)
    }
    emit_samples(t0, te);

    // Fire every armed event that has happened by te: coincident ones together (dz/dt = 0 and
    // dalpha/dt = 0 without a dashpot), and any whose function is already past at the event
    // state, which a restart there could no longer see.
    const T coincide = T(1e-12) * (1 + (te < 0 ? -te : te));
    bool separated = false;
    for (int i = 0; i < n_active; ++i) {
      const EventKind kind = active[i].kind;
      const bool happened = i == first || (found[i] && *found[i] <= te + coincide) ||
                            (armed[i] && !is_pre_event(event_value(kind, xe), active[i].dir));
      if (!happened) continue;
      run.events.push_back({kind, te, xe, sys.force(xe)});
      switch (kind) {
        case EventKind::yield:
          sys.law.next_segment(sys.branch);
          break;
        case EventKind::max_compression: {
          const T F = sys.force(xe);
          if (!System::rate_dependent) {
            run.F_max = F;
            run.tau_F_max = te;
          }
          run.tau_z_max = te;
          try {
            sys.law.begin_unloading(sys.branch, T(sys.length * sys.z(xe)));
          } catch (const LawDomainError& err) {
            return fail(FailureKind::law_domain, err.what());
          }
          break;
        }
        case EventKind::max_displacement:
          run.has_max_displacement = true;
          run.tau_alpha_max = te;
          run.x_alpha_max = xe;
          break;
        case EventKind::peak_force:
          peak_fired = true;
          run.F_max = sys.force(xe);
          run.tau_F_max = te;
          break;
        case EventKind::separation:
          separated = true;
          break;
        default:
          break;
      }
    }
    if (separated && xe[System::W] > 0) {
      // F = 0 while the impactor still approaches is no rebound: z would grow again and the
      // spring reload. In the exact solution the force is still (barely) positive; the
      // integration error has exceeded it. Say so rather than return a negative COR.
      std::ostringstream os;
      os << Stepper::name << ": contact force reached zero at tau = " << static_cast<double>(te)
         << " with the impactor still approaching (alpha_dot = +"
         << static_cast<double>(xe[System::W])
         << " v0): the integration error exceeds the remaining force; tighten --rtol or use "
            "another integrator";
      return fail(FailureKind::integrator, os.str());
    }
    if (separated) {
      run.status = ImpactStatus::separated;
      run.tau_end = te;
      run.x_end = xe;
      run.branch = sys.branch;
      run.steps = stepper.steps();
      return run;
    }
    stepper.start(sys, te, xe);
  }
}

}  // namespace ivv
