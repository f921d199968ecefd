#include "solver/steppers/machine_code.h"

#include "solver/steppers/fma_copy.h"

#include <cstdlib>
#include <string>

#include "scene/input_error.h"

namespace ivv {
namespace {

// IVV_MACHINE_CODE, read once: unset, "" or "fastest" leave the choice to the CPU, "baseline"
// forces the baseline code; anything else is bad input naming the variable (`problem`).
struct EnvironmentChoice {
  MachineCode code = MachineCode::fastest;
  std::string problem;
};

const EnvironmentChoice& environment_choice() {
  static const EnvironmentChoice choice = [] {
    const char* value = std::getenv("IVV_MACHINE_CODE");
    const std::string v = value ? value : "";
    if (v.empty() || v == to_string(MachineCode::fastest)) return EnvironmentChoice{};
    if (v == to_string(MachineCode::baseline)) return EnvironmentChoice{MachineCode::baseline, ""};
    return EnvironmentChoice{MachineCode::baseline,
                             "must be baseline (the x86-64 code every CPU runs) or fastest (the "
                             "AVX2 + FMA copy where the CPU has them; the default), got '" +
                                 v + "'"};
  }();
  return choice;
}

}  // namespace

bool cpu_has_fma_clone() {
#if IVV_FMA_COPY
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return has;
#else
  return false;
#endif
}

const std::string& machine_code_environment_problem() {
  return environment_choice().problem;
}

MachineCode machine_code_in_use(MachineCode requested) {
  const EnvironmentChoice& environment = environment_choice();
  if (!environment.problem.empty()) throw InputError("IVV_MACHINE_CODE", environment.problem);
  if (requested == MachineCode::baseline || environment.code == MachineCode::baseline)
    return MachineCode::baseline;
  return cpu_has_fma_clone() ? MachineCode::fastest : MachineCode::baseline;
}

std::string_view to_string(MachineCode code) {
  return code == MachineCode::baseline ? "baseline" : "fastest";
}

std::string_view machine_code_description(MachineCode in_use) {
  return in_use == MachineCode::baseline ? "x86-64 baseline" : "x86-64-v3 (AVX2, FMA)";
}

}  // namespace ivv
