// The dop853 run in SIMD lanes (simulate_lanes.h), compiled for AVX2 + FMA where the build
// compiles the FMA copy.
//
// The rules of solver/steppers/dop853_fma.cc: everything included from outside ivv comes first,
// compiled as usual; then ivv's headers under `#pragma GCC target("avx2,fma")`, with every
// template instantiated on types of this unit only (LocalLaw, Avx2Lanes: internal linkage), so no
// AVX2 code stands in for baseline code of the same name (cpu_clone_symbols_lanes_impacts checks
// the object). The entry point comes after the region, baseline code that checks the CPU before
// it calls in. The stage arithmetic is contracted into fused multiply-adds, as in the FMA copy of
// the scalar run.
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

#include "solver/steppers/fma_copy.h"      // IVV_FMA_COPY, a macro only
#include "solver/steppers/machine_code.h"  // cpu_has_fma_clone(), defined in baseline code

#if IVV_FMA_COPY
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#elif defined(__GNUC__)
// Four lanes are 32-byte vectors, passed between this unit's own functions (internal linkage):
// without AVX GCC notes that their ABI differs from an AVX caller's, which no caller here is.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include "solver/driver/lanes_driver.h"
#include "solver/simulate_impl.h"
#include "solver/simulate_lanes.h"
#include "solver/steppers/avx2_lanes.h"

namespace ivv::detail {
namespace {

// The law as a type of this unit: every template instantiated on it has internal linkage.
struct LocalLaw : ElastoplasticLaw {
  LocalLaw() = default;
  explicit LocalLaw(const ElastoplasticLaw& law) : ElastoplasticLaw(law) {}
};
using System = ImpactSystem<LocalLaw, true>;

// A lane's impact while it runs: its request, result and scales.
struct Job {
  const LaneImpact* impact;
  Scales k{};
};

// Not inlined into its baseline caller (run_dop853_lanes): GCC did, with this function's AVX
// code, which would run before the CPU is checked (cpu_clone_symbols_lanes_impacts caught it).
[[gnu::noinline]] void run_lanes(std::span<const LaneImpact> impacts) {
  std::vector<Job> jobs;
  jobs.reserve(impacts.size());
  for (const LaneImpact& impact : impacts) {
    const SimulationRequest& req = impact.request->request();
    if (req.law != LawKind::elastoplastic || !impact.request->derived().has_dashpot())
      throw std::logic_error("dop853 in lanes: the elastoplastic law with a dashpot only");
    jobs.push_back({&impact});
  }
  const IntegratorOptions& options = impacts.front().request->request().options;
  auto set_up = [](Job& job, System& sys) {
    const ValidatedRequest& v = *job.impact->request;
    const DerivedParameters& p = v.derived();
    job.k = scales_for<LocalLaw>(v.request().scene, p);
    set_up_system(sys, LocalLaw(ElastoplasticLaw::make(v.request().parameters, p)), p, job.k);
  };
  auto finish = [](Job& job, NormalisedRun<System>&& run, const System& sys) {
    ImpactResult& result = *job.impact->result;  // a sweep's batch keeps it: its events' memory
    result = to_physical(run, sys, job.impact->request->request().scene, job.k,
                         std::move(result.events));
  };
  run_impacts_in_lanes<System, Avx2Lanes>(std::span<Job>(jobs), options, set_up, finish);
}

}  // namespace
}  // namespace ivv::detail

#if IVV_FMA_COPY
#pragma GCC pop_options
#endif

namespace ivv::detail {

bool dop853_lanes_impacts_runnable() {
  return !IVV_FMA_COPY || cpu_has_fma_clone();
}

void run_dop853_lanes(std::span<const LaneImpact> impacts) {
  if (!dop853_lanes_impacts_runnable())
    throw std::logic_error("dop853 in lanes: compiled for AVX2 + FMA, which this CPU lacks");
  if (!impacts.empty()) run_lanes(impacts);
}

}  // namespace ivv::detail
