// The plate impact's driver (plate_impact.h): contacts integrated by a stepper with events
// located on its interpolant, free flights advanced exactly, until no contact is possible.
// A template on the law and on the stepper (start/step/interpolate, solver/steppers/dop853.h's
// interface): Dop853Stepper over the vector state by default, OdeintDenseDopri5 as a second
// integrator, PlateExponentialStepper (the modes advanced exactly for a polynomial force) as a
// third. Measured on the 5 mm ball on the 200 mm plate (866 modes, rtol 1e-10): 154 steps with
// dop853 against 832 with dopri5 and 100 with the exponential stepper, e the same to 1e-9.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "solver/driver/event_locator.h"
#include "solver/laws/law.h"
#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_system.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {

// A stepper for the plate: the hand-written ones from IntegratorOptions, odeint's adapter from
// its tolerances and first step.
template <class Stepper>
Stepper make_plate_stepper(const PlateImpactOptions& opt) {
  if constexpr (std::is_constructible_v<Stepper, const IntegratorOptions&>) {
    IntegratorOptions io;
    io.rtol = opt.rtol;
    io.atol = opt.atol;
    io.initial_dt = 1e-3;
    return Stepper(io);
  } else {
    return Stepper(opt.rtol, opt.atol, 1e-3);
  }
}

// Thrown inside the driver for a failed run; turned into ok = false and its reason.
struct PlateRunFailure {
  std::string reason;
};

// Runs `run`; a named failure of a plate run (PlateRunFailure, an event not located, a law
// outside its domain) becomes out.ok = false with its reason. Anything else propagates.
template <class Run>
void catching_plate_failures(PlateImpactResult& out, Run run) {
  try {
    run();
  } catch (const PlateRunFailure& f) {
    out.ok = false;
    out.reason = f.reason;
  } catch (const EventLocationError& e) {
    out.ok = false;
    out.reason = e.what();
  } catch (const LawDomainError& e) {
    out.ok = false;
    out.reason = e.what();
  }
}

template <class Law, class Stepper>
class PlateImpactDriver {
 public:
  using System = PlateSystem<Law>;
  using State = std::vector<double>;

  PlateImpactDriver(const Law& law, const Scales& k, const PlateModes& modes, double m,
                    const PlateImpactOptions& opt)
      : law_(law),
        sys_(law, k, modes, m, opt.dropped.value_or(DroppedModes::static_compliance)),
        scales_(k),
        opt_(opt),
        stepper_(make_plate_stepper<Stepper>(opt)) {}

  // Runs the impact; fills the dynamical members of `out` (the caller fills the plate's facts).
  void run(PlateImpactResult& out) {
    State x(sys_.size(), 0.0);
    x[1] = 1.0;  // alpha' = v0
    double t = 0.0;
    for (;;) {
      if (static_cast<int>(out.contacts.size()) >= opt_.max_contacts)
        throw PlateRunFailure{"more than " + std::to_string(opt_.max_contacts) + " contacts"};
      run_contact(t, x, out);
      if (out.contacts.size() == 1) out.e_first = -x[1];
      if (!free_flight(t, x, out)) break;
    }
    finish(t, x, out);
  }

 private:
  enum class Root { max_compression, segment_end, reload, separation };

  // The spring deformation z_f where the current branch's force vanishes, normalised.
  double zero_force_point() const {
    return static_cast<double>(sys_.history.z_perm) / sys_.length();
  }

  // One contact from its onset (t, x) to its separation; (t, x) are left at the separation.
  void run_contact(double& t, State& x, PlateImpactResult& out) {
    PlateContact c;
    c.t_start = t * scales_.time;
    const double v_start = x[1];
    stepper_.start(sys_, t, x);
    fired_.reset();
    if (opt_.record_force) out.force_history.push_back({t * scales_.time, 0.0});
    for (;;) {
      if (out.steps + out.free_flight_steps >= opt_.max_steps)
        throw PlateRunFailure{"more than " + std::to_string(opt_.max_steps) + " steps"};
      const StepResult r = stepper_.step(sys_);
      ++out.steps;
      if (!r.ok) throw PlateRunFailure{r.reason};
      if (!sys_.failure().empty()) throw PlateRunFailure{sys_.failure()};
      const std::optional<Root> hit = locate(t, x);
      if (opt_.record_force) record_force(stepper_.t0(), t, out);
      if (!hit && System::z_kin(x) < zero_force_point())
        throw PlateRunFailure{
            "the force turned negative at t = " + std::to_string(t * scales_.time) +
            " s without a located separation (on the " +
            (sys_.history.phase == Phase::loading ? "loading" : "unloading") + " branch)"};
      if (!hit) continue;
      if (*hit == Root::separation) break;
      on_event(*hit, x, c, out);
      // A reload located where z already falls (a graze of z_m: the crossing and the maximum
      // within the locator's resolution) is at once a maximum of compression: on the loading
      // branch only zdot = 0 falling would switch it back, and it has already fallen, so the
      // contact would run past its separation with no root watching it (measured: the 5 mm
      // ball at cut-off 80, rtol 1e-12, went on in tension to -35 N and ended with e 0.032
      // instead of 0.192).
      fired_ = *hit;
      if (*hit == Root::reload && System::z_kin_rate(x) <= 0.0) {
        on_event(Root::max_compression, x, c, out);
        fired_ = Root::max_compression;
      }
      stepper_.start(sys_, t, x);
    }
    c.t_end = t * scales_.time;
    c.velocity_end = x[1] * scales_.velocity;
    c.impulse = (v_start - x[1]) * scales_.energy / scales_.velocity;  // m v0 (alpha'_0 - alpha'_1)
    out.contacts.push_back(c);
    check_ledger(x, 0.0, out);
  }

  // Four samples of the force on the last step's interpolant over (ta, tb] (before an event
  // changes the branch), for plots only.
  void record_force(double ta, double tb, PlateImpactResult& out) {
    for (int k = 1; k <= 4; ++k) {
      const double tt = ta + 0.25 * k * (tb - ta);
      stepper_.interpolate(sys_, tt, sample_);
      out.force_history.push_back(
          {tt * scales_.time, sys_.force(System::z_kin(sample_)) * sys_.force_scale()});
    }
  }

  // What the roots read: z_kin and its rate (plate_system.h). The locator works on these two
  // numbers: the stepper's own event_gap(t) where it has one (the exponential stepper: exact, from
  // its tables at the probes), else interpolated as linear functionals of the stepper's
  // continuous extension where the stepper offers that (dop853: two sums over the stages once
  // per step instead of the interpolant of every mode at every probe), else from the
  // interpolated state.
  using EventState = std::array<double, 2>;
  // Probes a step: the most the locator takes. A root that goes out and back between two probes
  // is missed; the highest kept mode turns ~5 rad a step (dop853's stability on the imaginary
  // axis), so 16 probes leave it ~0.3 rad between them, and the probes are a few flops each on
  // the functionals (measured: with 4, the coupon at cut-off 50 missed a reload above z_m and
  // ended with e 0.940 instead of 0.9097).
  // A stepper that names its own probe count (the exponential stepper: its collocation nodes,
  // where its tables hold the exact solution) is probed there instead.
  static constexpr int probe_count() {
    if constexpr (requires { Stepper::kProbes; })
      return Stepper::kProbes;
    else
      return LocatorOptions::max_samples;
  }
  static constexpr LocatorOptions kProbes{probe_count()};
  static EventState event_state(const State& x) { return System::kinematic_gap(x); }

  class EventInterpolant {
   public:
    explicit EventInterpolant(PlateImpactDriver& d) : d_(d) {}
    void operator()(double t, EventState& s) {
      if constexpr (requires { d_.stepper_.event_gap(0.0); }) {
        s = d_.stepper_.event_gap(t);
      } else if constexpr (requires { d_.stepper_.dense_value(std::array<double, 8>{}, 0.0); }) {
        if (!ready_) {
          const auto c = d_.stepper_.template dense_functionals<2>(d_.sys_, &System::kinematic_gap);
          z_ = c[0];
          rate_ = c[1];
          ready_ = true;
        }
        s = {d_.stepper_.dense_value(z_, t), d_.stepper_.dense_value(rate_, t)};
      } else {
        d_.stepper_.interpolate(d_.sys_, t, d_.sample_);
        s = event_state(d_.sample_);
      }
    }

   private:
    PlateImpactDriver& d_;
    bool ready_ = false;
    std::array<double, 8> z_{}, rate_{};
  };

  // The roots active on the current branch, earliest crossing on the last step: (t, x) set there.
  std::optional<Root> locate(double& t, State& x) {
    RootSet<3> set;
    std::array<Root, 3> meaning{};
    const bool loading = sys_.history.phase == Phase::loading;
    auto add = [&](Root r, Direction d) {
      meaning[static_cast<std::size_t>(set.size)] = r;
      set.add({d, false});
    };
    add(Root::max_compression, Direction::falling);
    std::optional<double> z_end;
    if (loading) z_end = law_segment_end(law_, sys_.history);
    if (z_end) add(Root::segment_end, Direction::rising);
    if (!loading) add(Root::reload, Direction::rising);
    if (!loading) add(Root::separation, Direction::falling);
    // z_kin at which z reaches a given z: z + C f(z) (z_kin increases with z)
    const double zk_end =
        z_end ? *z_end / sys_.length() + sys_.compliance() * sys_.law_force(*z_end / sys_.length())
              : 0.0;
    const double zk_reload =
        static_cast<double>(sys_.history.z_max) / sys_.length() + sys_.compliance() * reload_force_;
    const double zk_zero = zero_force_point();
    auto g = [&](int i, const EventState& s) {
      switch (meaning[static_cast<std::size_t>(i)]) {
        case Root::max_compression:
          return s[1];
        case Root::segment_end:
          return s[0] - zk_end;
        case Root::reload:
          return s[0] - zk_reload;
        case Root::separation:
          return s[0] - zk_zero;
      }
      return 0.0;
    };
    // At a restart on an event the root that fired is post-event (a zero does not fire again):
    // the state interpolated there sums its modes in another order than the locator's values
    // did, and its rounding (~1e-16 in zdot) could arm that root again, which then fired within
    // the locator's tolerance of the same time, step after step (measured: the 5 mm ball at
    // cut-off 20, rtol 1e-5, 1 to 4 maxima of compression at one maximum, as rounding fell).
    const EventState s0 = event_state(stepper_.x0());
    std::array<double, 3> g0{};
    for (int i = 0; i < set.size; ++i) {
      g0[static_cast<std::size_t>(i)] = g(i, s0);
      if (fired_ && meaning[static_cast<std::size_t>(i)] == *fired_)
        g0[static_cast<std::size_t>(i)] =
            set.roots[static_cast<std::size_t>(i)].direction == Direction::falling
                ? std::min(g0[static_cast<std::size_t>(i)], 0.0)
                : std::max(g0[static_cast<std::size_t>(i)], 0.0);
    }
    fired_.reset();
    EventInterpolant interp(*this);
    const auto ec = locate_earliest<3>(stepper_.t0(), s0, stepper_.t1(), event_state(stepper_.x1()),
                                       interp, set, g, kProbes, true, &g0);
    std::optional<Root> r;
    t = ec.t ? *ec.t : stepper_.t1();
    if (ec.t) r = meaning[static_cast<std::size_t>(ec.first)];
    // On an unloading branch z stays at or below z_m: where it stands above z_m at the step's
    // stop (an event or the step's end), a reload was passed that had no sign change to find
    // (header of missed_reload).
    if (!loading && r != Root::reload) {
      if (const std::optional<double> tr = missed_reload(interp, t, zk_reload)) {
        t = *tr;
        r = Root::reload;
      }
    }
    if (!r) {
      x = stepper_.x1();
      return std::nullopt;
    }
    stepper_.interpolate(sys_, t, x);
    return r;
  }

  // A stop of the step (an event, or the step's end) at t_max on an unloading branch where z
  // stands above z_m (z_kin above zk_reload by more than the step's tolerance, rtol |zk_reload|
  // + atol: an excursion the integration does not resolve is not a reload) is past a reload the
  // locator could not see: its crossing, else nullopt. With z below z_m at the step's start,
  // [t0, t_max] is a bracket. A step that starts at z_m (the restart right after a maximum, or a
  // graze: z_kin' touched zero and rose again, so the reload root starts at zero and has no sign
  // change) is searched at kProbes points for one below z_m, and the bracket begins at the first;
  // if none is, z has been at or above z_m since t0 and the reload is at the first probe where z
  // rises (never t0 itself: there z_kin' is zero to rounding, and a reload where z falls is at
  // once a maximum again, run_contact, which would repeat this step). Measured: the drop-weight
  // coupon at cut-off 60 (100 modes), rtol 1e-6, missed such a reload after a maximum, stayed on
  // the stiffer unloading curve above z_m and ended with e = 0.9402 and F_max = 6566 N against
  // 0.90966 and 6316 N at rtol 1e-8 (both steppers alike; the energy ledger held, since it
  // follows the branch taken). When the step after a graze found no event at all, z rose above
  // z_m on the unloading curve for tens of steps unseen: the exponential stepper at rtol 1e-6
  // (cut-offs 20 .. 60) was off by 6.5e-5 .. 3.1e-4 in e, its ledger by 8.7e-6 .. 2.8e-5 (the
  // force jumped where the late reload switched the branch).
  std::optional<double> missed_reload(EventInterpolant& interp, double t_max, double zk_reload) {
    EventState s{};
    interp(t_max, s);
    const double g0 = System::z_kin(stepper_.x0()) - zk_reload, g1 = s[0] - zk_reload;
    const double slack = opt_.rtol * std::abs(zk_reload) + opt_.atol;
    if (!(g1 > slack)) return std::nullopt;
    auto g = [&](double tt) {
      EventState q{};
      interp(tt, q);
      return q[0] - zk_reload;
    };
    const double t0 = stepper_.t0();
    if (g0 < -slack) return solve_crossing(g, t0, t_max, g0, g1, Direction::rising, kProbes);
    const int n = kProbes.samples;
    for (int k = 1; k < n; ++k) {
      const double ta = t0 + (t_max - t0) * k / n;
      const double ga = g(ta);
      if (ga < 0.0) {
        for (int j = k + 1; j <= n; ++j) {
          const double tb = j == n ? t_max : t0 + (t_max - t0) * j / n;
          const double gb = j == n ? g1 : g(tb);
          if (gb >= 0.0) return solve_crossing(g, ta, tb, ga, gb, Direction::rising, kProbes);
        }
      }
    }
    for (int k = 1; k < n; ++k) {  // z at or above z_m from t0 on: the first probe where it rises
      const double ta = t0 + (t_max - t0) * k / n;
      EventState q{};
      interp(ta, q);
      if (q[1] > 0.0) return ta;
    }
    return std::nullopt;
  }

  // A branch event inside a contact: the law's history changes, the peaks are recorded.
  void on_event(Root r, const State& x, PlateContact& c, PlateImpactResult& out) {
    switch (r) {
      case Root::max_compression: {
        ++out.compression_maxima;
        const double zk = System::z_kin(x);
        const double F = sys_.force(zk);
        const double z = zk - sys_.compliance() * F;
        c.peak_force = std::max(c.peak_force, F * sys_.force_scale());
        out.z_max =
            std::isnan(out.z_max) ? z * sys_.length() : std::max(out.z_max, z * sys_.length());
        if (sys_.history.phase == Phase::loading) {
          loading_history_ = sys_.history;
          law_begin_unloading(law_, sys_.history, z * sys_.length());
          reload_force_ = sys_.law_force(z);
        }
        check_ledger(x, F, out);
        return;
      }
      case Root::segment_end:
        law_next_segment(law_, sys_.history);
        return;
      case Root::reload:
        ++out.reloads;
        sys_.history = loading_history_;
        return;
      case Root::separation:
        return;
    }
  }

  // (1/2) = (1/2) alpha'^2 + E_plate + (1/2) C F^2 + W_spring, on an unloading branch.
  void check_ledger(const State& x, double F, PlateImpactResult& out) {
    const auto hysteresis = law_.hysteresis_work(sys_.history);
    if (!hysteresis || sys_.history.phase != Phase::unloading) return;
    const double z = (System::z_kin(x) - sys_.compliance() * F) * sys_.length();
    const double spring =
        (*hysteresis + static_cast<double>(law_.stored_energy(sys_.history, z))) / scales_.energy;
    const double total =
        0.5 * x[1] * x[1] + sys_.plate_energy(x) + 0.5 * sys_.compliance() * F * F + spring;
    out.energy.max_error = std::max(out.energy.max_error, std::abs(total - 0.5) / 0.5);
    ++out.energy.checks;
  }

  // The free flight from a separation (t, x): true with (t, x) at the next contact's onset,
  // false when no further contact is possible (then (t, x) where that was established).
  bool free_flight(double& t, State& x, PlateImpactResult& out);

  void finish(double t, const State& x, PlateImpactResult& out) {
    out.e = -x[1];
    out.t_end = t * scales_.time;
    out.energy.initial = 0.5 * scales_.energy;
    out.energy.kinetic = 0.5 * x[1] * x[1] * scales_.energy;
    out.energy.plate = sys_.plate_energy(x) * scales_.energy;
    out.energy.plastic = law_.hysteresis_work(sys_.history).value_or(std::nan(""));
    out.impulse = (1.0 - x[1]) * scales_.energy / scales_.velocity;
    out.F_max = 0.0;
    for (const PlateContact& c : out.contacts) out.F_max = std::max(out.F_max, c.peak_force);
    out.t_contact = out.contacts.front().t_end - out.contacts.front().t_start;
    out.rhs_evaluations = sys_.evaluations();
    out.ok = true;
  }

  Law law_;
  System sys_;
  Scales scales_;
  PlateImpactOptions opt_;
  Stepper stepper_;
  typename System::History loading_history_{};
  double reload_force_ = 0.0;  // F(z_m) on the unloading branch, normalised
  std::optional<Root> fired_;  // the event the stepper was restarted on (locate(): post-event)
  State sample_ = State(sys_.size(), 0.0);  // record_force()'s interpolated state
};

}  // namespace ivv

#include "solver/plate/plate_free_flight.h"
