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
// Onset is the initial state (alpha = 0, alpha_dot = v0). Capture is not an event but one of
// two criteria checked after each unloading step: (1) exact, for a dashpot and a law whose
// unloading curve has a slope floor (law.h): the state is inside the forward-invariant region
// of ImpactSystem::capture_margin, where the impactor keeps approaching for ever, by more than
// the accumulated error bound; then e = 0 exactly and the long creep towards z_f is not
// integrated; (2) by energy, for any dissipative law: when the rebound the remaining energy
// could still produce, sqrt(w^2 + 2 U), is below `capture_cor`, the impact ends with e = 0 and
// e <= that bound.
// Capture needs dissipation (a dashpot, or a rate-dependent law that carries its own): without
// it the unloading branch is conservative, the
// rebound speed is sqrt(2 U(z_m)) > 0 and the criterion is never applied (a bound that
// falls below capture_cor there is round-off in U, not physics).
// Grazing capture: with a dashpot, the force can reach zero while the impactor still
// approaches by less than the integration error (alpha_dot = +1e-13 v0 near the capture
// boundary). When that approach speed is within the accumulated error bound of
// consistency.h the impact is captured (e = 0) with e <= that bound; beyond it, a failure.
//
// Steppers with dense output are located on it directly. Steppers with a Hermite interpolant
// (dense_output == false) have the estimate refined by re-stepping to it and re-interpolating
// on the shrinking bracket until the time is converged to ~1e-14 relative; a refinement that
// does not converge, a root finder out of iterations or a failed re-step ends the run as a
// failure naming it.
//
// Every run that ends separated or captured passes the consistency check of consistency.h
// (three CORs, energy ledger) unless options.check_consistency is false.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "solver/consistency.h"
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
  long steps_alpha_max = 0;  // accepted steps when alpha_dot = 0 was reached
  double e_bound = 0;        // captured: the Newton COR is at most this (units of v0)
  struct Event {
    EventKind kind;
    T tau;
    state_type x;
    T force;  // normalised force on the branch in force when the event happened
  };
  std::vector<Event> events;
  long steps = 0;
};

// Re-steps of the Hermite event refinement before it is declared unconverged. Each re-step
// shrinks the bracket to a sub-bracket of the cubic interpolant's root, whose error falls as
// the fourth power of the bracket: from a step-sized bracket a few re-steps reach the ulp level.
inline constexpr int kMaxRefinements = 12;

template <class T>
struct Refinement {
  T tau{};              // refined event time
  std::string failure;  // empty when converged
};

// Refines an event time found on a Hermite interpolant: re-step exactly to the estimate,
// keep the sub-bracket that still contains the crossing, re-interpolate on it, repeat until
// the estimate moves by no more than a few ulps (1e-14 in double, 1e-48 in the 50-digit
// reference), or the bracket is that narrow, or the move changes the event state by less
// than one step's error tolerance (|dtau| max|x'| <= atol + rtol max|x|; the reference's
// tolerance for the 50-digit type): a grazing event, whose function barely changes sign, is
// ill-conditioned in time but not in state, and its time cannot be pinned to ulps. Not
// converged after kMaxRefinements re-steps, or a re-step that fails: `failure` says so.
template <class Stepper, class System, class EventValue>
Refinement<typename System::value_type> refine_on_restep(Stepper& stepper, const System& sys,
                                                         EventKind kind, Direction dir,
                                                         typename System::value_type te,
                                                         typename System::state_type& xe,
                                                         const EventValue& event_value,
                                                         const IntegratorOptions& opt) {
  using T = typename System::value_type;
  using state_type = typename System::state_type;
  const LocatorOptions& locator = opt.locator;
  auto abs_of = [](const T& v) { return v < 0 ? T(-v) : v; };
  const bool reference = std::numeric_limits<T>::digits > std::numeric_limits<double>::digits;
  const T atol = reference ? T(opt.reference_tolerance) : T(opt.atol);
  const T rtol = reference ? T(opt.reference_tolerance) : T(opt.rtol);
  // the state moves by |dtau| max|x'| when the time moves by dtau
  auto state_resolved = [&](const T& dtau, const state_type& x) {
    state_type f;
    sys(x, f, te);
    T f_max = 0, x_max = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      f_max = std::max(f_max, abs_of(f[i]));
      x_max = std::max(x_max, abs_of(x[i]));
    }
    return abs_of(dtau) * f_max <= atol + rtol * x_max;
  };
  T lo = stepper.t0(), hi = stepper.t1();
  state_type x_lo = stepper.x0(), f_lo = stepper.f0(), x_hi = stepper.x1(), f_hi = stepper.f1();
  LocatorOptions single = locator;
  single.samples = 1;
  state_type s;
  auto restep_failure = [&](const StepResult& r) {
    return Refinement<T>{te, std::string(Stepper::name) + ": re-step to refine the " +
                                 std::string(to_string(kind)) + " event failed: " + r.reason};
  };
  T change = hi - lo;
  for (int iteration = 0; iteration < kMaxRefinements; ++iteration) {
    if (const StepResult r = stepper.restep(sys, te, xe); !r.ok) return restep_failure(r);
    const T ge = event_value(kind, xe);
    if (is_pre_event(ge, dir)) {
      lo = te;
      x_lo = xe;
      sys(x_lo, f_lo, lo);
    } else {
      hi = te;
      x_hi = xe;
      sys(x_hi, f_hi, hi);
      if (ge == 0) return {te, {}};
    }
    auto g = [&](T t) {
      hermite_interpolate(lo, x_lo, f_lo, hi, x_hi, f_hi, t, s);
      return event_value(kind, s);
    };
    const auto next = locate_first_crossing(g, lo, hi, event_value(kind, x_lo), dir, single);
    if (!next) break;  // cannot happen: g(lo) is pre-event, g(hi) is not
    change = *next - te;
    te = *next;
    const T ulps = 64 * std::numeric_limits<T>::epsilon() * (1 + abs_of(te));
    if (abs_of(change) <= ulps || hi - lo <= ulps || state_resolved(change, xe)) {
      if (const StepResult r = stepper.restep(sys, te, xe); !r.ok) return restep_failure(r);
      return {te, {}};
    }
  }
  std::ostringstream os;
  os << Stepper::name << ": the " << to_string(kind)
     << " event at tau = " << static_cast<double>(te) << " did not converge in " << kMaxRefinements
     << " Hermite re-steps (last change " << static_cast<double>(change) << ", bracket width "
     << static_cast<double>(hi - lo)
     << "): re-steps of different lengths disagree, as when the step is too large for the "
        "scene's stiffness; use a smaller --dt or --rtol, or an implicit integrator";
  return {te, os.str()};
}

// The normalised measures of a finished run for consistency.h (before conversion to SI).
template <class System>
ConsistencyMeasures consistency_measures(const NormalisedRun<System>& run, const System& sys) {
  using T = typename System::value_type;
  auto d = [](const T& v) { return static_cast<double>(v); };
  const auto& x = run.x_end;
  ConsistencyMeasures m;
  m.steps = run.steps;
  m.restitution_steps = run.steps - run.steps_alpha_max;
  const double energy_scale = sys.force_scale * sys.length;  // m v0^2 [J]
  const double final_kinetic = 0.5 * d(x[System::W]) * d(x[System::W]);
  const double stored =
      d(sys.law.stored_energy(run.branch, T(sys.length * sys.z(x)))) / energy_scale;
  double viscous = 0.0;
  if constexpr (System::has_dashpot) viscous = d(x[System::WV]);
  double plastic = 0.0;
  if (auto closed = sys.law.hysteresis_work(run.branch))
    plastic = *closed / energy_scale;
  else
    plastic = d(x[System::WA]) - viscous - stored;
  m.ledger_residual = 0.5 - final_kinetic - stored - plastic - viscous;
  if (run.status == ImpactStatus::separated && run.has_max_displacement) {
    const T J_c = run.x_alpha_max[System::J];
    const T Wa_c = run.x_alpha_max[System::WA];
    m.has_restitution = true;
    m.e = -d(x[System::W]);
    m.e_poisson = d((x[System::J] - J_c) / J_c);
    m.e_energetic_sq = d((Wa_c - x[System::WA]) / Wa_c);
  }
  return m;
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
    return std::move(run);  // the run is done: move, no copy of its events
  };
  // A run that ends separated or captured at (tau_end, x_end), checked for consistency.
  auto finish = [&](ImpactStatus status, T tau_end, const state_type& x_end, double e_bound) {
    run.status = status;
    run.tau_end = tau_end;
    run.x_end = x_end;
    run.branch = sys.branch;
    run.steps = stepper.steps();
    run.e_bound = e_bound;
    if (status == ImpactStatus::captured)
      run.events.push_back({EventKind::capture, tau_end, x_end, sys.force(x_end)});
    if (!opt.check_consistency)
      return std::move(run);  // the run is done: move, no copy of its events
    const std::string why = consistency_failure(consistency_measures(run, sys), opt, Stepper::name);
    if (why.empty()) return std::move(run);  // the run is done: move, no copy of its events
    run.status = ImpactStatus::failed;
    run.failure = FailureKind::integrator;
    run.reason = why;
    return std::move(run);  // the run is done: move, no copy of its events
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

  // A dense-output stepper's step goes on past an event that changes no branch of the law
  // (max_displacement, peak_force: they only record the state): the rest of the same step is
  // scanned from the event on, rather than thrown away by a restart there. `resume` says so;
  // scan_t0/scan_x0 are where the scan of the current step starts.
  bool resume = false;
  T scan_t0 = 0;
  state_type scan_x0{};
  for (;;) {
    if (!resume) {
      if (stepper.steps() >= opt.max_steps) {
        std::ostringstream os;
        os << Stepper::name << ": no separation after max_steps = " << opt.max_steps
           << " steps (tau = " << static_cast<double>(stepper.t1()) << ")";
        // the advice fits the cause: stiffness comes from a strong dashpot (zeta > 1 puts the
        // dashpot time scale below the contact's), which an explicit stepper must resolve
        if (System::has_dashpot && sys.two_zeta > 2.0)
          os << "; a stiff scene (zeta = " << sys.two_zeta / 2
             << ") needs an implicit integrator (rodas4, odeint-rosenbrock4, gsl-msbdf)";
        else
          os << "; raise --max-steps or loosen --rtol";
        return fail(FailureKind::integrator, os.str());
      }
      if (stepper.t1() > opt.tau_max) {
        std::ostringstream os;
        os << Stepper::name << ": no separation before tau_max = " << opt.tau_max;
        return fail(FailureKind::integrator, os.str());
      }
      const StepResult step = stepper.step(sys);
      if (!step.ok) return fail(FailureKind::integrator, step.reason);
      scan_t0 = stepper.t0();
      scan_x0 = stepper.x0();
    }
    resume = false;
    const T t0 = scan_t0, t1 = stepper.t1();

    // events active on this branch
    std::array<Active, 4> active{};
    int n_active = 0;
    const bool loading = sys.branch.phase == Phase::loading;
    // z - z_y is monotone over a loading step on which dz/dtau > 0 at both ends: while z' > 0,
    // z'' < 0 (see `monotone` above), so z' cannot dip below 0 and come back within the step.
    // Only a step that also reaches maximum compression needs the yield event probed (and,
    // for a dense-output stepper, its interpolant built on every loading step otherwise).
    if (loading && sys.law.segment_end(sys.branch)) {
      const bool z_rising = sys.z_rate(scan_x0) > 0 && sys.z_rate(stepper.x1()) > 0;
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
        xk = &scan_x0;
      else if (k == n)
        xk = &stepper.x1();
      else
        stepper.interpolate(sys, tp[k], s);
      for (int i = 0; i < n_active; ++i) gp[k][i] = event_value(active[i].kind, *xk);
    }
    try {
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
          found[i] = solve_crossing(g, tp[k - 1], tp[k], gp[k - 1][i], gp[k][i], active[i].dir,
                                    opt.locator);
        } else {
          found[i] = t1;  // naive detection at the end of the step
        }
        if (!t_event || *found[i] < *t_event) {
          t_event = found[i];
          first = i;
        }
      }
    } catch (const EventLocationError& err) {
      return fail(FailureKind::integrator, std::string(Stepper::name) + ": " + err.what());
    }

    if (!t_event) {
      emit_samples(t0, t1);
      if constexpr (System::has_dashpot || System::rate_dependent) {  // something dissipates
        if (!loading) {
          // Exact capture: inside the invariant region of ImpactSystem::capture_margin, by more
          // than the accumulated error bound, the impactor never turns back (e = 0 exactly).
          const std::optional<double> margin = sys.capture_margin(stepper.x1());
          if (opt.exact_capture && margin &&
              *margin > accumulated_error_bound(stepper.steps(), opt))
            return finish(ImpactStatus::captured, t1, stepper.x1(), 0.0);
          const T bound2 = 2 * sys.recoverable_energy(stepper.x1());
          if (bound2 < T(opt.capture_cor) * T(opt.capture_cor)) {
            using std::sqrt;
            // e <= sqrt(2 U + w^2) < capture_cor; the threshold is the bound the criterion
            // guarantees when round-off makes the remaining energy read as zero
            return finish(
                ImpactStatus::captured, t1, stepper.x1(),
                std::max(static_cast<double>(sqrt(bound2 > 0 ? bound2 : T(0))), opt.capture_cor));
          }
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
      Refinement<T> refined;
      try {
        refined = refine_on_restep(stepper, sys, active[first].kind, active[first].dir, te, xe,
                                   event_value, opt);
      } catch (const EventLocationError& err) {
        return fail(FailureKind::integrator, std::string(Stepper::name) + ": " + err.what());
      }
      if (!refined.failure.empty()) return fail(FailureKind::integrator, refined.failure);
      te = refined.tau;
      // events of other kinds are judged at the refined state (same step)
    }
    emit_samples(t0, te);

    // Fire every armed event that has happened by te: coincident ones together (dz/dt = 0 and
    // dalpha/dt = 0 without a dashpot), and any whose function is already past at the event
    // state, which a restart there could no longer see.
    const T coincide = T(1e-12) * (1 + (te < 0 ? -te : te));
    bool separated = false;
    bool branch_changed = false;  // yield or max_compression: the law's next branch from te
    for (int i = 0; i < n_active; ++i) {
      const EventKind kind = active[i].kind;
      const bool happened = i == first || (found[i] && *found[i] <= te + coincide) ||
                            (armed[i] && !is_pre_event(event_value(kind, xe), active[i].dir));
      if (!happened) continue;
      run.events.push_back({kind, te, xe, sys.force(xe)});
      switch (kind) {
        case EventKind::yield:
          sys.law.next_segment(sys.branch);
          branch_changed = true;
          break;
        case EventKind::max_compression: {
          const T F = sys.force(xe);
          if (!System::rate_dependent) {
            run.F_max = F;
            run.tau_F_max = te;
          }
          run.tau_z_max = te;
          branch_changed = true;
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
          run.steps_alpha_max = stepper.steps();
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
      // integration error has exceeded it. With a dashpot and an approach speed within the
      // integration error this is the capture boundary: captured, e <= the error bound.
      // Otherwise say so rather than return a negative COR.
      const double graze_bound = accumulated_error_bound(stepper.steps(), opt);
      if (System::has_dashpot && static_cast<double>(xe[System::W]) <= graze_bound)
        return finish(ImpactStatus::captured, te, xe, graze_bound);
      std::ostringstream os;
      os << Stepper::name << ": contact force reached zero at tau = " << static_cast<double>(te)
         << " with the impactor still approaching (alpha_dot = +"
         << static_cast<double>(xe[System::W])
         << " v0): the integration error exceeds the remaining force; tighten --rtol or use "
            "another integrator";
      return fail(FailureKind::integrator, os.str());
    }
    if (separated) return finish(ImpactStatus::separated, te, xe, 0.0);
    if constexpr (Stepper::dense_output) {
      if (opt.locate_events && !branch_changed && te < t1) {
        resume = true;
        scan_t0 = te;
        scan_x0 = xe;
        continue;
      }
    }
    stepper.start(sys, te, xe);
  }
}

}  // namespace ivv
