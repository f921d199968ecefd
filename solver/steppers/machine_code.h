// Which machine code runs an impact's hot loop: the baseline x86-64 code every build has (SSE2,
// no fused multiply-add), or a copy of the same C++ compiled for CPUs with AVX2 and FMA
// (x86-64-v3: Intel Haswell and later, AMD Zen), chosen once per process from the CPU.
//
// The copy (solver/steppers/dop853_fma.cc) is the dop853 run (driver, stepper, event locator,
// system) of the elastoplastic and Hertz laws compiled under GCC's target("avx2,fma") and
// instantiated on types local to that unit, so no code the rest of the program calls is compiled
// for those CPUs and the binary runs on any x86-64 (cpu_clone_symbols checks the object). Where the
// compiler contracts a*b + c into one fused multiply-add, the result is rounded once instead of
// twice: the last bits of a run differ from the baseline's, within the integrator's stated error
// (the verification cases cross.machine-code.* run grids of the paper map through both and bound
// |de|).
//
// IVV_MACHINE_CODE=baseline in the environment (read once per process) forces the baseline
// code everywhere, for reproducing a baseline run bit for bit on a newer CPU;
// IntegratorOptions::machine_code = MachineCode::baseline does the same for one run.
#pragma once

#include <string>
#include <string_view>

namespace ivv {

enum class MachineCode {
  fastest,   // the FMA copy where the CPU has AVX2 and FMA (and the run has a copy), else baseline
  baseline,  // the baseline x86-64 code
};

// The code an impact asked for as `requested` runs: baseline unless requested is fastest,
// the CPU has AVX2 and FMA, and IVV_MACHINE_CODE is not "baseline". Throws InputError naming
// IVV_MACHINE_CODE when it holds anything but "baseline", "fastest" or nothing.
MachineCode machine_code_in_use(MachineCode requested);

// What is wrong with IVV_MACHINE_CODE: "" when it is unset, empty, "baseline" or "fastest"
// (IntegratorOptions::invalid() reports it, so a request is refused before it runs).
const std::string& machine_code_environment_problem();

// Whether this CPU can run the FMA copy (AVX2 and FMA; false on a non-x86 build).
bool cpu_has_fma_clone();

// "fastest" / "baseline"; and the name of the code that runs (`ivv bench`, the report):
// "x86-64-v3 (AVX2, FMA)" or "x86-64 baseline".
std::string_view to_string(MachineCode code);
std::string_view machine_code_description(MachineCode in_use);

}  // namespace ivv
