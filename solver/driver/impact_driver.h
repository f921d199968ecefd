// The phase loop shared by every integrator: integrate one smooth branch at a time, locate the
// events on each step's interpolant, restart at each event that changes the law's branch.
//
//   advance one step -> the active events (impact_events.h) -> locate_earliest on the step
//   (event_locator.h) -> none: the capture criteria (capture.h) after an unloading step, then
//                        the end series (end_series.h) and the cap on the next step
//                        (cap_step_before_separation)
//                     -> some: the event state, then act on what each event that happened means
//                        (record, next segment, begin unloading, end of contact) and restart
//
// The events, their root functions, directions and meanings are the table of impact_events.h;
// the capture criteria (exact, by energy, grazing) are the units of capture.h. Onset is the
// initial state (alpha = 0, alpha_dot = v0); the error-controlled steppers written here start
// past it, from the onset series, where the law declares a Hertzian onset (onset_series.h): at
// the yield when the series reaches it, the yield fired there, else inside the onset; and they
// end an elastic contact (a Hertzian unloading branch with no permanent set) by the same series
// run backwards from the separation (end_series.h) once a step ends within its reach.
//
// Steppers with dense output are located on it directly, and a step goes on past an event
// that changes no branch (max_displacement, peak_force: they only record the state): the rest
// of the same step is scanned from the event on, rather than thrown away by a restart there.
// Steppers with a Hermite interpolant (dense_output == false) have the estimate refined by
// re-stepping to it and re-interpolating on the shrinking bracket until the time is converged
// to ~1e-14 relative; a refinement that does not converge, a root finder out of iterations or
// a failed re-step ends the run as a failure naming it.
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
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/consistency.h"
#include "solver/driver/capture.h"
#include "solver/driver/dashpot_stall.h"
#include "solver/driver/end_series.h"
#include "solver/driver/event_locator.h"
#include "solver/driver/hermite.h"
#include "solver/driver/impact_events.h"
#include "solver/driver/linear_phase.h"
#include "solver/driver/onset_series.h"
#include "solver/laws/law.h"
#include "solver/result.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_controller.h"
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

// One impact integrated by Stepper: the phase loop of the comment at the top of this file.
template <class Stepper, class System>
class ImpactDriver {
 public:
  using T = typename System::value_type;
  using state_type = typename System::state_type;
  using Earliest = EarliestCrossing<T, ActiveEvents::capacity>;

  ImpactDriver(System& sys, const IntegratorOptions& opt, const SampleObserver<System>* observer,
               int samples_per_step)
      : sys_(sys),
        opt_(opt),
        observer_(observer),
        samples_per_step_(samples_per_step),
        stepper_(opt) {}
  // The same with the stepper given and no observer: one lane of the SIMD lanes
  // (lane_stepper.h), which the caller steps (begin, after_step, limit_reached below).
  ImpactDriver(System& sys, const IntegratorOptions& opt, Stepper stepper)
      : sys_(sys), opt_(opt), observer_(nullptr), samples_per_step_(0), stepper_(stepper) {}

  // Before begin(): the event list of a run finished before, whose memory this run's event list
  // reuses (its contents are dropped), so that a lane's impacts after the first allocate none.
  void reuse_event_storage(std::vector<typename NormalisedRun<System>::Event>&& storage) {
    run_.events = std::move(storage);
    run_.events.clear();
  }

  // What the run needs after a call of limit_reached() or after_step() below: the next step, or
  // nothing (the run is done: take_run()).
  enum class Next { step, done };

  NormalisedRun<System> run() {
    if (begin() == Next::step)
      while (limit_reached() == Next::step && after_step(stepper_.step(sys_)) == Next::step) {
      }
    return take_run();
  }

  // The run driven a step at a time by a caller that steps the stepper itself (the lanes,
  // lanes_driver.h), as run() does: begin(); then, before each step, limit_reached(), and after
  // each accepted or failed one, after_step(), until one says the run is done; then take_run().
  //
  // The start: the stepper started at onset, or past it from the onset series; done already
  // where the series and the closed form of a linear segment reach a capture at maximum
  // compression (cross_linear_segment).
  Next begin() {
    const state_type x = System::initial_state();
    const T tau = 0;
    sys_.branch = typename System::history_type{};
    sys_.tension = law_allows_tension(sys_.law);
    // one allocation per impact (none where the list came with storage): onset, yield,
    // max_compression, max_displacement, peak_force and separation or capture, with room for a
    // law with more segments
    run_.events.reserve(8);
    run_.events.push_back({EventKind::onset, tau, x, sys_.force(x)});
    if (observer_) (*observer_)(0.0, x, sys_);
    if constexpr (requires { Stepper::starts_from_onset_series; }) {
      if (const std::optional<SeriesStart> start = series_start()) {
        if (observer_) emit_series_samples(*start);
        // the solution's own time scale there is tau itself (F ~ tau^{3/2}): the step tried
        // first is that estimate times the controller's safety factor, as every step it
        // proposes (step_controller.h). Measured (dop853, rtol 1e-8, 60 x 60 paper map):
        // tau itself was rejected often enough that 0.9 tau takes 215.5 -> 212.5 right-hand
        // sides an impact (rejections of a first step 0.40 -> 0.18 an impact). From the yield
        // the same: 1.5, 2, 3 and 5 times it took 2566, 2530, 2542 and 2554 right-hand sides
        // against 2578 over 18 paper impacts (v0 0.5, 1, 3 m/s, rtol 1e-6 ... 1e-12), the luck
        // of where maximum compression falls in a step
        T h = T(StepControl::safety) * start->tau;
        if (start->at_segment_end) {
          h *= enter_next_segment_at(start->tau, start->x);
          if (const std::optional<Next> crossed = cross_linear_segment(start->tau, start->x))
            return *crossed;
        }
        stepper_.start(sys_, start->tau, start->x);
        stepper_.propose_step(h);
        return Next::step;
      }
    }
    stepper_.start(sys_, tau, x);
    return Next::step;
  }

  // The run failed by a limit before the next step (max_steps, tau_max): done.
  Next limit_reached() {
    if (stepper_.steps() >= opt_.max_steps) {
      std::ostringstream os;
      os << Stepper::name << ": no separation after max_steps = " << opt_.max_steps
         << " steps (tau = " << static_cast<double>(stepper_.t1()) << ")";
      // the advice fits the cause: stiffness comes from a strong dashpot (zeta > 1 puts the
      // dashpot time scale below the contact's), which an explicit stepper must resolve
      if (System::has_dashpot && sys_.two_zeta > 2.0)
        os << "; a stiff scene (zeta = " << sys_.two_zeta / 2
           << ") needs an implicit integrator (rodas4, odeint-rosenbrock4, gsl-msbdf)";
      else
        os << "; raise --max-steps or loosen --rtol";
      return fail(FailureKind::step_limit, os.str());
    }
    if (stepper_.t1() > opt_.tau_max) {
      std::ostringstream os;
      os << Stepper::name << ": no separation before tau_max = " << opt_.tau_max;
      return fail(FailureKind::time_limit, os.str());
    }
    return Next::step;
  }

  // The finished run (once, after one of the calls above said done): moved out, no copy of its
  // events.
  NormalisedRun<System> take_run() { return std::move(run_); }

  // The step the stepper has just taken (what its step() returned): the events on it and what
  // they do (the phase loop of the comment at the top of this file).
  Next after_step(const StepResult& step) {
    if (!step.ok) return fail(failure_of_step(step.code), step.reason);
    scan_t0_ = stepper_.t0();
    scan_x0_ = stepper_.x0();
    try {
      return scan_step();
    } catch (const EventLocationError& err) {  // a root finder out of iterations
      return fail(FailureKind::event_location, std::string(Stepper::name) + ": " + err.what());
    }
  }

 private:
  // The events of the last step from (scan_t0_, scan_x0_) on, and what they do; the rest of the
  // step is scanned again past an event that changes no branch. EventLocationError from the
  // locator or the refinement propagates to after_step().
  Next scan_step() {
    for (;;) {
      const T t0 = scan_t0_, t1 = stepper_.t1();
      const ActiveEvents active = active_events(sys_, found_, scan_x0_, stepper_.x1());
      const Earliest earliest = locate(active);
      if (!earliest.t) {
        emit_samples(t0, t1);
        if (sys_.branch.phase == Phase::unloading) {
          if (const auto e_bound = capture_after_step(sys_, stepper_.x1(), stepper_.steps(), opt_))
            return finish(ImpactStatus::captured, t1, stepper_.x1(), *e_bound);
          if (std::optional<std::string> why = stalled(t0, t1))
            return fail(FailureKind::step_limit, std::move(*why));
          if constexpr (std::is_same_v<T, double>) {  // the 50-digit reference: no series
            const std::optional<double> kappa = hertzian_end();
            if (kappa) {
              if (const std::optional<EndSeriesMatch> end = end_series_match(*kappa))
                return separate_by_series(t1, stepper_.x1(), *end);
            }
            cap_step_before_separation(kappa);
          }
        }
        return Next::step;
      }
      T te = *earliest.t;
      state_type xe;
      if (std::optional<std::string> why = event_state(active, earliest.first, te, xe))
        return fail(FailureKind::event_refinement, std::move(*why));
      if (retake_to_separation(active.kinds[earliest.first], te, xe)) return Next::step;
      emit_samples(t0, te);
      const Fired fired = fire(active, earliest, te, xe);
      if (fired.law_domain) return fail(FailureKind::law_domain, std::move(*fired.law_domain));
      if (fired.separated) return separate(te, xe);
      if (const auto e_bound = capture_at_unloading(fired, xe))
        return finish(ImpactStatus::captured, te, xe, *e_bound);
      if (fired.branch_changed)  // a located yield onto a linear segment
        if (const std::optional<Next> crossed = cross_linear_segment(te, xe)) return *crossed;
      if constexpr (Stepper::dense_output) {
        if (opt_.locate_events && !fired.branch_changed && te < t1) {
          scan_t0_ = te;  // scan the rest of this step from the event on
          scan_x0_ = xe;
          continue;
        }
      }
      stepper_.start(sys_, te, xe);
      if constexpr (requires(Stepper & s) { s.scale_proposed_step(T{}); }) {
        if (fired.step_scale != 1) stepper_.scale_proposed_step(fired.step_scale);
      }
      return Next::step;
    }
  }

  // The step that crosses the separation is taken again from its start, ending at the event,
  // where its stages saw the law where the solution is not smooth in tau, as at onset; the
  // embedded error estimate assumes smoothness and can pass a step whose interpolant at the
  // event is wrong by far more than the tolerance. Two such places (separation_not_smooth):
  //   - the step ran past z = 0, where a law's formula changes (the elastoplastic unloading
  //     below z = 0 is its tension side): paper scene, dop853, rtol 1e-8, v0 = 0.2939 m/s,
  //     zeta = 0.147 passed every step (largest estimate 0.86) with e off by 3.0e-6;
  //   - the force vanishes together with its stiffness (F ~ z^{3/2} at z = 0: Hertz, an
  //     elastic unloading, a plastic set far below z_m): v0 = 0.1149 m/s, zeta = 0.264 passed
  //     a step at 0.8 of the tolerance with the energy ledger off by 4.3e-6 m v0^2.
  // The retaken step's error control sees only the smooth side; the event is then located on
  // the steps that follow. At most kSeparationRetakes times an impact: each retake ends nearer
  // the root, and a step that starts near it has little of its length past it. True when the
  // step is to be retaken.
  static constexpr int kSeparationRetakes = 2;
  bool retake_to_separation(EventKind kind, T te, const state_type& xe) {
    if constexpr (!Stepper::dense_output || !requires(Stepper & s) { s.propose_step(T{}); }) {
      return false;
    } else {
      if (opt_.fixed_step || !opt_.locate_events || separation_retakes_ >= kSeparationRetakes)
        return false;
      if (event_row(kind).action != EventAction::end_contact || !(te < stepper_.t1())) return false;
      if (!separation_not_smooth(xe)) return false;
      ++separation_retakes_;
      stepper_.start(sys_, scan_t0_, scan_x0_);
      stepper_.propose_step(te - scan_t0_);
      return true;
    }
  }

  // The step's end past z = 0, or the law's stiffness at the separation state xe below a tenth
  // of the unloading secant F(z_m) / (z_m - z): the force leaves zero with a vanishing slope.
  // For the elastoplastic unloading, whose slope at the set z_f is 1.5 K_h sqrt(z_f), that is
  // z_f / z_m below about 0.004.
  bool separation_not_smooth(const state_type& xe) const {
    if (!(sys_.z(stepper_.x1()) > 0)) return true;
    const typename NormalisedRun<System>::Event* peak = nullptr;
    for (const auto& ev : run_.events)
      if (ev.kind == EventKind::max_compression) peak = &ev;
    if (!peak) return true;
    const T span = sys_.z(peak->x) - sys_.z(xe);
    if (!(span > 0)) return true;
    using std::abs;
    return abs(sys_.stiffness(xe)) < T(0.1) * abs(peak->force) / span;
  }

  // kappa of F_bar = kappa z^{3/2} where the present unloading branch is Hertzian to its end
  // (end_series.h): a law that declares a Hertzian onset and separates at z_perm, unloading from
  // z_m within its Hertzian onset, with no permanent set (Hertz; the elastoplastic law below
  // yield). nullopt otherwise, and where the onset series is not used either (series_start).
  std::optional<double> hertzian_end() const {
    if constexpr (!std::is_same_v<T, double> ||
                  !law_separates_at_z_perm<typename System::law_type>() ||
                  !requires { Stepper::starts_from_onset_series; }) {
      return std::nullopt;
    } else {
      if (opt_.fixed_step || !opt_.onset_series || !opt_.locate_events || sys_.tension)
        return std::nullopt;
      if (sys_.branch.phase != Phase::unloading || !(sys_.branch.z_perm == 0)) return std::nullopt;
      const std::optional<HertzianOnset> onset = hertzian_onset(sys_.law);
      if (!onset || !(sys_.branch.z_max <= onset->z_end)) return std::nullopt;
      const double L = sys_.length;
      return onset->K * L * std::sqrt(L) * sys_.inverse_force_scale;
    }
  }

  // The end of contact from the last step's end by the series of end_series.h on a Hertzian end
  // (kappa = hertzian_end()), where that state is within the series' reach (its truncation bound
  // at most rtol) and the branch's force there is kappa z^{3/2} (to 1e-10, the rounding of the
  // law's unloading formula). nullopt otherwise: the integration goes on.
  std::optional<EndSeriesMatch> end_series_match(double kappa) const {
    const state_type& x = stepper_.x1();
    const double z = sys_.z(x), beta = System::has_dashpot ? sys_.two_zeta : 0.0;
    std::optional<EndSeriesMatch> m = match_end_series(kappa, beta, z, x[System::W], opt_.rtol);
    if (!m) return std::nullopt;
    const double hertz = kappa * z * std::sqrt(z);
    if (!(std::abs(sys_.force(x) - hertz) <= 1e-10 * hertz)) return std::nullopt;
    return m;
  }

  // The state at tau_f - sigma on the series of the match m, from the end state x_f (sigma = 0
  // gives x_f back); the identities of end_series.h.
  state_type series_end_state(const state_type& x_f, const EndSeriesMatch& m, double sigma) const {
    const double beta = System::has_dashpot ? sys_.two_zeta : 0.0;
    const OnsetSeriesState S = onset_series_state(m.kappa, -beta, sigma);
    const double W = m.W, W2 = W * W;
    state_type x = x_f;
    x[System::A] = x_f[System::A] + W * S.a;
    x[System::W] = -W * S.w;
    if constexpr (System::has_dashpot) {
      x[System::Z] = W * S.z;
      x[System::WV] = x_f[System::WV] + W2 * S.Wv;
    }
    x[System::J] = x_f[System::J] - W * S.J;
    x[System::WA] = x_f[System::WA] + W2 * S.Wa;
    return x;
  }

  // Separation by the series from (t1, x1): the end state is x1 plus what the last s of contact
  // adds (end_series.h), z = 0 and w = -W_f there; the event is recorded as a located one.
  Next separate_by_series(T t1, const state_type& x1, const EndSeriesMatch& m) {
    const double W = m.W, W2 = W * W;
    state_type x_f = x1;
    x_f[System::A] = x1[System::A] - W * m.at.a;
    x_f[System::W] = -W;
    if constexpr (System::has_dashpot) {
      x_f[System::Z] = 0;
      x_f[System::WV] = x1[System::WV] - W2 * m.at.Wv;
    }
    x_f[System::J] = x1[System::J] + W * m.at.J;
    x_f[System::WA] = x1[System::WA] - W2 * m.at.Wa;
    const T tau_f = t1 + T(m.s);
    if (observer_) {
      for (int k = 1; k <= samples_per_step_; ++k) {
        const double sigma = m.s * (samples_per_step_ - k) / samples_per_step_;
        (*observer_)(static_cast<double>(tau_f) - sigma, series_end_state(x_f, m, sigma), sys_);
      }
    }
    run_.events.push_back({EventKind::separation, tau_f, x_f, sys_.force(x_f)});
    return separate(tau_f, x_f);
  }

  // The step proposed next on an unloading branch, shortened where the controller would take it
  // past a point where the solution is not smooth:
  //   - on a Hertzian end (hertzian_end), to end kEndSeriesLanding of the series' reach before
  //     the predicted separation (end_series_target), so that the next state is matched by the
  //     series rather than the step crossing tau_f;
  //   - with a permanent set (separation at z_perm > 0, where the branch is smooth), to at most
  //     kKinkShare of the time z / (-z') in which z would reach 0 at its present rate: below
  //     z = 0 the law's formula changes (separation_not_smooth), and a step whose stages pass
  //     it is rejected (measured at v0 = 0.15 m/s, zeta = 0: errors 2e5, 6e2, 9e3 times the
  //     tolerance, three rejections in the last four steps).
  static constexpr double kEndSeriesLanding = 0.8;
  static constexpr double kKinkShare = 0.5;
  // `kappa`: hertzian_end() at the step's end.
  void cap_step_before_separation(const std::optional<double>& kappa) {
    if constexpr (requires(Stepper & s) { s.proposed_step(); }) {
      if (opt_.fixed_step || !opt_.locate_events || sys_.tension) return;
      const state_type& x = stepper_.x1();
      const double z = sys_.z(x), beta = System::has_dashpot ? sys_.two_zeta : 0.0;
      double end_at = 0;
      if (kappa) {
        const std::optional<EndSeriesTarget> target =
            end_series_target(*kappa, beta, z, x[System::W], opt_.rtol);
        if (!target) return;
        end_at = target->s - kEndSeriesLanding * target->reach;
      } else if constexpr (law_separates_at_z_perm<typename System::law_type>()) {
        // dz/dtau at x: a component of f(x) where the stepper holds it (f1), the law not asked
        double z_rate = 0;
        if constexpr (requires { stepper_.f1(); })
          z_rate = stepper_.f1()[System::has_dashpot ? System::Z : System::A];
        else
          z_rate = static_cast<double>(sys_.z_rate(x));
        if (!(sys_.branch.z_perm > 0 && z > 0 && z_rate < 0)) return;
        end_at = kKinkShare * z / -z_rate;
      }
      if (end_at > 0 && stepper_.proposed_step() > end_at) stepper_.propose_step(T(end_at));
    }
  }

  // What acting on the events of one time did.
  struct Fired {
    bool separated = false;
    bool branch_changed = false;            // the law's next branch starts at the event
    std::optional<std::string> law_domain;  // the law is undefined there: why
    T step_scale = 1;  // for the step proposed on the old branch (branch_step_scale)
  };

  // At an event that changes the law's branch the stiffness k = dF/dz may jump, and with it the
  // contact's local time scale 1/sqrt(k) (unit mass, normalised variables), which sets the step
  // an explicit method can take: the elastoplastic law at maximum compression goes from K_y to
  // 1.5 K_h sqrt(z_m), (z_m/z_y)^{1/2} times stiffer. The step the controller proposed on the old
  // branch is scaled by sqrt(k_before / k_after) where the new branch is stiffer (never grown:
  // the controller grows it when the error allows). Measured (dop853, rtol 1e-8): the paper
  // impact's first unloading step was rejected at the old branch's step, 159 -> 147 right-hand
  // sides; the 60 x 60 paper map, rejections of the first step after a restart 0.88 -> 0.40 an
  // impact, right-hand sides 219.7 -> 215.5. 1 where the stiffness is not positive before or
  // does not rise.
  static T branch_step_scale(T k_before, T k_after) {
    using std::sqrt;
    return k_before > 0 && k_after > k_before ? T(sqrt(k_before / k_after)) : T(1);
  }

  // The capture criteria (capture.h) at the state where an event has just put the law on its
  // unloading branch (maximum compression), rather than only at the end of the first unloading
  // step after it: each criterion is a statement about one state on the unloading branch
  // (inside the invariant region, the remaining energy, the well), so it holds at the event
  // state as at a step's end. A strongly damped impact is mostly inside the invariant region
  // already at z_m (582 of the 598 captured points of the 60 x 60 paper map, rtol 1e-8), so
  // the restart there and the one step that used to decide it (~14 of its ~137 right-hand-side
  // evaluations) are not taken. nullopt when no branch changed, the branch is not unloading, or
  // no criterion decides.
  std::optional<double> capture_at_unloading(const Fired& fired, const state_type& xe) const {
    if (!fired.branch_changed || sys_.branch.phase != Phase::unloading) return std::nullopt;
    return capture_after_step(sys_, xe, stepper_.steps(), opt_);
  }

  struct SeriesStart {
    T tau;
    state_type x;
    double kappa, beta;           // the series' F_bar = kappa z^{3/2} and 2 zeta (onset_series.h)
    bool at_segment_end = false;  // tau is where z reaches the Hertzian onset's end (the yield)
  };

  // The loading segment the law is on at (tau0, x0), crossed in closed form to maximum
  // compression where the law declares it linear in z (law.h: linear_segment; linear_phase.h):
  // the elastoplastic law's region II from the yield, reached by the onset series or located by
  // the integrator, which crossed it in 3.7 of the 9.1 steps of an impact (dop853, rtol 1e-8, a
  // 10 x 10 paper map that yields). Maximum compression is then fired there as fire() fires a
  // located one, the capture criteria asked, and the stepper started on the unloading branch.
  // Without a dashpot the impactor stops at the same instant, w = 0 exactly (z' = w), and
  // maximum displacement fires with it. nullopt where the closed form does not apply (no linear
  // segment, T not double, a stepper that does not start from the series, options that turn the
  // series off, no zero of its compression rate in floating point): the integrator crosses the
  // segment.
  std::optional<Next> cross_linear_segment(T tau0, const state_type& x0) {
    if constexpr (!std::is_same_v<T, double> || !requires { Stepper::starts_from_onset_series; }) {
      return std::nullopt;
    } else {
      if (opt_.fixed_step || !opt_.onset_series || !opt_.locate_events) return std::nullopt;
      const std::optional<LinearSegment> seg = law_linear_segment(sys_.law, sys_.branch);
      if (!seg) return std::nullopt;
      const double k = seg->K * sys_.length * sys_.inverse_force_scale;
      const double beta = System::has_dashpot ? sys_.two_zeta : 0.0;
      const double w0 = x0[System::W], u0 = sys_.force(x0);
      const std::optional<LinearPhasePoint> m = linear_phase_max_compression(k, beta, w0, u0);
      if (!m) return std::nullopt;
      // the state at p from (tau0, x0) by the identities of linear_phase.h, with impactor speed w
      auto state_at = [&](const LinearPhasePoint& p, double w) {
        state_type x = x0;
        const double dz = (p.u - u0) / k, dJ = w0 - w, dWa = 0.5 * (w0 - w) * (w0 + w);
        x[System::W] = w;
        x[System::A] = x0[System::A] + dz + beta * dJ;
        x[System::J] = x0[System::J] + dJ;
        x[System::WA] = x0[System::WA] + dWa;
        if constexpr (System::has_dashpot) {
          x[System::Z] = x0[System::Z] + dz;
          x[System::WV] = x0[System::WV] + dWa - 0.5 * (p.u - u0) * (p.u + u0) / k;
        }
        return x;
      };
      const state_type xm = state_at(*m, System::has_dashpot ? m->w : 0.0);
      const T tau_m = tau0 + m->tau;
      if (observer_)
        for (int i = 1; i <= samples_per_step_; ++i) {
          const LinearPhasePoint p =
              linear_phase_at(k, beta, w0, u0, m->tau * i / samples_per_step_);
          (*observer_)(tau0 + p.tau, i == samples_per_step_ ? xm : state_at(p, p.w), sys_);
        }
      return fire_max_compression(tau_m, xm, m->tau);
    }
  }

  // Maximum compression at (tau, x), reached in closed form after `span` of the segment: fired,
  // the capture criteria asked, and the stepper started on the unloading branch with a first
  // step of half the span (the solution's own time scale there) scaled to the branch's stiffness
  // (branch_step_scale).
  Next fire_max_compression(T tau, const state_type& x, double span) {
    Fired fired;
    fired.branch_changed = true;
    for (EventKind kind : {EventKind::max_compression, EventKind::max_displacement}) {
      if (kind == EventKind::max_displacement && (found_.max_displacement || x[System::W] > 0))
        continue;  // with a dashpot the impactor stops after the spring
      try {
        fired.step_scale *= record_and_act(kind, tau, x);
      } catch (const LawDomainError& err) {
        stepper_.start(sys_, tau, x);  // where the run stopped, for fail()
        return fail(FailureKind::law_domain, err.what());
      }
    }
    if (const auto e_bound = capture_at_unloading(fired, x))
      return finish(ImpactStatus::captured, tau, x, *e_bound);
    stepper_.start(sys_, tau, x);
    stepper_.propose_step(T(0.5 * span) * fired.step_scale);
    return Next::step;
  }

  // The yield event at the series' state where z reaches the end of the Hertzian onset, fired
  // as fire() fires a located one: recorded, and the law put on its next segment. Returns the
  // scale for the step proposed on the Hertzian segment (branch_step_scale).
  T enter_next_segment_at(T tau, const state_type& x) {
    return record_and_act(EventKind::yield, tau, x);
  }

  // Trajectory samples on (0, tau0], from the series like the state at tau0.
  void emit_series_samples(const SeriesStart& start) {
    for (int k = 1; k <= samples_per_step_; ++k) {
      const double tau = static_cast<double>(start.tau) * k / samples_per_step_;
      (*observer_)(tau, series_state(onset_series_state(start.kappa, start.beta, tau)), sys_);
    }
  }

  static state_type series_state(const OnsetSeriesState& s) {
    state_type x{};
    x[System::A] = s.a;
    x[System::W] = s.w;
    if constexpr (System::has_dashpot) {
      x[System::Z] = s.z;
      x[System::WV] = s.Wv;
    }
    x[System::J] = s.J;
    x[System::WA] = s.Wa;
    return x;
  }

  // Where the integration starts past onset (onset_series.h): where z reaches the end of the
  // Hertzian onset (the first kink, z_y) when the series reaches it (series_segment_end), the
  // yield then fired there; else the tau at which the series' truncation bound is rtol, kept
  // below half the end of the Hertzian onset (z <= tau, so z_y is met by the integrator and
  // located as an event). nullopt where the series does not apply: a law without a Hertzian
  // onset, a fixed step, the 50-digit reference (T is not double), or options.onset_series off.
  std::optional<SeriesStart> series_start() const {
    if constexpr (!std::is_same_v<T, double>) {
      return std::nullopt;
    } else {
      if (opt_.fixed_step || !opt_.onset_series || !opt_.locate_events) return std::nullopt;
      const std::optional<HertzianOnset> onset = hertzian_onset(sys_.law);
      if (!onset) return std::nullopt;
      const double L = sys_.length;
      const double kappa = onset->K * L * std::sqrt(L) * sys_.inverse_force_scale;
      const double beta = System::has_dashpot ? sys_.two_zeta : 0.0;
      const double reach = onset_series_reach(kappa, beta, opt_.rtol);
      if (!(reach > 0 && std::isfinite(reach) && std::isfinite(kappa))) return std::nullopt;
      if (const std::optional<OnsetSeriesState> end =
              series_segment_end(kappa, beta, reach, *onset))
        return SeriesStart{end->tau, series_state(*end), kappa, beta, true};
      const double tau = std::min(reach, 0.5 * onset->z_end / L);
      if (!(tau > 0)) return std::nullopt;
      return SeriesStart{tau, series_state(onset_series_state(kappa, beta, tau)), kappa, beta};
    }
  }

  // The series' state where z reaches the end of the Hertzian onset (the yield of the
  // elastoplastic law), where that is within the series' reach: the integration then starts
  // there, at the event, instead of from half of it, meeting it on its second or third step
  // and throwing away the part of that step past it. Paper scene, dop853, rtol 1e-8: the
  // series' bound at the yield is ~1e-11, and 123 -> 119 right-hand sides; the 300 x 300 map
  // (rtol 1e-8) 1,154,692 -> 1,070,465 accepted steps. Solved on the series by Newton's method
  // (onset_series_at_z: four evaluations of the series on the paper impact; the bracketing
  // root finder of the events took six, and the impact's instructions went from 21,070 to
  // 21,911 with it, to 20,930 with Newton). nullopt where the onset has no end, the end is past
  // the reach, or the law's first segment does not end there: the integrator then meets the
  // yield as an event, as before.
  std::optional<OnsetSeriesState> series_segment_end(double kappa, double beta, double reach,
                                                     const HertzianOnset& onset) const {
    const std::optional<double> segment_end = law_segment_end(sys_.law, sys_.branch);
    if (!std::isfinite(onset.z_end) || !segment_end || *segment_end != onset.z_end)
      return std::nullopt;
    return onset_series_at_z(kappa, beta, onset.z_end / sys_.length, reach);
  }

  // An explicit stepper whose steps (held by stability against a stiff dashpot) cannot reach
  // the least time the impact still needs (dashpot_stall.h) within kStallMargin times the steps
  // left: why, to fail now rather than at max_steps. Asked every 64th unloading step.
  std::optional<std::string> stalled(T t0, T t1) {
    if constexpr (Stepper::implicit) {
      return std::nullopt;
    } else {
      if (++unloading_steps_ % 64 != 0) return std::nullopt;
      const std::optional<double> dtau = least_remaining_time(sys_, stepper_.x1(), opt_);
      const double h = static_cast<double>(t1 - t0);
      const double left = static_cast<double>(opt_.max_steps - stepper_.steps());
      if (!dtau || !(h > 0) || !(*dtau > kStallMargin * left * h)) return std::nullopt;
      std::ostringstream os;
      os << Stepper::name
         << ": the impact cannot end before tau = " << static_cast<double>(t1) + *dtau
         << " (the dashpot must first slow the impactor), " << *dtau / h
         << " more steps of the present tau = " << h << ", over " << kStallMargin << " times the "
         << left << " left of max_steps = " << opt_.max_steps
         << ": a stiff scene (zeta = " << sys_.two_zeta / 2
         << ") needs an implicit integrator (rodas4, odeint-rosenbrock4, gsl-msbdf)";
      return os.str();
    }
  }

  // The earliest crossing of the active events on the part of the step being scanned.
  Earliest locate(const ActiveEvents& active) {
    auto interpolate = [this](const T& t, state_type& s) {
      if constexpr (requires { stepper_.interpolate(sys_, t, s, System::event_components); })
        stepper_.interpolate(sys_, t, s, System::event_components);
      else
        stepper_.interpolate(sys_, t, s);
    };
    auto root = [this, &active](int i, const state_type& s) {
      return event_root(active.kinds[i], sys_, s);
    };
    // the roots at this step's start are those at the last one's end when that step fired
    // nothing: then no event acted and no restart took place, so the branch, the events found
    // and with them the active roots are those of the last step (active_events), and the
    // values are not evaluated twice
    const bool reuse = roots_at_end_.valid && roots_at_end_.size == active.size();
    // the roots at the step's end from the stepper's derivative there, where it has one
    std::array<T, ActiveEvents::capacity> g1{};
    const std::array<T, ActiveEvents::capacity>* at_end = nullptr;
    if constexpr (requires { stepper_.f1(); }) {
      for (int i = 0; i < active.size(); ++i)
        g1[i] = event_root_at(active.kinds[i], sys_, stepper_.x1(), stepper_.f1());
      at_end = &g1;
    }
    Earliest earliest = locate_earliest(
        scan_t0_, scan_x0_, stepper_.t1(), stepper_.x1(), interpolate, active.roots, root,
        opt_.locator, opt_.locate_events, reuse ? &roots_at_end_.g : nullptr, at_end);
    roots_at_end_ = {!earliest.t, active.size(), earliest.g1};
    return earliest;
  }

  // The active roots' values at the end of the last step located on, for the next one.
  struct RootsAtEnd {
    bool valid = false;  // no event fired on that step: the next starts from its end
    int size = 0;
    std::array<T, ActiveEvents::capacity> g{};
  };

  // The state xe at the event time te: on the dense output, or refined by re-stepping (te
  // moves to the refined time) for a stepper without one. A refinement that fails: why.
  std::optional<std::string> event_state(const ActiveEvents& active, int first, T& te,
                                         state_type& xe) {
    if (!opt_.locate_events) {
      xe = stepper_.x1();
    } else if constexpr (Stepper::dense_output) {
      stepper_.interpolate(sys_, te, xe);
    } else {
      const EventKind kind = active.kinds[first];
      auto value = [this](EventKind k, const state_type& s) { return event_root(k, sys_, s); };
      const Refinement<T> refined =
          refine_on_restep(stepper_, sys_, kind, event_row(kind).direction, te, xe, value, opt_);
      if (!refined.failure.empty()) return refined.failure;
      te = refined.tau;  // events of other kinds are judged at the refined state (same step)
    }
    return std::nullopt;
  }

  // Acts on every armed event that has happened by te: coincident ones together (dz/dt = 0 and
  // dalpha/dt = 0 without a dashpot), and any whose root is already past at the event state,
  // which a restart there could no longer see.
  Fired fire(const ActiveEvents& active, const Earliest& earliest, T te, const state_type& xe) {
    const T coincide = T(1e-12) * (1 + (te < 0 ? -te : te));
    Fired fired;
    for (int i = 0; i < active.size(); ++i) {
      const EventKind kind = active.kinds[i];
      const Direction dir = active.roots.roots[i].direction;
      const bool happened = i == earliest.first ||
                            (earliest.found[i] && *earliest.found[i] <= te + coincide) ||
                            (earliest.armed[i] && !is_pre_event(event_root(kind, sys_, xe), dir));
      if (!happened) continue;
      const EventAction action = event_row(kind).action;
      fired.branch_changed = fired.branch_changed || changes_branch(action);
      try {
        fired.step_scale *= record_and_act(kind, te, xe);
      } catch (const LawDomainError& err) {
        fired.law_domain = err.what();
        return fired;
      }
      if (action == EventAction::end_contact) fired.separated = true;
    }
    return fired;
  }

  // One event at (te, xe): recorded, and what it means done (act). Returns the scale for the
  // step proposed on the old branch (branch_step_scale; 1 where the branch does not change).
  // LawDomainError from the law propagates.
  T record_and_act(EventKind kind, T te, const state_type& xe) {
    run_.events.push_back({kind, te, xe, sys_.force(xe)});
    const EventAction action = event_row(kind).action;
    const T k_before = changes_branch(action) ? sys_.stiffness(xe) : T(0);
    act(action, te, xe);
    return changes_branch(action) ? branch_step_scale(k_before, sys_.stiffness(xe)) : T(1);
  }

  // What an event means (impact_events.h), done at time te and state xe.
  void act(EventAction action, T te, const state_type& xe) {
    switch (action) {
      case EventAction::next_segment:
        law_next_segment(sys_.law, sys_.branch);
        break;
      case EventAction::begin_unloading:
        if (!System::rate_dependent) {
          run_.F_max = sys_.force(xe);
          run_.tau_F_max = te;
        }
        run_.tau_z_max = te;
        law_begin_unloading(sys_.law, sys_.branch, T(sys_.length * sys_.z(xe)));
        record_pull_off_work();
        break;
      case EventAction::record_alpha_max:
        run_.has_max_displacement = true;
        found_.max_displacement = true;
        run_.tau_alpha_max = te;
        run_.x_alpha_max = xe;
        run_.steps_alpha_max = stepper_.steps();
        break;
      case EventAction::record_peak_force:
        found_.peak_force = true;
        run_.F_max = sys_.force(xe);
        run_.tau_F_max = te;
        break;
      case EventAction::end_contact:
        break;
    }
  }

  // The depth of the unloading branch's attractive well, -S(z_f) (law.h: separation_work),
  // computed once where unloading begins (capture.h, criterion 4); 0 without a well.
  void record_pull_off_work() {
    const double z_f = static_cast<double>(sys_.branch.z_perm);
    const std::optional<double> S = separation_work(sys_.law, sys_.branch, z_f);
    sys_.pull_off_work = S ? std::max(0.0, -*S * sys_.inverse_force_scale / sys_.length) : 0.0;
  }

  // F = 0 at (te, xe): a rebound, or, with the impactor still approaching, grazing capture
  // (capture.h) or a failure that says so rather than return a negative COR.
  Next separate(T te, const state_type& xe) {
    if (!(xe[System::W] > 0)) return finish(ImpactStatus::separated, te, xe, 0.0);
    const double w = static_cast<double>(xe[System::W]);
    if (const auto e_bound = grazing_capture(System::has_dashpot, w, stepper_.steps(), opt_))
      return finish(ImpactStatus::captured, te, xe, *e_bound);
    std::ostringstream os;
    os << Stepper::name << ": contact force reached zero at tau = " << static_cast<double>(te)
       << " with the impactor still approaching (alpha_dot = +" << w
       << " v0): the integration error exceeds the remaining force; tighten --rtol or use "
          "another integrator";
    return fail(FailureKind::still_approaching, os.str());
  }

  void emit_samples(T a, T b) {
    if (!observer_) return;
    state_type s;
    for (int k = 1; k <= samples_per_step_; ++k) {
      const T t = a + (b - a) * k / samples_per_step_;
      stepper_.interpolate(sys_, t, s);
      (*observer_)(static_cast<double>(t), s, sys_);
    }
  }

  Next fail(FailureKind kind, std::string why) {
    run_.status = ImpactStatus::failed;
    run_.failure = kind;
    run_.reason = std::move(why);
    run_.tau_end = stepper_.t1();
    run_.x_end = stepper_.x1();
    run_.branch = sys_.branch;
    run_.steps = stepper_.steps();
    return Next::done;
  }

  // A run that ends separated or captured at (tau_end, x_end), checked for consistency.
  Next finish(ImpactStatus status, T tau_end, const state_type& x_end, double e_bound) {
    run_.status = status;
    run_.tau_end = tau_end;
    run_.x_end = x_end;
    run_.branch = sys_.branch;
    run_.steps = stepper_.steps();
    run_.e_bound = e_bound;
    if (status == ImpactStatus::captured)
      run_.events.push_back({EventKind::capture, tau_end, x_end, sys_.force(x_end)});
    if (opt_.check_consistency) {
      std::string why = consistency_failure(consistency_measures(run_, sys_), opt_, Stepper::name);
      if (!why.empty()) {
        run_.status = ImpactStatus::failed;
        run_.failure = FailureKind::inconsistent;
        run_.reason = std::move(why);
      }
    }
    return Next::done;
  }

  System& sys_;
  const IntegratorOptions& opt_;
  const SampleObserver<System>* observer_;
  int samples_per_step_;
  Stepper stepper_;
  NormalisedRun<System> run_;
  EventsFound found_;
  RootsAtEnd roots_at_end_;
  int separation_retakes_ = 0;  // retake_to_separation() so far
  long unloading_steps_ = 0;    // stalled() so far
  // The scan of the last step starts at (scan_t0_, scan_x0_): its start, or the last event on
  // it that changed no branch (a dense-output step goes on past such an event).
  T scan_t0_ = 0;
  state_type scan_x0_{};
};

template <class Stepper, class System>
NormalisedRun<System> run_impact(System& sys, const IntegratorOptions& opt,
                                 const SampleObserver<System>* observer = nullptr,
                                 int samples_per_step = 4) {
  return ImpactDriver<Stepper, System>(sys, opt, observer, samples_per_step).run();
}

}  // namespace ivv
