// Cross-implementation tier: every double-precision integrator against the 50-digit reference
// (mp50), which shares only the laws and event definitions with them.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "closed_forms/linear_model.h"
#include "solver/consistency.h"
#include "solver/simulate_batch.h"
#include "solver/steppers/machine_code.h"
#include "verification/cases.h"
#include "verification/support.h"
#include "verification/tolerances.h"

namespace ivv::verification {
namespace {

struct LawGrid {
  LawKind law;
  std::vector<SimulationRequest> requests;  // integrator filled in per case
  std::vector<std::string> labels;
};

LawGrid grid_for(LawKind law) {
  LawGrid g{law, {}, {}};
  if (law == LawKind::hunt_crossley) {
    for (double v0 : {0.1, 1.0, 5.0})
      for (double u0 : {0.2, 1.0, 5.0}) {
        g.requests.push_back(
            request(with(paper_scene(), v0, 0.0), law, IntegratorKind::odeint_dopri5, u0 / v0));
        g.labels.push_back("paper v0=" + fmt(v0) + " mu v0=" + fmt(u0));
      }
    return g;
  }
  for (const GridScene& gs : paper_grid()) {
    // the linearized law is undefined at 0.1 m/s (z_m < 2.25 z_y): a stability case says so
    if (law == LawKind::linearized && gs.scene.velocity < 0.5) continue;
    g.requests.push_back(request(gs.scene, law, IntegratorKind::odeint_dopri5));
    g.labels.push_back(gs.label);
  }
  return g;
}

Outcome against_reference(const std::vector<SimulationRequest>& requests,
                          const std::vector<std::string>& labels, IntegratorKind k,
                          double tolerance) {
  WorstError w;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    SimulationRequest req = requests[i];
    req.integrator = k;
    const ImpactResult& ref = reference(req);
    const ImpactResult r = simulate(req);
    if (r.status != ref.status) {
      w.fail(labels[i] + ": status " + std::string(to_string(r.status)) + " vs reference " +
             std::string(to_string(ref.status)) + " " + r.reason);
      continue;
    }
    w.add_cor(r.e, ref.e, labels[i] + " e");
    w.add(r.F_max, ref.F_max, labels[i] + " F_max");
    w.add(r.t_contact, ref.t_contact, labels[i] + " t_contact");
    w.add(r.z_max, ref.z_max, labels[i] + " z_max");
  }
  return worst_case(w, tolerance, "e, F_max, t_contact, z_max against mp50");
}

std::vector<IntegratorKind> double_integrators() {
  std::vector<IntegratorKind> out;
  for (IntegratorKind k : all_integrators())
    if (k != IntegratorKind::mp50) out.push_back(k);
  return out;
}

// Two runs of each point that differ only in rounding, compared: |e_a - e_b| over the sum of the
// two runs' stated errors (accumulated_error_bound of each run's steps), its largest value and
// where; a run that failed or a status that differs ends the comparison (`failure` says so).
struct PairedRuns {
  double worst = 0, largest_de = 0;
  int differing = 0, points = 0;
  std::string where = "none", failure;

  // false when the comparison ends at this point
  bool add(const std::string& label, const ImpactResult& a, std::string_view a_name,
           const ImpactResult& b, std::string_view b_name, const IntegratorOptions& options) {
    if (!a.ok() || !b.ok() || a.status != b.status) {
      failure = label + ": " + std::string(to_string(a.status)) + " (" + std::string(a_name) +
                ") vs " + std::string(to_string(b.status)) + " (" + std::string(b_name) + ") " +
                a.reason + b.reason;
      return false;
    }
    ++points;
    const double de = std::abs(a.e - b.e);
    const double stated =
        accumulated_error_bound(a.steps, options) + accumulated_error_bound(b.steps, options);
    differing += de > 0 ? 1 : 0;
    largest_de = std::max(largest_de, de);
    if (de / stated > worst) {
      worst = de / stated;
      where = label;
    }
    return true;
  }
};

// The map of `law` (dop853, rtol = atol = 1e-8, v0 0.1-10 m/s log x zeta 0-1, n_v0 x n_zeta
// points, zeta 0 without the dashpot) run in the baseline machine code and in the fastest this
// CPU has (solver/steppers/machine_code.h). Measured: the largest |e_fast - e_baseline| over the
// sum of the two runs' stated errors (accumulated_error_bound of each run's steps); a point whose
// status differs fails the case.
Outcome machine_codes_agree(LawKind law, int n_v0, int n_zeta) {
  const MachineCode fast = machine_code_in_use(MachineCode::fastest);
  PairedRuns c;
  for (int i = 0; i < n_v0 && c.failure.empty(); ++i) {
    for (int j = 0; j < n_zeta; ++j) {
      const double v0 = 0.1 * std::pow(100.0, i / static_cast<double>(n_v0 - 1));
      const double zeta = j / static_cast<double>(n_zeta - 1);
      SimulationRequest req = request(with(paper_scene(), v0, zeta), law, IntegratorKind::dop853);
      req.model = ModelKind::full;
      req.options.rtol = req.options.atol = 1e-8;
      req.options.machine_code = MachineCode::baseline;
      const ImpactResult base = simulate(req);
      req.options.machine_code = MachineCode::fastest;
      const ImpactResult r = simulate(req);
      const std::string label = "v0=" + fmt(v0) + " zeta=" + fmt(zeta);
      if (!c.add(label, base, "baseline", r, "fastest", req.options)) break;
    }
  }
  if (!c.failure.empty()) return at_most(std::nan(""), 1.0, c.failure);
  if (fast == MachineCode::baseline)  // no copy here: one code ran twice, bit for bit the same
    return at_most(c.largest_de, 0.0,
                   std::string(to_string(law)) + ", " + std::to_string(c.points) +
                       " points: this CPU (or IVV_MACHINE_CODE) has only the baseline code, so "
                       "both requests ran it and must agree exactly; largest |de| " +
                       fmt(c.largest_de, 3));
  return at_most(c.worst, 1.0,
                 std::string(to_string(law)) + ", " + std::to_string(c.points) +
                     " points: " + std::string(machine_code_description(fast)) + " against " +
                     std::string(machine_code_description(MachineCode::baseline)) +
                     "; e differs at " + std::to_string(c.differing) + " points, by at most " +
                     fmt(c.largest_de, 3) +
                     " (units of v0); the largest |de| over the sum of the two stated errors is " +
                     fmt(c.worst, 3) + " at " + c.where);
}

// The requests of one velocity's row of the map of `law` (dop853, the full model, rtol 1e-8 with
// the default atol, zeta 0-1 in n_zeta points, zeta 0 without the dashpot).
std::vector<SimulationRequest> map_row(LawKind law, double v0, int n_zeta) {
  std::vector<SimulationRequest> row;
  for (int j = 0; j < n_zeta; ++j) {
    const double zeta = j / static_cast<double>(n_zeta - 1);
    SimulationRequest req = request(with(paper_scene(), v0, zeta), law, IntegratorKind::dop853);
    req.model = ModelKind::full;
    req.options.rtol = 1e-8;
    row.push_back(req);
  }
  return row;
}

// The results of a row computed together, as `ivv sweep` computes a batch of its points
// (simulate_batch: the elastoplastic law in SIMD lanes).
std::vector<ImpactResult> batch_results(const std::vector<SimulationRequest>& row) {
  std::vector<ValidatedRequest> validated;
  for (const SimulationRequest& req : row) validated.emplace_back(req);
  std::vector<ImpactResult> results(row.size());
  simulate_batch(validated, results);
  return results;
}

double map_velocity(int i, int n_v0) {
  return 0.1 * std::pow(100.0, i / static_cast<double>(n_v0 - 1));
}

// The map of `law` as `ivv sweep --rtol 1e-8` runs it (map_row, computed a row at a time by
// batch_results; v0 0.1-10 m/s log x zeta 0-1, n_v0 x n_zeta points) against the same map at
// rtol = atol = 1e-12, each of those points run on its own by the scalar dop853. Measured: the
// largest |e - e_tight| over the sum of the two runs' stated errors (accumulated_error_bound of
// each run's steps). A point captured in one run and separated in the other is held to the
// captured run's bound on e (e_bound) plus the two stated errors.
Outcome map_within_stated_error(LawKind law, int n_v0, int n_zeta) {
  double worst = 0, largest_de = 0;
  int points = 0, capture_boundary = 0;
  std::string where = "none", failure;
  for (int i = 0; i < n_v0 && failure.empty(); ++i) {
    const double v0 = map_velocity(i, n_v0);
    const std::vector<SimulationRequest> row = map_row(law, v0, n_zeta);
    const std::vector<ImpactResult> results = batch_results(row);
    for (int j = 0; j < n_zeta; ++j) {
      const SimulationRequest& req = row[j];
      const ImpactResult& r = results[j];
      SimulationRequest tight = req;
      tight.options.rtol = tight.options.atol = 1e-12;
      const ImpactResult ref = simulate(tight);
      const std::string label = "v0=" + fmt(v0) + " zeta=" + fmt(j / (n_zeta - 1.0));
      if (!r.ok() || !ref.ok()) {
        failure = label + ": " + r.reason + ref.reason;
        break;
      }
      ++points;
      double allowed = accumulated_error_bound(r.steps, req.options) +
                       accumulated_error_bound(ref.steps, tight.options);
      if (r.status != ref.status) {
        ++capture_boundary;
        allowed += r.status == ImpactStatus::captured ? r.e_bound : ref.e_bound;
      }
      const double de = std::abs(r.e - ref.e);
      largest_de = std::max(largest_de, de);
      if (de / allowed > worst) {
        worst = de / allowed;
        where = label;
      }
    }
  }
  if (!failure.empty()) return at_most(std::nan(""), 1.0, failure);
  return at_most(worst, 1.0,
                 std::string(to_string(law)) + ", " + std::to_string(points) +
                     " points: largest |e(rtol 1e-8) - e(rtol 1e-12)| " + fmt(largest_de, 3) +
                     " (units of v0), " + std::to_string(capture_boundary) +
                     " points captured in one run only; the largest |de| over the sum of the two "
                     "stated errors is " +
                     fmt(worst, 3) + " at " + where);
}

// The paper map (map_row of the elastoplastic law, n_v0 x n_zeta points) computed a row at a time
// together (batch_results: the points with a dashpot in SIMD lanes) and point by point by the
// scalar dop853 (simulate), both in the fastest machine code. Measured: the largest |e_batch -
// e_one| over the sum of the two runs' stated errors; a point whose status differs fails the
// case. Where the lanes do not run (no AVX2 + FMA here, or IVV_MACHINE_CODE=baseline) both are
// the scalar run and must agree exactly.
Outcome lanes_agree(int n_v0, int n_zeta) {
  PairedRuns c;
  int in_lanes = 0;
  for (int i = 0; i < n_v0 && c.failure.empty(); ++i) {
    const double v0 = map_velocity(i, n_v0);
    const std::vector<SimulationRequest> row = map_row(LawKind::elastoplastic, v0, n_zeta);
    const std::vector<ImpactResult> results = batch_results(row);
    for (int j = 0; j < n_zeta; ++j) {
      const ImpactResult one = simulate(row[j]);
      in_lanes += runs_in_lanes(ValidatedRequest(row[j])) ? 1 : 0;
      const std::string label = "v0=" + fmt(v0) + " zeta=" + fmt(j / (n_zeta - 1.0));
      if (!c.add(label, results[j], "lanes", one, "one by one", row[j].options)) break;
    }
  }
  if (!c.failure.empty()) return at_most(std::nan(""), 1.0, c.failure);
  const std::string counts = std::to_string(c.points) + " points, " + std::to_string(in_lanes) +
                             " of them in lanes; e differs at " + std::to_string(c.differing) +
                             " points, by at most " + fmt(c.largest_de, 3) + " (units of v0)";
  if (in_lanes == 0)
    return at_most(c.largest_de, 0.0,
                   counts +
                       ": the lanes do not run here, so both ran the scalar code and must "
                       "agree exactly");
  return at_most(c.worst, 1.0,
                 counts + "; the largest |de| over the sum of the two stated errors is " +
                     fmt(c.worst, 3) + " at " + c.where);
}

}  // namespace

// Why two runs of one map may differ by the sum of their stated errors (the reason of every case
// comparing two such maps).
constexpr const char* kStatedErrorSum =
    "each run's e is within its stated error of the exact e, accumulated_error_bound "
    "(solver/consistency.h: 10 x steps x 2 (atol + 2 rtol), the bound every run's ledger is held "
    "to), so the two differ by at most the sum of their stated errors: measured over that sum, "
    "at most 1";

// The maps that two runs compute by the same method and differ only in rounding: the machine
// codes, and the lanes against one impact at a time.
void register_rounding_cases(Registry& reg) {
  const std::string machine_code_reason =
      std::string(
          "both runs integrate the same equations by the same method (dop853) and differ "
          "only in rounding (a fused multiply-add rounds once where the baseline rounds "
          "twice); ") +
      kStatedErrorSum;
  reg.add({"cross.machine-code.elastoplastic-map",
           "The paper map (elastoplastic, dop853, rtol 1e-8, 30 x 30 points v0 0.1-10 m/s x zeta "
           "0-1) in the AVX2 + FMA machine code vs the baseline x86-64 code",
           Tier::cross_implementation, machine_code_reason, Cost::quick,
           [] { return machine_codes_agree(LawKind::elastoplastic, 30, 30); }});
  reg.add({"cross.machine-code.hertz-map",
           "Zener's problem (Hertz with the dashpot, dop853, rtol 1e-8, 10 x 10 points v0 0.1-10 "
           "m/s x zeta 0-1) in the AVX2 + FMA machine code vs the baseline x86-64 code",
           Tier::cross_implementation, machine_code_reason, Cost::quick,
           [] { return machine_codes_agree(LawKind::hertz, 10, 10); }});
  reg.add({"cross.lanes.elastoplastic-map",
           "The paper map (elastoplastic, dop853, rtol 1e-8, 30 x 30 points v0 0.1-10 m/s x zeta "
           "0-1) in SIMD lanes, as ivv sweep runs it, vs each point on its own",
           Tier::cross_implementation,
           std::string("both runs integrate the same equations by the same method (dop853), the "
                       "lanes four impacts at once on vectors, whose fused multiply-adds fall "
                       "where the scalar run's need not; ") +
               kStatedErrorSum,
           Cost::quick, [] { return lanes_agree(30, 30); }});
}

void register_cross_implementation_cases(Registry& reg) {
  register_rounding_cases(reg);
  const std::string map_reason =
      std::string(kStatedErrorSum) +
      ". It holds what the driver does to an impact (event location, step sizes after events, "
      "capture) to the accuracy the map states, point by point";
  reg.add({"convergence.map.elastoplastic",
           "The paper map (elastoplastic, dop853, 30 x 30 points v0 0.1-10 m/s x zeta 0-1) at "
           "rtol 1e-8 vs the same map at rtol 1e-12",
           Tier::convergence, map_reason, Cost::quick,
           [] { return map_within_stated_error(LawKind::elastoplastic, 30, 30); }});
  reg.add({"convergence.map.hertz",
           "Zener's problem (Hertz with the dashpot, dop853, 10 x 10 points v0 0.1-10 m/s x zeta "
           "0-1) at rtol 1e-8 vs the same map at rtol 1e-12",
           Tier::convergence, map_reason, Cost::quick,
           [] { return map_within_stated_error(LawKind::hertz, 10, 10); }});
  for (LawKind law : all_laws()) {
    for (IntegratorKind k : double_integrators()) {
      const Tolerance tol = default_settings_tolerance(k);
      const std::string id =
          "cross." + std::string(to_string(law)) + "." + std::string(to_string(k));
      reg.add({id,
               std::string(to_string(law)) + " law on the paper grid (v0 0.1-5 m/s, zeta 0-0.3): " +
                   std::string(to_string(k)) + " vs the 50-digit reference",
               Tier::cross_implementation, tol.reason, Cost::quick, [law, k, tol] {
                 const LawGrid g = grid_for(law);
                 return against_reference(g.requests, g.labels, k, tol.value);
               }});
    }
  }
  for (IntegratorKind k : double_integrators()) {
    const Tolerance tol = default_settings_tolerance(k);
    reg.add(
        {"cross.extended-scenes." + std::string(to_string(k)),
         "Every law on other material pairs and masses 1e-3-10 kg: " + std::string(to_string(k)) +
             " vs the 50-digit reference",
         Tier::cross_implementation, tol.reason, Cost::slow, [k, tol] {
           std::vector<SimulationRequest> reqs;
           std::vector<std::string> labels;
           for (const GridScene& gs : extended_grid()) {
             for (LawKind law : {LawKind::hertz, LawKind::elastoplastic}) {
               reqs.push_back(request(gs.scene, law, k));
               labels.push_back(std::string(to_string(law)) + " " + gs.label);
             }
             // the linearized law only where its closed form says it is defined
             try {
               closed_forms::solve_linear_model(
                   closed_forms::linear_model_input(gs.scene, derive(gs.scene)));
               reqs.push_back(request(gs.scene, LawKind::linearized, k));
               labels.push_back("linearized " + gs.label);
             } catch (const closed_forms::LinearizedLawUndefined&) {
             }
             // Hunt-Crossley (no dashpot) with mu v0 = 1
             reqs.push_back(request(gs.scene, LawKind::hunt_crossley, k, 1.0 / gs.scene.velocity));
             labels.push_back("hunt-crossley mu v0=1 " + gs.label);
           }
           return against_reference(reqs, labels, k, tol.value);
         }});
  }
}

}  // namespace ivv::verification
