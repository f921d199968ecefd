#include "solver/simulate_batch.h"

#include <optional>
#include <stdexcept>
#include <vector>

#include "solver/choice/model_choice.h"
#include "solver/simulate_lanes.h"
#include "solver/steppers/machine_code.h"

namespace ivv {
namespace {

// How simulate() would run a request, and whether the lanes run it instead.
struct Plan {
  std::optional<ModelDecision> decision;  // the auto model's (nullopt: the full model)
  IntegratorKind integrator = IntegratorKind::dop853;
  bool lanes = false;
};

Plan plan(const ValidatedRequest& v) {
  Plan plan;
  const SimulationRequest& req = v.request();
  if (req.model == ModelKind::automatic) {
    plan.decision = decide_model(v, RunOutput::result);
    if (plan.decision->route != ModelRoute::integrated) return plan;
    plan.integrator = plan.decision->integrator;
  } else {
    plan.integrator = effective_integrator(v);
  }
  const IntegratorOptions& opt = req.options;
  plan.lanes = plan.integrator == IntegratorKind::dop853 && req.law == LawKind::elastoplastic &&
               v.derived().has_dashpot() && !opt.fixed_step && opt.locate_events &&
               machine_code_in_use(opt.machine_code) == MachineCode::fastest &&
               detail::dop853_lanes_impacts_runnable();
  return plan;
}

// simulate(v) for a request the lanes do not run, by its plan.
ImpactResult run_one(const ValidatedRequest& v, const Plan& plan) {
  if (plan.decision) return run_model(v, *plan.decision, nullptr);
  return detail::simulate_full(v, plan.integrator, nullptr);
}

}  // namespace

bool runs_in_lanes(const ValidatedRequest& request) {
  return plan(request).lanes;
}

void simulate_batch(std::span<const ValidatedRequest> requests, std::span<ImpactResult> results) {
  if (requests.size() != results.size())
    throw std::invalid_argument("simulate_batch: as many results as requests");
  std::vector<Plan> plans(requests.size());
  std::vector<std::size_t> waiting;  // the lanes' impacts not run yet
  waiting.reserve(requests.size());  // one allocation, not one for every doubling
  for (std::size_t i = 0; i < requests.size(); ++i) {
    plans[i] = plan(requests[i]);
    if (plans[i].lanes)
      waiting.push_back(i);
    else
      results[i] = run_one(requests[i], plans[i]);
  }
  // the lanes share their options: those of the first waiting impact, then of the next left
  std::vector<detail::LaneImpact> lanes;
  lanes.reserve(waiting.size());
  while (!waiting.empty()) {
    const IntegratorOptions& options = requests[waiting.front()].request().options;
    std::vector<std::size_t> later;
    lanes.clear();
    for (const std::size_t i : waiting) {
      if (requests[i].request().options == options)
        lanes.push_back({&requests[i], &results[i]});
      else
        later.push_back(i);
    }
    detail::run_dop853_lanes(lanes);
    waiting.swap(later);
  }
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (!plans[i].lanes) continue;
    detail::finish_full(results[i], plans[i].integrator);
    if (plans[i].decision) finish_route(results[i], *plans[i].decision);
  }
}

}  // namespace ivv
