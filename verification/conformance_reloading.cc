// The reloading checks of a contact law: what it does when the spring, unloading from z_m, is
// compressed again before it separates (a finite plate's rebound does this within one contact,
// solver/plate/plate_impact.h). The drivers keep the unloading branch of z_m below z_m (the
// unloading curve is retraced, the rate now positive) and give the law back the loading history
// it had at z_m once z reaches z_m again. Checked statically, on the law alone:
//   static.reloading         the cycle z_m -> z1 -> z_m (unloading at zdot = -v, reloading at
//                            zdot = +v) creates no energy (within 1e-10 F_ref z_ref): the work put
//                            into the spring on reloading, int_{z1}^{z_m} F(z, +v) dz, is at least
//                            the work it returned on unloading, int_{z1}^{z_m} F(z, -v) dz
//   static.reloading_beyond  reloading meets the loading curve at z_m without a jump, and
//                            beyond z_m the law loads on its first-loading curve
// at z_m = 0.25, 0.5, 1, 2 z_ref, z1 at 5 % and 50 % of the way from the bottom of the cycle
// (z_f, or 0 for a law with tension) to z_m, and v = v0/2, v0 (the grid's largest v0).
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <string>

#include "solver/laws/law.h"
#include "verification/conformance_internal.h"

namespace ivv::conformance::detail {
namespace {

// Each work is an adaptive Gauss-Kronrod quadrature to 1e-12 of its value, and the values are at
// most a few F_ref z_ref (z_m <= 2 z_ref): the difference of two is exact to a few 1e-12 F_ref
// z_ref (for a rate-independent law the two are the same sum, and cancel exactly).
constexpr double kCycleWork = 1e-10;  // [F_ref z_ref]
constexpr const char* kCycleWorkWhy =
    "each work is a Gauss-Kronrod quadrature converged to 1e-12 of itself, at most a few F_ref "
    "z_ref: 1e-10 F_ref z_ref bounds the error of their difference with room";

double integral(const std::function<double(double)>& f, double a, double b) {
  double error = 0;
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, a, b, 10, 1e-12, &error);
}

struct Worst {
  double value = 0;  // the largest found (energy created, or jump)
  double law = NAN, reference = NAN;
  std::string where;
};

class ReloadingChecks {
 public:
  ReloadingChecks(const LawUnderTest& law, const Scene& scene, double v_hi,
                  ConformanceResult& report)
      : law_(law), k_(hertz_scales(scene, v_hi)), report_(report) {
    unloading_ = law.probe(scene);
    loading_ = law.probe(scene);
  }

  void run() {
    for (double z_m : {0.25 * k_.z, 0.5 * k_.z, k_.z, 2.0 * k_.z}) cycles_from(z_m);
    if (used_ == 0) {
      const std::string why = "the law could not unload from any z_m:" + skipped_;
      report_.skipped.push_back({"static.reloading", why});
      report_.skipped.push_back({"static.reloading_beyond", why});
      return;
    }
    push_cycle_check();
    push_beyond_check();
  }

 private:
  void cycles_from(double z_m) {
    load_to(*unloading_, z_m);
    try {
      unloading_->begin_unloading(z_m);
    } catch (const LawDomainError& e) {
      skipped_ += " z_m = " + fmt(z_m) + " m (" + e.what() + ")";
      return;
    }
    ++used_;
    const double bottom = law_.allows_tension ? 0.0 : unloading_->permanent_set();
    load_to(*loading_, z_m);
    for (double v : {0.5 * k_.v, k_.v}) {
      for (double fraction : {0.05, 0.5}) {
        const double z1 = bottom + fraction * (z_m - bottom);
        const double returned =
            integral([&](double z) { return unloading_->force(z, -v); }, z1, z_m);
        const double put_in = integral([&](double z) { return unloading_->force(z, v); }, z1, z_m);
        const double created = (returned - put_in) / (k_.F * k_.z);
        if (created > created_.value || created_.where.empty())
          created_ = {created, put_in, returned,
                      "z_m = " + fmt(z_m) + " m -> z1 = " + fmt(z1) + " m -> z_m at |zdot| = " +
                          fmt(v) + " m/s: returned " + fmt(returned, 12) + " J on unloading, " +
                          fmt(put_in, 12) + " J put in on reloading"};
      }
      // reaching z_m again: the unloading branch meets the loading history of z_m
      const double arriving = unloading_->force(z_m, v);
      const double leaving = loading_->force(z_m, v);
      const double jump = std::abs(arriving - leaving) / k_.F;
      if (jump > beyond_.value || beyond_.where.empty())
        beyond_ = {jump, arriving, leaving,
                   "z_m = " + fmt(z_m) + " m, zdot = " + fmt(v) + " m/s: reloading arrives at " +
                       fmt(arriving, 12) + " N, the loading curve is at " + fmt(leaving, 12) +
                       " N"};
    }
  }

  void push_cycle_check() {
    Check c = make_check(
        "static.reloading", created_.value, 0.0, kCycleWork, created_.value <= kCycleWork,
        kCycleWorkWhy,
        (created_.value > kCycleWork
             ? "reloading along the unloading branch creates energy: "
             : "no cycle below z_m creates energy (reloading retraces the unloading branch, "
               "work put in >= work returned); largest excess of returned over put in at ") +
            created_.where + note());
    c.unit = "F_ref z_ref", c.unit_si = k_.F * k_.z, c.si_unit = "J";
    c.value = created_.law, c.reference_value = created_.reference, c.value_unit = "J";
    report_.checks.push_back(std::move(c));
  }

  void push_beyond_check() {
    Check c = make_check(
        "static.reloading_beyond", beyond_.value, 0.0, kRounding, beyond_.value <= kRounding,
        kRoundingWhy,
        "beyond z_m the law loads on with the loading history it had at z_m (its first-loading "
        "curve); largest jump where reloading meets it at " +
            beyond_.where + note());
    c.unit = "F_ref", c.unit_si = k_.F, c.si_unit = "N";
    c.value = beyond_.law, c.reference_value = beyond_.reference, c.value_unit = "N";
    report_.checks.push_back(std::move(c));
  }

  std::string note() const { return skipped_.empty() ? "" : "; not defined at" + skipped_; }

  const LawUnderTest& law_;
  Scales k_;
  ConformanceResult& report_;
  std::unique_ptr<LawProbe> unloading_, loading_;
  Worst created_, beyond_;
  std::string skipped_;
  int used_ = 0;
};

}  // namespace

void reloading_checks(const LawUnderTest& law, const Scene& scene, double v_hi,
                      ConformanceResult& result) {
  ReloadingChecks(law, scene, v_hi, result).run();
}

}  // namespace ivv::conformance::detail
