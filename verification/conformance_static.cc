// The static checks of a contact law: its equations on one scene, no integrator
// (verification/conformance.h lists each check with its tolerance and why).
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "solver/laws/law.h"
#include "verification/conformance_internal.h"
#include "verification/continuity_scan.h"

namespace ivv::conformance::detail {
namespace {

class StaticChecks {
 public:
  StaticChecks(const LawUnderTest& law, const Scene& scene, double v_hi, double z_scan,
               ConformanceResult& report)
      : law_(law), scene_(scene), k_(hertz_scales(scene, v_hi)), z_scan_(z_scan), report_(report) {
    probe_ = law.probe(scene);
    loading_ = law.probe(scene);
  }

  void run() {
    onset();
    attractive_and_monotone();
    breakpoints();
    continuity();
    unloading();
    stiffness();
  }

 private:
  Check& push(Check c, std::string unit, double unit_si, std::string si_unit) {
    c.unit = std::move(unit);
    c.unit_si = unit_si;
    c.si_unit = std::move(si_unit);
    report_.checks.push_back(std::move(c));
    return report_.checks.back();
  }
  Check& push_force(Check c) { return push(std::move(c), "F_ref", k_.F, "N"); }

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

  // F(0, v0) on first loading against 0, or against the force the law declares there (an
  // adhesive jump-in): the declared jump is then the law's intent, and static.continuity holds
  // every other point of the curves to continuity, so that it is the only one.
  void onset() {
    probe_->reset();
    const double F0 = probe_->force(0.0, k_.v);
    const std::optional<double> declared = probe_->onset_force();
    const double expected = declared.value_or(0.0);
    const double miss = std::abs(F0 - expected);
    const bool ok = miss <= kRounding * k_.F;  // false for a NaN on either side
    std::string detail = "F(z = 0, zdot = " + fmt(k_.v) + " m/s) = " + fmt(F0) +
                         " N on first loading (F_ref = " + fmt(k_.F) + " N)";
    if (declared)
      detail += ok ? ", the declared onset force " + fmt(*declared) +
                         " N: a jump at impact the law intends (static.continuity checks that "
                         "it is the only one)"
                   : ", but the law declares " + fmt(*declared) +
                         " N there: the force at impact is not the one declared";
    else if (!ok)
      detail +=
          ": the force jumps at impact; a law that is not zero at z = 0 is not continuous at "
          "onset (the paper's argument against Kelvin-Voigt); an adhesive law that means it "
          "declares the jump (--onset-force, or the member onset_force())";
    Check& c = push_force(make_check(
        "static.onset", miss / k_.F, 0.0, kRounding, ok,
        declared ? "F(0) is the declared onset force up to rounding (1e-12 F_ref)" : kRoundingWhy,
        detail));
    c.value = F0, c.reference_value = expected, c.value_unit = "N";
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
    Check& a = push_force(make_check(
        "static.attractive", min_force / k_.F, 0.0, -kRounding, !attractive || law_.allows_tension,
        "a contact force cannot pull unless the law says so (--allow-tension): the smallest "
        "force must be at least -1e-12 F_ref (rounding)",
        detail));
    a.bound = Bound::at_least;
    a.value = min_force, a.reference_value = 0.0, a.value_unit = "N";
    push_force(make_check("static.loading_monotone", worst_drop / k_.F, 0.0, kRounding,
                          worst_drop <= kRounding * k_.F, kRoundingWhy,
                          worst_drop > 0
                              ? "largest fall of F on first loading " + fmt(worst_drop) +
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
      report_.skipped.push_back({"static.breakpoints", "the law declares no kinks"});
      return;
    }
    push_force(make_check("static.breakpoints", worst / k_.F, 0.0, kRounding,
                          worst <= kRounding * k_.F, kRoundingWhy,
                          std::to_string(count) + " kink(s); largest jump at " + where));
  }

  // A located jump anywhere on loading (0 to z_scan) or unloading (from z_scan/4, z_scan/2
  // and z_scan down to z_f, or to 0 when the law allows tension), at each rate.
  void continuity() {
    constexpr int kIntervals = 1000;
    const double tau = kRounding * k_.F;
    std::optional<Jump> worst;
    std::string where, blind;
    int scans = 0, jumps = 0;
    double resolution = 0;
    auto scan = [&](const std::function<double(double)>& f, double lo, double hi,
                    const std::string& curve) {
      if (!(hi > lo)) return;
      const ScanResult s = scan_for_jumps(f, lo, hi, kIntervals, tau);
      ++scans, jumps += s.jumps;
      if (s.resolution >= resolution) resolution = s.resolution, blind = blind_spots(s);
      if (s.largest && (!worst || (worst->finite() && s.largest->size() > worst->size())))
        worst = s.largest, where = curve;
    };
    for (double v : rates()) {
      const std::string rate = law_.rate_dependent ? ", zdot = " + fmt(v) + " m/s" : "";
      scan(
          [&](double z) {
            load_to(*loading_, z);
            return loading_->force(z, v);
          },
          0.0, z_scan_, "first loading" + rate);
      for (double z_m : {0.25 * z_scan_, 0.5 * z_scan_, z_scan_}) {
        load_to(*probe_, z_m);
        try {
          probe_->begin_unloading(z_m);
        } catch (const LawDomainError&) {
          continue;
        }
        const double lo = law_.allows_tension ? 0.0 : probe_->permanent_set();
        scan([&](double z) { return probe_->force(z, -v); }, lo, z_m,
             "unloading from z_m = " + fmt(z_m) + " m" +
                 (law_.rate_dependent ? ", zdot = " + fmt(-v) + " m/s" : ""));
      }
    }
    const double size = worst ? worst->size() : 0.0;
    std::string detail;
    if (worst && !worst->finite())
      detail = "F is not finite at z = " + fmt(worst->z_left, 12) + " m on " + where +
               ": F = " + fmt(worst->F_left) + " N, then " + fmt(worst->F_right) + " N";
    else if (worst)
      detail = std::to_string(jumps) + " jump(s); the largest on " + where +
               " at z = " + fmt(worst->z_left, 12) + " m: F(z-) = " + fmt(worst->F_left, 10) +
               " N, F(z+) = " + fmt(worst->F_right, 10) + " N";
    else
      detail = "no jump in " + std::to_string(scans) + " curves (loading to z = " + fmt(z_scan_) +
               " m, and unloading), each sampled at " + std::to_string(kIntervals) + " intervals";
    Check& c = push_force(make_check(
        "static.continuity", size / k_.F, 0.0, kRounding, !worst,
        "a change of F that survives bisection down to adjacent doubles is a jump: a continuous "
        "law's change vanishes there (1e-12 F_ref allows rounding)",
        detail + "; " + blind));
    if (worst) c.value = worst->F_right, c.reference_value = worst->F_left, c.value_unit = "N";
  }

  void unloading() {
    double jump = 0, above = 0, energy_err = 0;
    std::pair<double, double> jump_values{NAN, NAN}, energy_values{NAN, NAN};  // law, reference
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
        jump = std::abs(F_un - F_load), jump_values = {F_un, F_load},
        jump_at = "z_m = " + fmt(z_m) + " m: loading " + fmt(F_load, 12) + " N, unloading " +
                  fmt(F_un, 12) + " N";
      const double z_f = probe_->permanent_set();
      // with tension the attractive part below z_f is part of the cycle too (to z = 0)
      const double lo = law_.allows_tension ? 0.0 : z_f;
      for (int i = 0; i <= 100; ++i) {
        const double z = lo + (z_m - lo) * i / 100.0;
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
          energy_err = diff, energy_values = {stored, integral},
          energy_at = "z_m = " + fmt(z_m) + " m: stored_energy " + fmt(stored, 12) +
                      " J, quadrature " + fmt(integral, 12) + " J";
      }
    }
    if (used == 0) {
      push_force(make_check("static.unloading_switch", NAN, 0.0, kRounding, false, kRoundingWhy,
                            "the law could not unload from any z_m:" + skipped));
      return;
    }
    const std::string note = skipped.empty() ? "" : "; not defined at" + skipped;
    Check& sw = push_force(make_check("static.unloading_switch", jump / k_.F, 0.0, kRounding,
                                      jump <= kRounding * k_.F, kRoundingWhy,
                                      "largest jump where unloading begins, at " + jump_at + note));
    sw.value = jump_values.first, sw.reference_value = jump_values.second, sw.value_unit = "N";
    push_force(make_check(
        "static.unloading_below", above / k_.F, 0.0, kRounding, above <= kRounding * k_.F,
        "an unloading curve above the loading curve returns more work than loading stored; "
        "1e-12 F_ref is rounding",
        above > 0 ? "unloading exceeds loading by " + fmt(above) + " N at " + above_at
                  : "unloading stays at or below loading (101 points per z_m)"));
    if (probe_->stored_energy_is_quadrature()) {
      report_.skipped.push_back(
          {"static.stored_energy",
           "the law computes its stored energy by quadrature of its own force: comparing it "
           "with another quadrature would prove nothing"});
    } else {
      Check& e =
          push(make_check("static.stored_energy", energy_err, 0.0, 1e-10, energy_err <= 1e-10,
                          "61-point Gauss-Kronrod of a smooth branch converges to rounding (its "
                          "own estimate is below 1e-13); 1e-10 of F_ref z_ref",
                          "largest difference (in F_ref z_ref) at " + energy_at),
               "F_ref z_ref", k_.F * k_.z, "J");
      e.value = energy_values.first, e.reference_value = energy_values.second, e.value_unit = "J";
    }
  }

  void stiffness() {
    if (!probe_->autodiff_slopes(k_.z, 0.0)) {
      report_.skipped.push_back(
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
    push(make_check("static.stiffness", worst, 0.0, kDerivative, worst <= kDerivative,
                    "hand-written and automatic derivatives are both exact; they differ by "
                    "rounding amplified by the formula's conditioning (1e-10 of k_ref = "
                    "F_ref/z_ref is 1e6 ulps)",
                    "largest difference (in k_ref, and F_ref/v for dF/dzdot) at " + where),
         "k_ref", k_.k, "N/m");
  }

  const LawUnderTest& law_;
  Scene scene_;
  Scales k_;
  double z_scan_;
  ConformanceResult& report_;
  std::unique_ptr<LawProbe> probe_, loading_;
};

}  // namespace

void static_checks(const LawUnderTest& law, const Scene& scene, double v_hi, double z_scan,
                   ConformanceResult& result) {
  StaticChecks(law, scene, v_hi, z_scan, result).run();
}

}  // namespace ivv::conformance::detail
