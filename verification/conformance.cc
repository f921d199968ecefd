#include "verification/conformance.h"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "scene/input_error.h"
#include "solver/law.h"
#include "solver/simulate_law.h"
#include "verification/conformance_law.h"
#include "verification/tolerances.h"

namespace ivv::conformance {
namespace {

// Rounding of a force formula in double, relative to the force scale F_ref: a few hundred ulps.
constexpr double kRounding = 1e-12;
constexpr const char* kRoundingWhy =
    "exact in exact arithmetic; 1e-12 F_ref allows the rounding of evaluating the formulas in "
    "double (a few hundred ulps)";
// Two exact derivatives (hand-written and autodiff) differ only by rounding, amplified by the
// conditioning of the formula; 1e-10 of the stiffness scale covers 1e6 ulps.
constexpr double kDerivative = 1e-10;
// The reference's error in e: mp50 ~1e-12 against closed forms; dp45 at rtol 1e-13 ~1e-10
// (global error N rtol over N <= 1000 steps). A rise of e above 1e-9 is the law's.
constexpr double kMonotone = 1e-9;

std::string fmt(double v, int precision = 6) {
  std::ostringstream os;
  os << std::setprecision(precision) << v;
  return os.str();
}

struct Scales {
  double z = 0, F = 0, k = 0, v = 0;  // z_ref [m], F_ref [N], k_ref [N/m], v [m/s]
};

Scales hertz_scales(const Scene& s, double v) {
  const DerivedParameters p = derive(s);
  Scales k;
  k.v = v;
  k.z = std::pow(5.0 * p.effective_mass * v * v / (4.0 * p.K_h), 0.4);
  k.F = p.K_h * k.z * std::sqrt(k.z);
  k.k = k.F / k.z;
  return k;
}

Check make_check(std::string id, double measured, double reference, double tolerance, bool passed,
                 std::string why, std::string detail) {
  return {std::move(id), passed, measured, reference, tolerance, std::move(why), std::move(detail)};
}

// Advance a fresh probe along first loading to z (through every kink below z).
void load_to(LawProbe& probe, double z) {
  probe.reset();
  while (auto end = probe.segment_end()) {
    if (*end >= z) break;
    probe.next_segment();
  }
}

class StaticChecks {
 public:
  StaticChecks(const LawUnderTest& law, const Scene& scene, double v_hi, Report& report)
      : law_(law), scene_(scene), k_(hertz_scales(scene, v_hi)), report_(report) {
    probe_ = law.probe(scene);
    loading_ = law.probe(scene);
  }

  void run() {
    onset();
    attractive_and_monotone();
    breakpoints();
    unloading();
    stiffness();
  }

 private:
  std::vector<double> zs(double hi, int n = 200) const {
    std::vector<double> out;
    for (int i = 1; i <= n; ++i) out.push_back(hi * i / n);
    return out;
  }
  std::vector<double> rates() const {
    if (!law_.rate_dependent) return {0.0};
    return {0.0, 0.5 * k_.v, k_.v};
  }
  std::vector<double> unloading_points() const {
    return {0.25 * k_.z, 0.5 * k_.z, k_.z, 2.0 * k_.z};
  }

  void onset() {
    probe_->reset();
    const double F0 = probe_->force(0.0, k_.v);
    report_.checks.push_back(
        make_check("static.onset", std::abs(F0) / k_.F, 0.0, kRounding,
                   std::abs(F0) <= kRounding * k_.F, kRoundingWhy,
                   "F(z = 0, zdot = " + fmt(k_.v) + " m/s) = " + fmt(F0) +
                       " N on first loading (F_ref = " + fmt(k_.F) + " N)" +
                       (std::abs(F0) > kRounding * k_.F
                            ? ": the force jumps at impact; a law that is not zero at z = 0 is not "
                              "continuous at onset (the paper's argument against Kelvin-Voigt)"
                            : "")));
  }

  void attractive_and_monotone() {
    double min_force = std::numeric_limits<double>::infinity(), where_min = 0;
    double worst_drop = 0, where_drop = 0;
    for (double v : rates()) {
      probe_->reset();
      double previous = probe_->force(0.0, v);
      for (double z : zs(2.0 * k_.z, 400)) {
        while (auto end = probe_->segment_end()) {
          if (*end >= z) break;
          probe_->next_segment();
        }
        const double F = probe_->force(z, v);
        if (F < min_force) min_force = F, where_min = z;
        if (v == 0.0 && previous - F > worst_drop) worst_drop = previous - F, where_drop = z;
        previous = F;
      }
    }
    // unloading at zdot = 0 above the permanent set
    for (double z_m : unloading_points()) {
      load_to(*probe_, z_m);
      try {
        probe_->begin_unloading(z_m);
      } catch (const LawDomainError&) {
        continue;
      }
      const double z_f = probe_->permanent_set();
      for (int i = 1; i <= 100; ++i) {
        const double z = z_f + (z_m - z_f) * i / 100.0;
        const double F = probe_->force(z, 0.0);
        if (F < min_force) min_force = F, where_min = z;
      }
    }
    const bool attractive = min_force < -kRounding * k_.F;
    std::string detail = "smallest force in contact " + fmt(min_force) +
                         " N at z = " + fmt(where_min) + " m (loading, and unloading above z_f)";
    if (attractive)
      detail += law_.allows_tension ? ": attractive, and the law declares tension"
                                    : ": the law pulls (F < 0) without declaring tension";
    report_.checks.push_back(make_check(
        "static.attractive", min_force / k_.F, 0.0, -kRounding, !attractive || law_.allows_tension,
        "a contact force cannot pull unless the law says so (--allow-tension); 1e-12 F_ref is "
        "rounding",
        detail));
    report_.checks.push_back(
        make_check("static.loading_monotone", worst_drop / k_.F, 0.0, kRounding,
                   worst_drop <= kRounding * k_.F, kRoundingWhy,
                   worst_drop > 0 ? "largest fall of F on first loading " + fmt(worst_drop) +
                                        " N, at z = " + fmt(where_drop) + " m"
                                  : "F never falls on first loading (400 points to 2 z_ref)"));
  }

  void breakpoints() {
    probe_->reset();
    double worst = 0;
    int count = 0;
    std::string where;
    while (auto end = probe_->segment_end()) {
      if (!(*end > 0) || count > 50) break;
      const double before = probe_->force(*end, 0.0);
      probe_->next_segment();
      const double after = probe_->force(*end, 0.0);
      ++count;
      if (std::abs(after - before) >= worst) {
        worst = std::abs(after - before);
        where = "z = " + fmt(*end) + " m: " + fmt(before, 12) + " N -> " + fmt(after, 12) + " N";
      }
    }
    if (count == 0) {
      report_.not_applicable.push_back({"static.breakpoints", "the law declares no kinks"});
      return;
    }
    report_.checks.push_back(
        make_check("static.breakpoints", worst / k_.F, 0.0, kRounding, worst <= kRounding * k_.F,
                   kRoundingWhy, std::to_string(count) + " kink(s); largest jump at " + where));
  }

  void unloading() {
    double jump = 0, above = 0, energy_err = 0;
    std::string jump_at, above_at, energy_at, skipped;
    int used = 0;
    for (double z_m : unloading_points()) {
      load_to(*probe_, z_m);
      const double F_load = probe_->force(z_m, 0.0);
      try {
        probe_->begin_unloading(z_m);
      } catch (const LawDomainError& e) {
        skipped += " z_m = " + fmt(z_m) + " m (" + e.what() + ")";
        continue;
      }
      ++used;
      const double F_un = probe_->force(z_m, 0.0);
      if (std::abs(F_un - F_load) >= jump)
        jump = std::abs(F_un - F_load), jump_at = "z_m = " + fmt(z_m) + " m: loading " +
                                                  fmt(F_load, 12) + " N, unloading " +
                                                  fmt(F_un, 12) + " N";
      const double z_f = probe_->permanent_set();
      for (int i = 0; i <= 100; ++i) {
        const double z = z_f + (z_m - z_f) * i / 100.0;
        load_to(*loading_, z);
        const double excess = probe_->force(z, 0.0) - loading_->force(z, 0.0);
        if (excess > above)
          above = excess, above_at = "z = " + fmt(z) + " m after z_m = " + fmt(z_m) + " m";
      }
      if (!probe_->stored_energy_is_quadrature()) {
        double error = 0;
        const double integral = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
            [&](double s) { return probe_->force(s, 0.0); }, z_f, z_m, 15, 1e-14, &error);
        const double stored = probe_->stored_energy(z_m);
        const double diff = std::abs(stored - integral) / (k_.F * k_.z);
        if (diff >= energy_err)
          energy_err = diff, energy_at = "z_m = " + fmt(z_m) + " m: stored_energy " +
                                         fmt(stored, 12) + " J, quadrature " + fmt(integral, 12) +
                                         " J";
      }
    }
    if (used == 0) {
      report_.checks.push_back(make_check("static.unloading_switch", NAN, 0.0, kRounding, false,
                                          kRoundingWhy,
                                          "the law could not unload from any z_m:" + skipped));
      return;
    }
    const std::string note = skipped.empty() ? "" : "; not defined at" + skipped;
    report_.checks.push_back(
        make_check("static.unloading_switch", jump / k_.F, 0.0, kRounding, jump <= kRounding * k_.F,
                   kRoundingWhy, "largest jump where unloading begins, at " + jump_at + note));
    report_.checks.push_back(make_check(
        "static.unloading_below", above / k_.F, 0.0, kRounding, above <= kRounding * k_.F,
        "an unloading curve above the loading curve returns more work than loading stored; "
        "1e-12 F_ref is rounding",
        above > 0 ? "unloading exceeds loading by " + fmt(above) + " N at " + above_at
                  : "unloading stays at or below loading (101 points per z_m)"));
    if (probe_->stored_energy_is_quadrature()) {
      report_.not_applicable.push_back(
          {"static.stored_energy",
           "the law computes its stored energy by quadrature of its own force: comparing it "
           "with another quadrature would prove nothing"});
    } else {
      report_.checks.push_back(make_check(
          "static.stored_energy", energy_err, 0.0, 1e-10, energy_err <= 1e-10,
          "61-point Gauss-Kronrod of a smooth branch converges to rounding (its own estimate "
          "is below 1e-13); 1e-10 of F_ref z_ref",
          "largest difference (in F_ref z_ref) at " + energy_at));
    }
  }

  void stiffness() {
    if (!probe_->autodiff_slopes(k_.z, 0.0)) {
      report_.not_applicable.push_back(
          {"static.stiffness",
           "the law is not templated on its scalar, so automatic differentiation cannot run it; "
           "its stiffness is a central difference of its own force (used only by implicit "
           "integrators and the peak-force event), and checking it with another difference "
           "would prove nothing"});
      return;
    }
    double worst = 0;
    std::string where;
    auto compare = [&](double z, double v, const char* regime) {
      const auto slopes = probe_->autodiff_slopes(z, v);
      const double k = probe_->stiffness(z, v), kv = probe_->rate_stiffness(z, v);
      const double dk = std::abs(k - slopes->first) / k_.k;
      const double dkv = std::abs(kv - slopes->second) * k_.v / k_.F;
      if (std::max(dk, dkv) >= worst) {
        worst = std::max(dk, dkv);
        where = std::string(regime) + " z = " + fmt(z) + " m, zdot = " + fmt(v) +
                " m/s: stiffness " + fmt(k, 12) + " vs autodiff " + fmt(slopes->first, 12) +
                " N/m; rate stiffness " + fmt(kv, 12) + " vs " + fmt(slopes->second, 12) + " N s/m";
      }
    };
    for (double v : rates()) {
      probe_->reset();
      for (double z : zs(2.0 * k_.z, 100)) {
        while (auto end = probe_->segment_end()) {
          if (*end >= z) break;
          probe_->next_segment();
        }
        compare(z, v, "loading");
      }
      for (double z_m : unloading_points()) {
        load_to(*probe_, z_m);
        try {
          probe_->begin_unloading(z_m);
        } catch (const LawDomainError&) {
          continue;
        }
        const double z_f = probe_->permanent_set();
        for (int i = 1; i <= 20; ++i) compare(z_f + (z_m - z_f) * i / 20.0, -v, "unloading");
      }
    }
    report_.checks.push_back(make_check(
        "static.stiffness", worst, 0.0, kDerivative, worst <= kDerivative,
        "hand-written and automatic derivatives are both exact; they differ by rounding "
        "amplified by the formula's conditioning (1e-10 of k_ref = F_ref/z_ref is 1e6 ulps)",
        "largest difference (in k_ref, and F_ref/v for dF/dzdot) at " + where));
  }

  const LawUnderTest& law_;
  Scene scene_;
  Scales k_;
  Report& report_;
  std::unique_ptr<LawProbe> probe_, loading_;
};

struct Run {
  double v0, zeta;
  ImpactResult reference;
  double reference_error = 0;  // estimate (double-precision reference only)
  std::vector<std::pair<IntegratorKind, ImpactResult>> runs;
};

Scene at(const Scene& base, double v0, double zeta) {
  Scene s = base;
  s.velocity = v0;
  s.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  return s;
}

void dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                    Report& report) {
  std::vector<double> zetas;
  for (double z : grid.zetas)
    if (z == 0 || !law.rate_dependent) zetas.push_back(z);
  std::vector<Run> runs;
  for (double zeta : zetas) {
    for (double v0 : grid.velocities) {
      Run r{v0, zeta, {}, 0, {}};
      const Scene s = at(grid.scene, v0, zeta);
      if (law.runs_in_reference) {
        r.reference = law.simulate(s, IntegratorKind::mp50, grid.options);
      } else {
        IntegratorOptions tight = grid.options;
        tight.rtol = 1e-13;
        tight.atol = 1e-15;
        r.reference = law.simulate(s, IntegratorKind::dp45, tight);
        tight.rtol = 1e-12;
        tight.atol = 1e-14;
        const ImpactResult looser = law.simulate(s, IntegratorKind::dp45, tight);
        r.reference_error = std::abs(looser.e - r.reference.e);
      }
      for (IntegratorKind k : grid.integrators)
        r.runs.push_back({k, law.simulate(s, k, grid.options)});
      runs.push_back(std::move(r));
    }
  }
  const std::string reference_name =
      law.runs_in_reference ? "mp50 (50 digits, tol 1e-26)" : "dp45 at rtol 1e-13";

  // COR curve (the reference runs)
  for (const Run& r : runs) {
    CorPoint c{r.v0, r.zeta, std::nullopt, std::nullopt,
               std::string(to_string(r.reference.status))};
    if (r.reference.ok())
      c.e = r.reference.e;
    else
      c.status = r.reference.reason;
    if (claims.expected_cor && r.zeta == 0) c.expected = claims.expected_cor(r.v0);
    report.cor.push_back(c);
  }

  // energy, COR range, COR definitions: every run
  double energy = 0, range = 0, definitions = 0;
  std::string energy_at = "every run", range_at = "every run", definitions_at = "every run";
  int failed = 0;
  std::string first_failure;
  auto label = [](const Run& r, std::string_view who) {
    return std::string(who) + " at v0 = " + fmt(r.v0) + " m/s, zeta = " + fmt(r.zeta);
  };
  auto judge = [&](const Run& r, std::string_view who, const ImpactResult& x) {
    if (!x.ok()) {
      if (failed++ == 0) first_failure = label(r, who) + ": " + x.reason;
      return;
    }
    const double res = std::abs(x.energy.residual) / x.energy.initial;
    if (res >= energy) energy = res, energy_at = label(r, who);
    const double out = std::max(-x.e, x.e - 1.0);
    if (out >= range) range = out, range_at = label(r, who) + ", e = " + fmt(x.e, 12);
    if (x.separated()) {
      const double d = std::max(std::abs(x.e - x.e_poisson), std::abs(x.e - x.e_energetic));
      if (d >= definitions)
        definitions = d, definitions_at = label(r, who) + ": Newton " + fmt(x.e, 12) +
                                          ", Poisson " + fmt(x.e_poisson, 12) + ", energetic " +
                                          fmt(x.e_energetic, 12);
    }
  };
  for (const Run& r : runs) {
    judge(r, "reference", r.reference);
    for (const auto& [k, x] : r.runs) judge(r, to_string(k), x);
  }
  const auto tol = verification::conservation_tolerance(IntegratorKind::odeint_dopri5);
  const std::string failures =
      failed ? "; " + std::to_string(failed) + " run(s) failed, first: " + first_failure : "";
  report.checks.push_back(make_check(
      "dynamic.energy", energy, 0.0, tol.value, energy <= tol.value && failed == 0, tol.reason,
      "largest |ledger residual| / E0 = " + fmt(energy) + " (" + energy_at + ")" + failures));
  report.checks.push_back(make_check(
      "dynamic.cor_range", range, 0.0, tol.value, range <= tol.value && failed == 0,
      "e outside [0, 1] by more than the integration error of e (as for the ledger)",
      range > 0 ? "largest excursion outside [0, 1]: " + fmt(range) + " (" + range_at + ")"
                : "0 <= e <= 1 in every run" + failures));
  report.checks.push_back(make_check(
      "dynamic.cor_definitions", definitions, 0.0, tol.value,
      definitions <= tol.value && failed == 0,
      "for a frictionless central impact of a point mass the three CORs are equal; they are "
      "integrated quantities with the error of the ledger",
      "largest difference " + fmt(definitions) + " (" + definitions_at + ")" + failures));

  // integrators against the reference
  double worst = 0;
  std::string worst_at = "no comparison";
  int compared = 0;
  std::string mismatch;
  for (const Run& r : runs) {
    if (!r.reference.ok()) continue;
    for (const auto& [k, x] : r.runs) {
      if (x.status != r.reference.status) {
        if (mismatch.empty())
          mismatch = label(r, to_string(k)) + " ended " + std::string(to_string(x.status)) +
                     (x.reason.empty() ? "" : " (" + x.reason + ")") + ", the reference " +
                     std::string(to_string(r.reference.status));
        continue;
      }
      ++compared;
      const double de = std::abs(x.e - r.reference.e);
      const double dF = std::abs(x.F_max - r.reference.F_max) / std::abs(r.reference.F_max);
      const double dt =
          std::abs(x.t_contact - r.reference.t_contact) / std::abs(r.reference.t_contact);
      const double d = std::max({de, dF, dt});
      if (d >= worst)
        worst = d, worst_at = label(r, to_string(k)) + ": |de| " + fmt(de) + ", F_max " + fmt(dF) +
                              ", t_contact " + fmt(dt) + " relative";
    }
  }
  double reference_error = 0;
  for (const Run& r : runs) reference_error = std::max(reference_error, r.reference_error);
  const auto itol = verification::default_settings_tolerance(IntegratorKind::odeint_dopri5);
  report.checks.push_back(make_check(
      "dynamic.integrators", worst, 0.0, itol.value,
      worst <= itol.value && mismatch.empty() && compared > 0, itol.reason,
      std::to_string(compared) + " runs against " + reference_name +
          (law.runs_in_reference ? ""
                                 : " (its own error estimated at " + fmt(reference_error) +
                                       " in e from its run at 1e-12)") +
          "; largest difference at " + worst_at + (mismatch.empty() ? "" : "; " + mismatch)));

  // trends of the reference's e
  auto e_of = [&](double v0, double zeta) -> std::optional<double> {
    for (const Run& r : runs)
      if (r.v0 == v0 && r.zeta == zeta && r.reference.ok()) return r.reference.e;
    return std::nullopt;
  };
  if (claims.cor_nonincreasing_in_v0) {
    double rise = 0;
    std::string at = "e never rises with v0";
    for (double zeta : zetas)
      for (std::size_t i = 1; i < grid.velocities.size(); ++i) {
        const auto a = e_of(grid.velocities[i - 1], zeta), b = e_of(grid.velocities[i], zeta);
        if (a && b && *b - *a > rise)
          rise = *b - *a, at = "e rises by " + fmt(rise) +
                               " from v0 = " + fmt(grid.velocities[i - 1]) + " to " +
                               fmt(grid.velocities[i]) + " m/s at zeta = " + fmt(zeta);
      }
    report.checks.push_back(make_check(
        "dynamic.monotone_v0", rise, 0.0, kMonotone, rise <= kMonotone,
        "the reference's error in e is at most 1e-10; a rise above 1e-9 is the law's", at));
  } else {
    report.not_applicable.push_back({"dynamic.monotone_v0", "not claimed"});
  }
  if (claims.cor_nonincreasing_in_damping && zetas.size() > 1) {
    double rise = 0;
    std::string at = "e never rises with the damping ratio";
    for (double v0 : grid.velocities)
      for (std::size_t i = 1; i < zetas.size(); ++i) {
        const auto a = e_of(v0, zetas[i - 1]), b = e_of(v0, zetas[i]);
        if (a && b && *b - *a > rise)
          rise = *b - *a, at = "e rises by " + fmt(rise) + " from zeta = " + fmt(zetas[i - 1]) +
                               " to " + fmt(zetas[i]) + " at v0 = " + fmt(v0) + " m/s";
      }
    report.checks.push_back(make_check(
        "dynamic.monotone_damping", rise, 0.0, kMonotone, rise <= kMonotone,
        "the reference's error in e is at most 1e-10; a rise above 1e-9 is the law's", at));
  } else {
    report.not_applicable.push_back(
        {"dynamic.monotone_damping",
         law.rate_dependent ? "the law carries its own damping: no series dashpot to vary"
                            : "not claimed"});
  }
  if (claims.elastic_at_low_speed) {
    // 1 - e at the three lowest velocities: zero within the reference's error, or falling as a
    // power of v0 (viscoelastic laws: 1 - e ~ v0^{1/5}); any exponent the reference's error
    // cannot explain is a fall, since the claim is only that the loss vanishes as v0 -> 0
    std::vector<double> lv, lq;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, grid.velocities.size()); ++i)
      if (auto e = e_of(grid.velocities[i], 0.0)) {
        lv.push_back(std::log(grid.velocities[i]));
        lq.push_back(std::log(std::max(1.0 - *e, 1e-300)));
      }
    const auto e_low = e_of(grid.velocities.front(), 0.0);
    const double loss = e_low ? 1.0 - *e_low : NAN;
    double slope = NAN, slope_noise = NAN;
    if (lv.size() >= 2) {
      slope = (lq.back() - lq.front()) / (lv.back() - lv.front());
      // the reference's error kMonotone in e moves ln(1 - e) by kMonotone/(1 - e) at each end
      const double smallest_loss = std::exp(std::min(lq.front(), lq.back()));
      slope_noise = 2.0 * kMonotone / smallest_loss / (lv.back() - lv.front());
    }
    const bool exact = e_low && loss <= kMonotone;
    const bool vanishing = std::isfinite(slope) && slope > slope_noise;
    report.checks.push_back(make_check(
        "dynamic.low_speed", exact ? loss : slope, exact ? 0.0 : slope_noise,
        exact ? kMonotone : slope_noise, exact || vanishing,
        "elastic at low speed: 1 - e within the reference's error of e (1e-9) at the lowest v0, "
        "or 1 - e falling with v0 over the three lowest: its local exponent above what the "
        "reference's error alone could produce, 2e-9/((1 - e) ln(v_3/v_1)) (viscoelastic laws: "
        "1/5)",
        "1 - e = " + fmt(loss) + " at v0 = " + fmt(grid.velocities.front()) +
            " m/s; local exponent of 1 - e in v0: " + fmt(slope, 4) +
            (std::isfinite(slope_noise) ? " (noise bound " + fmt(slope_noise, 3) + ")" : "")));
  } else {
    report.not_applicable.push_back({"dynamic.low_speed", "not claimed"});
  }
  if (claims.expected_cor) {
    double miss = 0, signed_miss = 0;
    std::string at = "no separated run";
    int n = 0;
    for (const CorPoint& c : report.cor) {
      if (!c.expected || !c.e) continue;
      ++n;
      const double d = *c.e - *c.expected;
      if (!std::isfinite(d)) {  // never a silent pass on a NaN (run_conformance refuses those)
        miss = signed_miss = std::numeric_limits<double>::infinity();
        at = "v0 = " + fmt(c.v0) + " m/s: delivered e = " + fmt(*c.e, 10) + ", expected " +
             fmt(*c.expected, 10);
        break;
      }
      if (std::abs(d) >= miss)
        miss = std::abs(d), signed_miss = d,
        at = "v0 = " + fmt(c.v0) + " m/s: delivered e = " + fmt(*c.e, 10) + ", expected " +
             fmt(*c.expected, 10);
    }
    report.checks.push_back(
        make_check("dynamic.expected_cor", miss, 0.0, claims.cor_tolerance,
                   n > 0 && miss <= claims.cor_tolerance, claims.cor_tolerance_reason,
                   "largest |e - (" + claims.expected_cor_text + ")| = " + fmt(miss) + " (" +
                       (signed_miss > 0 ? "over" : "under") + "), at " + at + "; " +
                       std::to_string(n) + " velocities"));
  } else {
    report.not_applicable.push_back({"dynamic.expected_cor", "no COR claimed (--expect-cor)"});
  }
}

}  // namespace

bool Report::passed() const {
  return !checks.empty() &&
         std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
}

std::string Report::brief() const {
  std::ostringstream os;
  int failed = 0;
  for (const Check& c : checks) failed += !c.passed;
  os << "law " << law << ": " << (passed() ? "PASS" : "FAIL") << " (" << checks.size() - failed
     << " of " << checks.size() << " checks passed";
  if (failed) {
    os << "; failed:";
    for (const Check& c : checks)
      if (!c.passed) os << ' ' << c.id;
  }
  os << ")";
  return os.str();
}

std::string Report::full() const {
  std::ostringstream os;
  os << "law " << law << ": " << description << "\n";
  for (const Check& c : checks)
    os << "  " << (c.passed ? "pass" : "FAIL") << "  " << std::left << std::setw(26) << c.id << " "
       << c.detail << " (tolerance " << fmt(c.tolerance, 3) << ")\n";
  for (const auto& [id, why] : not_applicable)
    os << "  n/a   " << std::left << std::setw(26) << id << " " << why << "\n";
  os << brief() << "\n";
  return os.str();
}

std::vector<verification::Plot> Report::plots() const {
  using verification::Plot;
  using verification::Series;
  Plot p;
  p.id = "conformance-cor-" + law;
  for (char& c : p.id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '-';
  p.title = "COR delivered by " + law;
  p.x_label = "impact velocity v0 [m/s]";
  p.y_label = "coefficient of restitution e";
  p.log_x = true;
  std::vector<double> zetas;
  for (const CorPoint& c : cor)
    if (std::find(zetas.begin(), zetas.end(), c.zeta) == zetas.end()) zetas.push_back(c.zeta);
  for (double zeta : zetas) {
    Series s;
    s.label = zeta == 0 ? "no dashpot" : "zeta = " + fmt(zeta);
    s.style = Series::Style::linespoints;
    for (const CorPoint& c : cor)
      if (c.zeta == zeta && c.e) s.x.push_back(c.v0), s.y.push_back(*c.e);
    p.series.push_back(std::move(s));
  }
  Series expected;
  expected.label = "claimed COR";
  expected.style = Series::Style::dashed;
  for (const CorPoint& c : cor)
    if (c.expected) expected.x.push_back(c.v0), expected.y.push_back(*c.expected);
  if (!expected.x.empty()) p.series.push_back(std::move(expected));
  return {p};
}

nlohmann::json to_json(const Report& report) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json checks = nlohmann::json::array();
  for (const Check& c : report.checks)
    checks.push_back({{"id", c.id},
                      {"passed", c.passed},
                      {"measured", num(c.measured)},
                      {"reference", num(c.reference)},
                      {"tolerance", num(c.tolerance)},
                      {"why", c.why},
                      {"detail", c.detail}});
  nlohmann::json na = nlohmann::json::array();
  for (const auto& [id, why] : report.not_applicable) na.push_back({{"id", id}, {"why", why}});
  nlohmann::json cor = nlohmann::json::array();
  for (const CorPoint& c : report.cor)
    cor.push_back({{"v0", c.v0},
                   {"zeta", c.zeta},
                   {"e", c.e ? num(*c.e) : nlohmann::json()},
                   {"expected", c.expected ? num(*c.expected) : nlohmann::json()},
                   {"status", c.status}});
  return {{"verdict", report.passed() ? "pass" : "fail"},
          {"law", {{"name", report.law}, {"description", report.description}}},
          {"checks", checks},
          {"not_applicable", na},
          {"cor", cor}};
}

Grid default_grid(const Scene& scene) {
  Grid g;
  g.scene = scene;
  // a damping ratio is defined through the yield stiffness K_y (zeta = sqrt(m* K_y)/(2c)): a
  // scene without a yield strength has none, and its default grid is undamped (issue 21 item
  // 14: check-law on chung-ooi-1-glass blamed damping.zeta, which the user had not given)
  if (!scene.yield_strength) g.zetas = {0.0};
  // A scene whose dashpot comes from its [structure] (and that has a yield strength) is
  // checked without a dashpot and with that dashpot: zeta = sqrt(m K_y)/(2 c) gives back the
  // structure's c at every v0.
  if (scene.damping.kind == Damping::Kind::structure && scene.yield_strength)
    g.zetas = {0.0, derive(scene).zeta};
  return g;
}

namespace {
// A claimed COR is a number in [0, 1] at every velocity of the grid; anything else (0/0,
// sqrt(-1), 1.5) is bad input, not a claim a check could pass (issue 21 item 3).
void require_cor_claim_in_range(const Claims& claims, const std::vector<double>& velocities) {
  if (!claims.expected_cor) return;
  for (double v0 : velocities) {
    const double e = claims.expected_cor(v0);
    if (std::isfinite(e) && e >= 0.0 && e <= 1.0) continue;
    throw InputError("--expect-cor", "'" + claims.expected_cor_text + "' evaluates to " + fmt(e) +
                                         " at v0 = " + fmt(v0) +
                                         " m/s; a COR is a finite number in [0, 1]");
  }
}
}  // namespace

Report run_conformance(const LawUnderTest& law, const Claims& claims, const Grid& given) {
  Grid grid = given;
  if (grid.velocities.empty()) {
    const double v = grid.scene.velocity;
    for (int i = 0; i < 7; ++i) grid.velocities.push_back(v * std::pow(10.0, -2.0 + 0.5 * i));
  }
  std::sort(grid.velocities.begin(), grid.velocities.end());
  if (grid.zetas.empty()) grid.zetas = {0.0};
  std::sort(grid.zetas.begin(), grid.zetas.end());
  require_cor_claim_in_range(claims, grid.velocities);  // bad input before any run
  Report report;
  report.law = law.name;
  report.description = law.description;
  StaticChecks(law, at(grid.scene, grid.velocities.back(), 0.0), grid.velocities.back(), report)
      .run();
  dynamic_checks(law, claims, grid, report);
  return report;
}

LawUnderTest registry_law(const SimulationRequest& request) {
  LawUnderTest t;
  const LawInfo& info = law_info(request.law);
  t.name = request.law == LawKind::expression ? "expression" : std::string(info.name);
  t.description = std::string(info.summary);
  SimulationRequest base = request;
  if (request.law == LawKind::expression) {
    t.description = "F = " + request.expression.force;
    if (!request.expression.unload.empty())
      t.description += "; unloading F = " + request.expression.unload;
    t.description += request.expression.allow_tension ? "; tension allowed, contact ends at z = 0"
                                                      : "; clamped F >= 0, contact ends at F = 0";
    t.allows_tension = request.expression.allow_tension;
    t.runs_in_reference = false;
    t.rate_dependent = detail::compile_expression_law(request, derive(request.scene))->uses_rate();
    t.probe = [base](const Scene& s) -> std::unique_ptr<LawProbe> {
      const auto compiled = detail::compile_expression_law(
          [&] {
            SimulationRequest r = base;
            r.scene = s;
            return r;
          }(),
          derive(s));
      if (compiled->uses_rate())
        return std::make_unique<TypedProbe<ExpressionLaw<true>>>(
            ExpressionLaw<true>{compiled, base.expression.allow_tension});
      return std::make_unique<TypedProbe<ExpressionLaw<false>>>(
          ExpressionLaw<false>{compiled, base.expression.allow_tension});
    };
  } else {
    t.rate_dependent = info.rate_dependent;
    t.probe = [base](const Scene& s) -> std::unique_ptr<LawProbe> {
      return with_builtin_law(base.law, base.parameters, derive(s),
                              [](const auto& law) -> std::unique_ptr<LawProbe> {
                                using Law = std::decay_t<decltype(law)>;
                                return std::make_unique<TypedProbe<Law>>(law);
                              });
    };
  }
  t.simulate = [base](const Scene& s, IntegratorKind k, const IntegratorOptions& o) {
    SimulationRequest r = base;
    r.scene = s;
    r.integrator = k;
    r.options = o;
    return ivv::simulate(r);
  };
  return t;
}

}  // namespace ivv::conformance
