// The dop853 run of the paper's laws compiled a second time for CPUs with AVX2 and FMA
// (solver/steppers/machine_code.h says which runs): the same C++ as run_typed<Dop853Stepper,
// Law, Dashpot> of solver/simulate_impl.h, instantiated in dop853_fma.cc on a law type of that
// unit only, so its machine code (fused multiply-adds, AVX encodings) is that unit's own and
// replaces no baseline code of the same templates (cpu_clone_symbols checks the object).
//
// Covered: the elastoplastic law (the paper's, with and without the dashpot: the paper map and
// the single impact) and Hertz (Zener's problem). Other laws and integrators run the baseline
// code. Call only where cpu_has_fma_clone() is true.
#pragma once

#include <type_traits>
#include <vector>

#include "scene/scene.h"
#include "solver/laws/elastoplastic.h"
#include "solver/laws/hertz.h"
#include "solver/result.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {
struct TrajectoryPoint;
}

namespace ivv::detail {

// The laws with a copy: exactly these types (a law derived from one of them has its own members,
// which the copy of the base would silently replace).
template <class Law>
inline constexpr bool kHasFmaCopy =
    std::is_same_v<Law, ElastoplasticLaw> || std::is_same_v<Law, HertzLaw>;

ImpactResult run_dop853_fma(const ElastoplasticLaw& law, const Scene& scene,
                            const IntegratorOptions& options, const DerivedParameters& p,
                            std::vector<TrajectoryPoint>* trajectory);
ImpactResult run_dop853_fma(const HertzLaw& law, const Scene& scene,
                            const IntegratorOptions& options, const DerivedParameters& p,
                            std::vector<TrajectoryPoint>* trajectory);

}  // namespace ivv::detail
