// Validation cases: the calibration recovers what generated its data, its 95 %
// intervals cover at the stated rate, it names what the data cannot determine, and it rejects
// and out-ranks a wrong model. All data here are SYNTHETIC (validation/synthetic.h), generated
// from stated parameters with stated, seeded noise.
#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>

#include "validation/calibration.h"
#include "validation/comparison.h"
#include "validation/example.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"
#include "validation/prediction.h"
#include "validation/synthetic.h"
#include "verification/cases.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

using namespace ivv::validation;

// The paper scene (Table 1) with the dashpot of zeta = 0.1 held as a coefficient (c = 11440
// N s/m), so c and S_y are separate physical parameters; --model auto, --integrator auto.
SimulationRequest damped_paper() {
  SimulationRequest r;
  r.scene = paper_scene();
  r.scene.damping = Damping::ratio(0.1);
  r.scene.damping = Damping::coefficient(validation::parameter_value(r, "c"));
  r.auto_integrator = true;
  return r;
}

// Profile-likelihood intervals cost one calibration per parameter and bound: the cases that do
// not judge them skip them.
enum class Profiles { computed, skipped };

CalibrationOptions fitting(std::vector<std::string> names, Profiles profiles = Profiles::computed) {
  CalibrationOptions o;
  o.fit = std::move(names);
  o.profile = profiles == Profiles::computed;
  return o;
}

// Velocities spanning the paper's plastic range: 0.3 to 5 m/s (v_y ~ 0.2 m/s; docs/design.md §3).
std::vector<double> plastic_velocities(int n) {
  return log_velocities(0.3, 5.0, n);
}

Outcome recovery() {
  const SimulationRequest truth = damped_paper();
  const int n = 20;
  const double u = 0.01;
  const MeasuredData data = synthetic_data(truth, {.velocities = plastic_velocities(n),
                                                   .u_e = u,
                                                   .noise = false,
                                                   .seed = 1,
                                                   .description = "recovery case"});
  CalibrationProblem problem{truth, data};
  set_parameter(problem.request, "c", 1.3 * validation::parameter_value(truth, "c"));
  set_parameter(problem.request, "yield_strength", 0.7 * *truth.scene.yield_strength);
  const CalibrationResult r =
      calibrate(problem, fitting({"c", "yield_strength"}, Profiles::skipped));
  if (!r.ok) return at_most(NAN, 0, r.failure);
  double worst = 0;
  std::string where;
  for (const auto& p : r.parameters) {
    const double err =
        std::abs(p.value - validation::parameter_value(truth, p.name)) / p.standard_error;
    if (!(err <= worst)) worst = err, where = p.name;
  }
  // The data carry the generator's stated error (<= 300 x 1e-12 in e) and the fit's runs
  // theirs (<= kIntegrationShare u); a residual perturbation dr moves theta_j by at most
  // SE_j |dr| (Cauchy-Schwarz on the rows of the pseudo-inverse), |dr| <= sqrt(n) (that)/u.
  const double bound = std::sqrt(n) * (kIntegrationShare + 300 * kSyntheticRtol / u);
  return at_most(worst, bound,
                 "largest |estimate - generating value| = " + fmt(worst, 3) + " standard errors (" +
                     where + ") from noise-free data, start 30 % off; " + r.brief());
}

// The smallest count k of n Bernoulli(p) successes with P(X < k) <= alpha.
int binomial_floor(int n, double p, double alpha) {
  const boost::math::binomial_distribution<double> b(n, p);
  int k = 0;
  while (k + 1 <= n && boost::math::cdf(b, k) <= alpha) ++k;
  return k;
}

// The share of `sets` seeded noisy data sets whose linearised 95 % intervals contain the
// generating c and S_y; the case asks for each parameter's count to reach the binomial floor.
Outcome coverage(int sets) {
  const SimulationRequest truth = damped_paper();
  const double alpha = 0.005;  // per parameter: a correct method fails the case with P <= 1 %
  const int floor = binomial_floor(sets, 0.95, alpha);
  int covered[2] = {0, 0};
  for (int seed = 1; seed <= sets; ++seed) {
    const MeasuredData data = synthetic_data(truth, {.velocities = plastic_velocities(20),
                                                     .u_e = 0.01,
                                                     .seed = static_cast<std::uint64_t>(seed),
                                                     .description = "coverage case"});
    const CalibrationResult r =
        calibrate({truth, data}, fitting({"c", "yield_strength"}, Profiles::skipped));
    if (!r.ok) return at_least(NAN, floor, "seed " + std::to_string(seed) + ": " + r.failure);
    for (int j = 0; j < 2; ++j) {
      const ParameterEstimate& p = r.parameters[static_cast<std::size_t>(j)];
      const double v = validation::parameter_value(truth, p.name);
      covered[j] += p.identifiable && p.lower95 <= v && v <= p.upper95;
    }
  }
  const int worst = std::min(covered[0], covered[1]);
  return at_least(worst, floor,
                  "95 % intervals containing the generating value in " + std::to_string(sets) +
                      " seeded data sets (20 impacts 0.3-5 m/s, u_e = 0.01): c " +
                      std::to_string(covered[0]) + ", yield_strength " +
                      std::to_string(covered[1]) + "; binomial floor " + std::to_string(floor) +
                      " (P(X < floor) <= " + fmt(alpha, 3) + " for X ~ Bin(" +
                      std::to_string(sets) + ", 0.95))");
}

}  // namespace

namespace {

// Data all below yield (0.01-0.1 m/s; the paper's 0.1 m/s is elastic, docs/design.md §3) determine
// the dashpot but not S_y: the case passes when S_y is named unidentifiable and c is not.
Outcome elastic_data() {
  const SimulationRequest truth = damped_paper();
  const MeasuredData data = synthetic_data(truth, {.velocities = log_velocities(0.01, 0.1, 12),
                                                   .u_e = 0.005,
                                                   .seed = 3,
                                                   .description = "identifiability case"});
  const CalibrationResult r = calibrate({truth, data}, fitting({"c", "yield_strength"}));
  if (!r.ok) return at_least(NAN, 1, r.failure);
  const bool right = !r.find("yield_strength")->identifiable && r.find("c")->identifiable &&
                     std::isnan(r.find("yield_strength")->value);
  return at_least(right ? 1 : 0, 1,
                  std::string(right ? "yield_strength named unidentifiable, c determined: "
                                    : "expected yield_strength unidentifiable and c determined: ") +
                      r.brief());
}

// Every impact at one speed (10 repeats at 1 m/s): e(v0) is one number, so c and S_y are
// determined only in combination: both named unidentifiable, correlation +-1.
Outcome correlated() {
  const SimulationRequest truth = damped_paper();
  const MeasuredData data = synthetic_data(truth, {.velocities = std::vector<double>(10, 1.0),
                                                   .u_e = 0.01,
                                                   .seed = 5,
                                                   .description = "identifiability case"});
  const CalibrationResult r = calibrate({truth, data}, fitting({"c", "yield_strength"}));
  if (!r.ok) return at_least(NAN, 1, r.failure);
  const double rho = std::abs(r.correlation[0][1]);
  const bool both = !r.parameters[0].identifiable && !r.parameters[1].identifiable;
  // Identical rows make J of rank 1 in exact arithmetic; the pseudo-inverse keeps one
  // direction, so |rho| = 1 to round-off (1e-12 allows for the SVD's).
  return at_least(both ? rho : 0.0, 1 - 1e-12,
                  "|corr(c, yield_strength)| = " + fmt(rho, 15) +
                      (both ? ""
                            : " but not both "
                              "named unidentifiable") +
                      "; " + r.brief());
}

// Kuwabara-Kono viscoelastic Hertz (examples/laws/kuwabara_kono.h) as an expression law:
// F = K_h (z^{3/2} + (3/2) A sqrt(z) dz/dt), no dashpot, on the paper's sphere and target.
SimulationRequest kuwabara_kono(double A) {
  SimulationRequest r;
  r.scene = paper_scene();
  r.law = LawKind::expression;
  r.expression.force = "K_h*(z^1.5 + 1.5*A*sqrt(z)*zdot)";
  r.parameters["A"] = A;
  r.auto_integrator = true;
  return r;
}

// A strongly dissipative material: beta = (3/2) A (K_h/m)^{2/5} ~ 0.8, e from ~0.6 at 0.01 m/s
// to ~0.3 at 10 m/s. At weak dissipation (A = 2e-6 and 2e-5 s tried) the elastoplastic law
// with a large series dashpot and no yield - Zener's Hertz-plus-dashpot, whose 1 - e also
// grows as v0^{1/5} - fits KK data to within u_e = 0.005 (chi^2/dof 0.96-0.98): the two
// differ only beyond the first order in the dissipation, which is what this case probes.
constexpr double kKuwabaraKonoA = 1e-4;  // [s]
constexpr double kWrongModelSignificance = 1e-3;

struct WrongModel {
  CalibrationResult elastoplastic, hunt_crossley, kk;
  ModelRanking ranking;
};

// KK data (25 impacts 0.01-10 m/s, u_e = 0.005, seed 11) fitted by the elastoplastic law
// (c, S_y from a coarse scan), Hunt-Crossley (mu) and KK itself (A). Computed once.
const WrongModel& wrong_model() {
  static const WrongModel w = [] {
    const MeasuredData data =
        synthetic_data(kuwabara_kono(kKuwabaraKonoA), {.velocities = log_velocities(0.01, 10, 25),
                                                       .u_e = 0.005,
                                                       .seed = 11,
                                                       .description = "wrong-model case"});
    WrongModel m;
    CalibrationOptions ep = fitting({"c", "yield_strength"}, Profiles::skipped);
    ep.scan = true;
    m.elastoplastic = calibrate({damped_paper(), data}, ep);
    SimulationRequest hc = damped_paper();
    hc.scene.damping = Damping::none();
    hc.law = LawKind::hunt_crossley;
    hc.parameters["mu"] = 0.1;
    CalibrationOptions hco = fitting({"mu"}, Profiles::skipped);
    hco.scan = true;
    m.hunt_crossley = calibrate({hc, data}, hco);
    m.kk = calibrate({kuwabara_kono(3 * kKuwabaraKonoA), data}, fitting({"A"}, Profiles::skipped));
    m.ranking = compare({"elastoplastic", "hunt-crossley", "kuwabara-kono (expression)"},
                        {m.elastoplastic, m.hunt_crossley, m.kk});
    return m;
  }();
  return w;
}

Outcome wrong_model_rejected() {
  const CalibrationResult& r = wrong_model().elastoplastic;
  if (!r.ok || !r.p_value) return at_most(NAN, kWrongModelSignificance, r.failure);
  return at_most(*r.p_value, kWrongModelSignificance,
                 "chi^2 p-value of the elastoplastic fit to Kuwabara-Kono data: " + r.brief());
}

Outcome wrong_model_ranked() {
  const ModelRanking& c = wrong_model().ranking;
  const RankedModel* best = c.best();
  const bool kk = best && best->name.rfind("kuwabara-kono", 0) == 0;
  // the runner-up's Delta AIC: > 0 with KK first; the case asks KK to be first
  const double delta = c.models.size() > 1 ? c.models[1].delta_aic : 0.0;
  return at_least(kk ? delta : -delta, 0.0, "ranking by AIC:\n" + c.table());
}

// The shipped example: each generating value inside the printed 95 % interval.
Outcome shipped_recovery() {
  const ShippedExample& x = shipped_example();
  if (!x.fit.ok) return at_most(NAN, 1.96, x.fit.failure);
  double worst = 0;
  for (const auto& p : x.fit.parameters) {
    const double truth = p.name == "c" ? kExampleTruthC : kExampleTruthYield;
    worst = std::max(worst, std::abs(p.value - truth) / p.standard_error);
  }
  return at_most(worst, 1.959963984540054,
                 "largest |estimate - generating value| in standard errors (the linearised "
                 "interval is 1.96 SE wide either way in ln theta): " +
                     x.fit.brief());
}

Outcome shipped_validation() {
  const ShippedExample& x = shipped_example();
  if (!x.validation.prediction.ok()) return at_most(NAN, 1, "the prediction failed");
  // 8 held-back points of the generating model: each exceeds 2 u_val with P ~ 5 %, so two or
  // more do with P = 5.7 %, three or more with P = 0.6 %: at most 2.
  return at_most(x.validation.exceeding, 2, x.validation.summary());
}

// The calibrate -> predict chain held to the truth: data of the damped paper scene generated by
// an independent implementation (GSL's rk8pd, not the auto choice of dop853/rodas4 the fit and
// the prediction run), c and S_y fitted, the 95 % band predicted at three speeds; the share of
// `sets` seeded data sets whose band contains the generating model's e at each speed must reach
// the binomial floor. The band is that of the model from the parameter uncertainty (V&V 20's
// u_input), so this checks the covariance, its sampling and the quantiles together.
// Measured when the case was written: 89, 99 and 89 of 100 at 0.5, 1.5 and 4 m/s, the floor
// being 89 (with draws in theta rather than ln theta: 89, 98, 81, failing). At the ends of the
// data's range the band is narrower than a 95 % band should be: the Gaussian approximation
// still straightens the curved valley along which c and S_y trade off (correlation -0.99).
Outcome band_coverage(int sets) {
  SimulationRequest truth = damped_paper();
  truth.auto_integrator = false;
  truth.integrator = IntegratorKind::gsl_rk8pd;
  const std::vector<double> speeds{0.5, 1.5, 4.0};
  std::vector<double> e_true;
  for (const auto& p : run_model_points(damped_paper(), {}, {}, speeds, 1)) {
    if (!p.result.ok()) return at_least(NAN, 1, p.result.reason);
    e_true.push_back(p.result.e);
  }
  const double alpha = 0.005;  // per speed: a correct band fails the case with P <= 1.5 %
  const int floor = binomial_floor(sets, 0.95, alpha);
  std::vector<int> covered(speeds.size());
  for (int seed = 1; seed <= sets; ++seed) {
    const CalibrationProblem problem{
        damped_paper(), synthetic_data(truth, {.velocities = plastic_velocities(20),
                                               .u_e = 0.01,
                                               .seed = static_cast<std::uint64_t>(1000 + seed),
                                               .description = "band coverage case (GSL rk8pd)"})};
    const CalibrationResult r =
        calibrate(problem, fitting({"c", "yield_strength"}, Profiles::skipped));
    if (!r.ok) return at_least(NAN, floor, "seed " + std::to_string(seed) + ": " + r.failure);
    PredictionOptions o;
    o.samples = 400;
    o.seed = static_cast<std::uint64_t>(seed);
    const Prediction band = predict(calibrated_model(problem, r), speeds, o);
    if (!band.ok()) return at_least(NAN, floor, band.failures.front());
    for (std::size_t k = 0; k < speeds.size(); ++k)
      covered[k] += band.points[k].e_lo <= e_true[k] && e_true[k] <= band.points[k].e_hi;
  }
  std::string detail = "95 % bands containing the generating e in " + std::to_string(sets) +
                       " seeded data sets (20 impacts 0.3-5 m/s, u_e = 0.01, generated by GSL "
                       "rk8pd; 400 draws):";
  for (std::size_t k = 0; k < speeds.size(); ++k)
    detail += " v0 = " + fmt(speeds[k], 2) + " m/s: " + std::to_string(covered[k]) + ";";
  detail += " binomial floor " + std::to_string(floor);
  return at_least(*std::min_element(covered.begin(), covered.end()), floor, detail);
}

}  // namespace

void register_validation_cases(Registry& reg) {
  const Tier T = Tier::validation;
  reg.add({"validation.calibrate.recovery",
           "Calibration recovers the generating c and S_y from noise-free synthetic data", T,
           "the data and the fit's runs carry at most the stated integration errors; they move "
           "an estimate by at most sqrt(n) x (their size / u_e) standard errors",
           Cost::quick, recovery});
  reg.add({"validation.calibrate.coverage-100",
           "95 % intervals cover the generating values (100 seeded noisy data sets)", T,
           "binomial: a correct method reaches the floor except with probability <= 0.5 % per "
           "parameter (the seeded sets make the case reproducible; ~10 s, so in the default run)",
           Cost::quick, [] { return coverage(100); }});
  reg.add({"validation.predict.band-coverage-100",
           "calibrate -> predict: 95 % bands cover the generating e (100 data sets from GSL rk8pd)",
           T,
           "binomial: a correct band reaches the floor except with probability <= 0.5 % per "
           "speed; the quantiles of 400 draws add a Monte Carlo error of about 1 % to the "
           "band's coverage, inside the floor's margin",
           Cost::quick, [] { return band_coverage(100); }});
  reg.add({"validation.identifiability.elastic",
           "Data all below yield: yield_strength named unidentifiable, c determined", T,
           "unidentifiable means a linearised standard error of ln S_y above 1 (kUnidentifiable); "
           "below yield e does not depend on S_y at all",
           Cost::quick, elastic_data});
  reg.add({"validation.identifiability.correlated",
           "Data at one speed: c and yield_strength named unidentifiable, correlation +-1", T,
           "identical Jacobian rows: rank 1 exactly, |rho| = 1 to round-off", Cost::quick,
           correlated});
  reg.add({"validation.wrong-model.chi2",
           "Kuwabara-Kono data fitted by the elastoplastic law fail the chi^2 test", T,
           "significance 1e-3: a right model fails so with probability 1e-3", Cost::quick,
           wrong_model_rejected});
  reg.add({"validation.wrong-model.ranking",
           "Model comparison ranks Kuwabara-Kono first on its own data (AIC)", T,
           "AIC differences: the measured value is the runner-up's Delta AIC (negative when KK is "
           "not first)",
           Cost::quick, wrong_model_ranked});
  reg.add(
      {"validation.example.recovery",
       "Shipped example (synthetic): the generating c and S_y lie in the printed 95 % intervals", T,
       "the interval itself: |estimate - truth| <= 1.96 SE (fails with P = 5 % per parameter "
       "for a correct method; the shipped data are fixed, so the outcome is too)",
       Cost::quick, shipped_recovery});
  reg.add({"validation.example.vv20",
           "Shipped example: the V&V 20 comparison with the held-back points flags at most 2 of 8",
           T, "binomial: 3 or more of 8 points beyond 2 u_val has P = 0.6 % for a right model",
           Cost::quick, shipped_validation});
}

}  // namespace ivv::verification
