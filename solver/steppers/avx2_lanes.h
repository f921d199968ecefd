// The lane arithmetic of dop853 in four lanes (dop853_lanes.h) for a unit compiled for AVX2 + FMA
// (fma_copy.h: IVV_FMA_COPY): LaneMath<4> with all four roots in one vsqrtpd, correctly rounded
// as std::sqrt. Include it only inside such a unit's target region, after fma_copy.h.
//
// Avx2Lanes is declared in an unnamed namespace on purpose: each unit that includes it has its
// own type, so every template instantiated on it (Dop853Lanes<System, Avx2Lanes>, ...) has
// internal linkage and its AVX2 code cannot stand in for another unit's code of the same name
// (the rule of dop853_fma.cc, checked by cpu_clone_symbols).
#pragma once

#include "solver/steppers/dop853_lanes.h"
#include "solver/steppers/dop853_lanes_run.h"

namespace ivv {
namespace {

struct Avx2Lanes : LaneMath<kDop853Lanes> {
#if IVV_FMA_COPY
  [[gnu::always_inline]] static vector sqrt(vector v) {
    return __builtin_ia32_sqrtpd256(v);
  }
#endif
};

}  // namespace
}  // namespace ivv
