// The dynamic checks of a contact law on a finite plate (`ivv check-law --scene PLATE`): the law
// between the impactor and the plate's modes (solver/plate/plate_impact.h), at each velocity of
// the grid, by the plate's own integration (the exponential stepper at the grid's tolerances,
// odeint's dopri5 as a second stepper, dop853 at rtol 1e-12 as the reference). A plate has no
// series dashpot: its modes carry the energy away, and may give it back (reloading, repeated
// contacts).
//   dynamic.energy        the ledger closes with the plate's vibration energy at the end:
//                         (1/2) m v0^2 = (1/2) m alpha'_f^2 + E_plate + W_p, W_p the loop of the
//                         largest z_m computed here from the law (quadrature of its loading and
//                         unloading curves), and the driver's own ledger at every event
//   dynamic.impulse       int F dt (Milne's rule on the force sampled inside each step of the
//                         stepper's interpolant) = m (v0 - alpha'_final)
//   dynamic.cor_range     the final e in [0, 1]
//   dynamic.integrators   the two steppers agree with the reference on e, e_first, F_max,
//                         t_contact and the contact count (a run over the tolerance is repeated
//                         at 1/1000 of its tolerances before the law is blamed)
//   dynamic.expected_cor  the claimed COR against the final e, the tolerance widened by the
//                         plate's estimated truncation error in e (|e - e(cut-off/2)|/7,
//                         solver/plate/plate_run.h)
// Skipped, each with its reason: the COR definitions (one Newton COR after every contact), the
// trends in v0 and damping and the low-speed and capture claims (claims about the law that the
// plate's ringing can break or that it does not model).
#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "scene/input_error.h"
#include "solver/laws/law.h"
#include "verification/conformance_internal.h"

namespace ivv::conformance::detail {
namespace {

// The plate runs' cross-checks: each at the grid's rtol = 1e-10 per step, global error at most
// N rtol over N steps (the 5 mm ball on the 200 mm plate takes ~150 steps per contact).
constexpr double kPlateTolerance = 1e-7;
constexpr const char* kPlateTolerancelWhy =
    "the plate's stepper at rtol = 1e-10 per step: local errors add over the N steps of the "
    "contacts, a global error of at most N rtol (1e-7 for N <= 1000); free flights are exact";

PlateImpactOptions plate_options(const Grid& grid) {
  PlateImpactOptions o;
  o.rtol = grid.options.rtol;
  o.atol = grid.options.atol;
  return o;
}

// int F dz along first loading from 0 to z_M, through each kink, minus the area under the
// unloading curve of z_M from z_f: the plastic work of the loop [J].
double plastic_work(const LawUnderTest& law, const Scene& scene, double z_M) {
  auto probe = law.probe(scene);
  auto gk = [](const std::function<double(double)>& f, double a, double b) {
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, a, b, 15, 1e-13);
  };
  double loading = 0, from = 0;
  probe->reset();
  for (;;) {
    const std::optional<double> end = probe->segment_end();
    const double to = end && *end < z_M ? *end : z_M;
    loading += gk([&](double z) { return probe->force(z, 0.0); }, from, to);
    if (to == z_M) break;
    probe->next_segment();
    from = to;
  }
  probe->begin_unloading(z_M);
  const double z_f = probe->permanent_set();
  return loading - gk([&](double z) { return probe->force(z, 0.0); }, z_f, z_M);
}

// int F dt from PlateImpactResult::force_history: per contact its onset (t_start, 0), then four
// samples per step at 1/4, 1/2, 3/4 and 1 of the step; Milne's open rule on the three inside the
// step, h (2 F_1/4 - F_1/2 + 2 F_3/4)/3 (exact for cubics), so that no sample taken on another
// branch (before an event, where a law may jump) enters. Its error per step is ~3e-4 h^5 F^(4):
// far below 1e-7 of the impulse at the plate's steps. NaN when the samples are not in that layout.
double force_impulse(const PlateImpactResult& r) {
  const auto& h = r.force_history;
  double total = 0;
  std::size_t i = 0;
  for (std::size_t c = 0; c < r.contacts.size(); ++c) {
    if (i >= h.size() || h[i][0] != r.contacts[c].t_start || h[i][1] != 0.0) return NAN;
    std::size_t end = i + 1;  // one past this contact's samples: the next contact's onset
    while (end < h.size() && !(c + 1 < r.contacts.size() &&
                               h[end][0] == r.contacts[c + 1].t_start && h[end][1] == 0.0))
      ++end;
    if ((end - i - 1) % 4 != 0) return NAN;
    for (std::size_t k = i + 1; k < end; k += 4) {
      const double width = 2.0 * (h[k + 2][0] - h[k][0]);
      total += width * (2.0 * h[k][1] - h[k + 1][1] + 2.0 * h[k + 2][1]) / 3.0;
    }
    i = end;
  }
  return i == h.size() ? total : NAN;
}

std::string point_label(double v0, const char* who) {
  return std::string(who) + " at v0 = " + fmt(v0) + " m/s";
}

constexpr const char* kRuns[] = {"reference (dop853 at rtol 1e-12)", "exponential",
                                 "odeint-dopri5"};

class PlateChecks {
 public:
  PlateChecks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
              const PlateGrid& runs, ConformanceResult& result)
      : law_(law), claims_(claims), grid_(grid), runs_(runs), result_(result) {}

  void run() {
    if (!runs_.refused.empty()) {
      for (const char* id : {"dynamic.energy", "dynamic.impulse", "dynamic.cor_range",
                             "dynamic.integrators", "dynamic.expected_cor"})
        result_.skipped.push_back({id, "not run on the finite plate: " + runs_.refused});
      skip_the_rest();
      return;
    }
    cor_points();
    energy();
    impulse();
    cor_range();
    integrators();
    expected_cor();
    skip_the_rest();
  }

 private:
  // the three runs of a point: reference (dop853), the exponential stepper, odeint-dopri5
  static std::array<const PlateImpactResult*, 3> runs_of(const PlatePoint& p) {
    return {&p.reference, &p.run, &p.second};
  }

  void cor_points() {
    for (const PlatePoint& p : runs_.points) {
      CorPoint c;
      c.v0 = p.v0;
      c.finite_plate = true;
      c.status = p.reference.ok ? "separated" : p.reference.reason;
      if (p.reference.ok) c.e = p.reference.e;
      if (claims_.expected_cor) c.expected = claims_.expected_cor(p.v0);
      result_.cor.push_back(c);
    }
  }

  // A run that failed fails the check that needed it, with its reason.
  void note_failure(const PlatePoint& p, int k, std::string& failures, int& count) const {
    if (count++ == 0)
      failures = "; failed: " + point_label(p.v0, kRuns[k]) + ": " +
                 runs_of(p)[static_cast<std::size_t>(k)]->reason;
  }

  void energy() {
    double worst = 0;
    std::string at = "no run", failures;
    int n = 0, failed = 0;
    for (const PlatePoint& p : runs_.points) {
      const Scene s = at_velocity(grid_.scene, p.v0);
      for (int k = 0; k < 3; ++k) {
        const PlateImpactResult& r = *runs_of(p)[static_cast<std::size_t>(k)];
        if (!r.ok) {
          note_failure(p, k, failures, failed);
          continue;
        }
        ++n;
        const double W_p = plastic_work(law_, s, r.z_max);
        const PlateEnergy& e = r.energy;
        const double end = std::abs(e.initial - e.kinetic - e.plate - W_p) / e.initial;
        const double measured = std::max(end, e.max_error);
        if (measured >= worst || at == "no run")
          worst = measured, at = point_label(p.v0, kRuns[k]) +
                                 ": (1/2) m v0^2 = " + fmt(e.initial, 10) +
                                 " J against (1/2) m alpha'^2 " + fmt(e.kinetic, 10) +
                                 " J + plate " + fmt(e.plate, 10) + " J + W_p " + fmt(W_p, 10) +
                                 " J (end residual " + fmt(end) + ", the driver's ledger over " +
                                 std::to_string(e.checks) + " events " + fmt(e.max_error) + ")";
      }
    }
    Check& c = result_.checks.emplace_back(
        make_check("dynamic.energy", worst, 0.0, kPlateTolerance,
                   worst <= kPlateTolerance && failed == 0 && n > 0, kPlateTolerancelWhy,
                   "the ledger with the plate's vibration energy, largest residual (in E0) at " +
                       at + "; W_p from the law's loading and unloading curves" + failures));
    c.unit = "E0", c.unit_si = NAN, c.si_unit = "J";
  }

  void impulse() {
    double worst = 0;
    std::string at = "no run", failures;
    int n = 0, failed = 0;
    for (const PlatePoint& p : runs_.points)
      for (int k = 1; k < 3; ++k) {
        const PlateImpactResult& r = *runs_of(p)[static_cast<std::size_t>(k)];
        if (!r.ok) {
          note_failure(p, k, failures, failed);
          continue;
        }
        const double J = force_impulse(r);
        if (std::isnan(J)) {
          result_.skipped.push_back({"dynamic.impulse",
                                     "the plate run's force samples are not four per step (the "
                                     "layout the quadrature needs): int F dt cannot be formed"});
          return;
        }
        ++n;
        const double momentum = 2.0 * r.energy.initial / p.v0;  // m v0
        const double d = std::abs(J - r.impulse) / momentum;
        if (d >= worst || at == "no run")
          worst = d, at = point_label(p.v0, kRuns[k]) + ": int F dt = " + fmt(J, 12) +
                          " N s, m (v0 - alpha'_final) = " + fmt(r.impulse, 12) + " N s over " +
                          std::to_string(r.contacts.size()) + " contact(s)";
      }
    Check& c = result_.checks.emplace_back(
        make_check("dynamic.impulse", worst, 0.0, kPlateTolerance,
                   worst <= kPlateTolerance && failed == 0 && n > 0,
                   std::string(kPlateTolerancelWhy) +
                       "; Milne's rule per step adds far less (~3e-4 h^5 F^(4) a step)",
                   "largest |int F dt - m (v0 - alpha'_final)| (in m v0) at " + at + failures));
    c.unit = "m v0", c.unit_si = NAN, c.si_unit = "N s";
  }

  void cor_range() {
    double worst = 0;
    std::string at = "every final e in [0, 1]", failures;
    int failed = 0;
    for (const PlatePoint& p : runs_.points)
      for (int k = 0; k < 3; ++k) {
        const PlateImpactResult& r = *runs_of(p)[static_cast<std::size_t>(k)];
        if (!r.ok) {
          note_failure(p, k, failures, failed);
          continue;
        }
        const double out = std::max(-r.e, r.e - 1.0);
        if (out > worst)
          worst = out, at = point_label(p.v0, kRuns[k]) + ": e = " + fmt(r.e, 12) + " (e_first " +
                            fmt(r.e_first, 6) + ")";
      }
    result_.checks.push_back(make_check(
        "dynamic.cor_range", worst, 0.0, kPlateTolerance, worst <= kPlateTolerance && failed == 0,
        kPlateTolerancelWhy,
        "the final e after every contact (e_first at the first separation may be negative: "
        "the plate outran the ball); " +
            at + failures));
  }

  void integrators();
  void expected_cor();
  void skip_the_rest();

  const LawUnderTest& law_;
  const Claims& claims_;
  const Grid& grid_;
  const PlateGrid& runs_;
  ConformanceResult& result_;
};

// How far run x is from the reference: e, e_first, F_max and t_contact relative; infinite when
// the contact counts differ or either failed.
double plate_difference(const PlateImpactResult& x, const PlateImpactResult& ref) {
  if (!x.ok || !ref.ok || x.contacts.size() != ref.contacts.size())
    return std::numeric_limits<double>::infinity();
  return std::max({std::abs(x.e - ref.e), std::abs(x.e_first - ref.e_first),
                   std::abs(x.F_max / ref.F_max - 1.0),
                   std::abs(x.t_contact / ref.t_contact - 1.0)});
}

std::string plate_outcome(const PlateImpactResult& r) {
  if (!r.ok) return "failed (" + r.reason + ")";
  return "e = " + fmt(r.e, 12) + ", e_first = " + fmt(r.e_first, 12) +
         ", F_max = " + fmt(r.F_max, 10) + " N, t_contact = " + fmt(r.t_contact, 10) + " s, " +
         std::to_string(r.contacts.size()) + " contact(s)";
}

void PlateChecks::integrators() {
  double worst = 0;
  std::string at = "no comparison", failures;
  int compared = 0, failed = 0;
  for (const PlatePoint& p : runs_.points) {
    if (!p.reference.ok) {
      note_failure(p, 0, failures, failed);
      continue;
    }
    for (int k = 1; k < 3; ++k) {
      const PlateImpactResult& r = *runs_of(p)[static_cast<std::size_t>(k)];
      double d = plate_difference(r, p.reference);
      ++compared;
      if (d > kPlateTolerance) {  // repeated tighter before the law is blamed
        PlateImpactOptions tight = plate_options(grid_);
        tight.rtol = std::max(1e-3 * tight.rtol, 1e-13);
        tight.atol = std::max(1e-3 * tight.atol, 1e-15);
        if (k == 2) tight.stepper = PlateImpactOptions::Stepper::odeint_dopri5;
        const double d_tight = plate_difference(
            law_.simulate_plate(at_velocity(grid_.scene, p.v0), tight), p.reference);
        if (d_tight <= kPlateTolerance) {
          IntegratorNote n;
          n.check = "dynamic.integrators";
          n.integrator = kRuns[k];
          n.v0 = p.v0;
          n.damping = "finite plate";
          n.error = d, n.tolerance = kPlateTolerance, n.error_tight = d_tight;
          n.detail = plate_outcome(r) + " against the reference's " + plate_outcome(p.reference) +
                     "; at rtol " + fmt(tight.rtol) + ": " + fmt(d_tight);
          result_.notes.push_back(std::move(n));
          d = d_tight;
        }
      }
      if (d >= worst || at == "no comparison")
        worst = d, at = point_label(p.v0, kRuns[k]) + ": " + plate_outcome(r) +
                        " against the reference's " + plate_outcome(p.reference);
    }
  }
  result_.checks.push_back(make_check(
      "dynamic.integrators", worst, 0.0, kPlateTolerance,
      worst <= kPlateTolerance && failed == 0 && compared > 0, kPlateTolerancelWhy,
      "the plate's steppers against dop853 at rtol 1e-12 (the same modes): largest of |e|, "
      "|e_first|, |F_max| and |t_contact| (relative) differences, the contact counts equal, at " +
          at + failures));
}

void PlateChecks::expected_cor() {
  if (!claims_.expected_cor) {
    result_.skipped.push_back({"dynamic.expected_cor", "no COR claimed (--expect-cor)"});
    return;
  }
  double truncation = 0;
  for (const PlatePoint& p : runs_.points) truncation = std::max(truncation, p.truncation_error);
  const double tol = claims_.cor_tolerance + truncation;
  double miss = 0;
  std::optional<std::pair<double, double>> worst;
  std::string at = "no run", failures;
  int n = 0, failed = 0;
  for (const CorPoint& c : result_.cor) {
    if (!c.e) {
      if (failed++ == 0) failures = "; not judged at v0 = " + fmt(c.v0) + " m/s: " + c.status;
      continue;
    }
    ++n;
    const double d = std::abs(*c.e - *c.expected);
    if (!(d < miss) || at == "no run")
      miss = d, worst = std::pair{*c.e, *c.expected},
      at = "v0 = " + fmt(c.v0) + " m/s: final e = " + fmt(*c.e, 10) + ", expected " +
           fmt(*c.expected, 10);
  }
  Check& c = result_.checks.emplace_back(make_check(
      "dynamic.expected_cor", miss, 0.0, tol, n > 0 && failed == 0 && miss <= tol,
      claims_.cor_tolerance_reason + "; plus the plate's estimated truncation error in e, " +
          fmt(truncation) + " (|e - e(cut-off/2)|/7, the largest over the grid)",
      "largest |e - (" + claims_.expected_cor_text + ")| on the final e at " + at + "; " +
          std::to_string(n) + " velocities judged" + failures));
  if (worst) c.value = worst->first, c.reference_value = worst->second, c.value_unit = "-";
}

void PlateChecks::skip_the_rest() {
  result_.skipped.push_back(
      {"dynamic.cor_definitions",
       "a finite plate defines one COR, the Newton COR after the last contact: Poisson's and the "
       "energetic COR belong to one compression and one restitution, which repeated contacts and "
       "reloading do not have"});
  result_.skipped.push_back(
      {"dynamic.monotone_v0",
       "on a finite plate the final e need not fall with v0 for a law whose e does on a rigid "
       "target: the contact time, and with it what the plate's ringing gives back, changes with "
       "v0 (check the trend on a scene without the plate)"});
  result_.skipped.push_back({"dynamic.monotone_damping",
                             "a finite plate has no series dashpot to vary: its modes "
                             "carry the energy away"});
  result_.skipped.push_back(
      {"dynamic.low_speed", claims_.elastic_at_low_speed
                                ? "e -> 1 as v0 -> 0 is a claim about the law on a rigid target: "
                                  "a plate keeps vibration energy, so e < 1 for an elastic law "
                                  "too (check it on a scene without the plate)"
                                : "not claimed (--elastic-at-low-speed)"});
  const char* capture =
      "capture is not modelled on a finite plate (its laws are clamped at F >= 0: every contact "
      "ends, and the flight is free)";
  result_.skipped.push_back(
      {"dynamic.increasing_v0",
       claims_.cor_nondecreasing_in_v0 ? capture : "not claimed (--cor-increasing-in-v0)"});
  result_.skipped.push_back({"dynamic.captured_below", claims_.captured_below
                                                           ? capture
                                                           : "not claimed (--captured-below V)"});
}

}  // namespace

PlateGrid run_plate_grid(const LawUnderTest& law, const Grid& grid) {
  PlateGrid out;
  if (!law.simulate_plate) {
    out.refused = "the law under test gives no plate run (a rate-dependent C++ law)";
    return out;
  }
  const PlateImpactOptions opt = plate_options(grid);
  PlateImpactOptions recorded = opt, second = opt, reference = opt, half = opt;
  recorded.record_force = second.record_force = true;
  second.stepper = PlateImpactOptions::Stepper::odeint_dopri5;
  reference.stepper = PlateImpactOptions::Stepper::dop853;
  reference.rtol = 1e-12;
  reference.atol = 1e-14;
  half.cutoff /= 2.0;
  for (double v0 : grid.velocities) {
    const Scene s = at_velocity(grid.scene, v0);
    PlatePoint p;
    p.v0 = v0;
    try {
      p.reference = law.simulate_plate(s, reference);
    } catch (const InputError& e) {
      out.refused = e.what();  // "FIELD: why"
      out.points.clear();
      return out;
    }
    p.run = law.simulate_plate(s, recorded);
    p.second = law.simulate_plate(s, second);
    const PlateImpactResult h = law.simulate_plate(s, half);
    if (h.ok && p.run.ok) p.truncation_error = std::abs(p.run.e - h.e) / 7.0;
    out.points.push_back(std::move(p));
  }
  return out;
}

Scene at_velocity(const Scene& base, double v0) {
  Scene s = base;
  s.velocity = v0;
  return s;
}

void plate_dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                          const PlateGrid& runs, ConformanceResult& result) {
  PlateChecks(law, claims, grid, runs, result).run();
}

}  // namespace ivv::conformance::detail
