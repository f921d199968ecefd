// Outcome of one attempted step of an integrator adapter.
#pragma once

#include <string>

namespace ivv {

struct StepResult {
  bool ok = true;
  std::string reason;  // why the integrator could not go on (empty when ok)
  static StepResult success() { return {}; }
  static StepResult failure(std::string why) { return {false, std::move(why)}; }
};

}  // namespace ivv
