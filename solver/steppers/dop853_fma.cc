// The AVX2 + FMA copy of the dop853 run (solver/steppers/dop853_fma.h).
//
// Everything this unit includes from outside ivv comes first, compiled as usual; then the
// target region: ivv's headers are read under `#pragma GCC target("avx2,fma")`, so each function
// template they define is instantiated here with that target. The run is instantiated on a law
// type of this unit only (LocalLaw, internal linkage), so the driver, the stepper, the locator
// and the system instantiated on it are this unit's own functions: their AVX2 code cannot stand
// in for the baseline code of the same templates elsewhere (one name, two codes, the linker
// picking either). A function of the region instantiated on types the rest of the program shares
// would be such a stand-in; cpu_clone_symbols_test checks this object defines none.
#include <algorithm>
#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/steppers/fma_copy.h"  // IVV_FMA_COPY, a macro only

// Where IVV_FMA_COPY is 0 (not x86-64, unoptimised, or under AddressSanitizer: fma_copy.h)
// cpu_has_fma_clone() is false and this unit is one more baseline copy, never called.
#if IVV_FMA_COPY
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif

#include "solver/simulate_impl.h"
#include "solver/steppers/dop853.h"
#include "solver/steppers/dop853_fma.h"

namespace ivv::detail {
namespace {

// The law as a type of this unit: every template instantiated on it has internal linkage.
template <class Law>
struct LocalLaw : Law {
  LocalLaw() = default;
  explicit LocalLaw(const Law& law) : Law(law) {}
};

template <class Law>
ImpactResult run_fma(const Law& law, const Scene& scene, const IntegratorOptions& options,
                     const DerivedParameters& p, std::vector<TrajectoryPoint>* trajectory) {
  const LocalLaw<Law> local(law);
  return p.has_dashpot() ? run_typed<Dop853Stepper, LocalLaw<Law>, true, double>(
                               local, scene, options, p, trajectory)
                         : run_typed<Dop853Stepper, LocalLaw<Law>, false, double>(
                               local, scene, options, p, trajectory);
}

}  // namespace

ImpactResult run_dop853_fma(const ElastoplasticLaw& law, const Scene& scene,
                            const IntegratorOptions& options, const DerivedParameters& p,
                            std::vector<TrajectoryPoint>* trajectory) {
  return run_fma(law, scene, options, p, trajectory);
}

ImpactResult run_dop853_fma(const HertzLaw& law, const Scene& scene,
                            const IntegratorOptions& options, const DerivedParameters& p,
                            std::vector<TrajectoryPoint>* trajectory) {
  return run_fma(law, scene, options, p, trajectory);
}

}  // namespace ivv::detail

#if IVV_FMA_COPY
#pragma GCC pop_options
#endif
