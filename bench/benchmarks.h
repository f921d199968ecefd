// The Google Benchmark suite: wall-clock time of one impact per integrator.
//
// Benchmarks (names are what --benchmark_filter matches):
//   paper/default/<integrator>   paper scene, v0 = 1 m/s, c = 11440 N s/m (zeta ~ 0.1),
//                                elastoplastic law, each integrator at its default settings
//   paper/rtol=1e-6/<integrator> the same at rtol = atol = 1e-6 (adaptive integrators only:
//                                rk4 has no tolerance, its step is fixed)
//   stiff/<integrator>           the paper scene with zeta = 1000 (dashpot time scale c/K_y
//                                ~ 1e-6 of the contact time), for the two implicit integrators
//   reference/mp50               the 50-digit reference, once: the price of the yardstick
// Each reports, as counters, the RHS evaluations and accepted steps of one impact and the
// Newton COR obtained (so a fast but wrong run is visible). A failed impact is reported as a
// benchmark error, not timed.
//
// Google Benchmark repeats each case until its timing is stable and reports the mean per
// iteration; pass --benchmark_repetitions=N to get the median over N repetitions. Timings
// are never pass/fail; on a shared machine compare ratios within one run of the suite.
#pragma once

namespace ivv::bench {

// Runs the suite: benchmark::Initialize(argc, argv) (so every --benchmark_* flag works),
// RunSpecifiedBenchmarks, Shutdown. Returns 0, or 1 for an unrecognised argument.
// Throws InputError first for a --benchmark_* value Google Benchmark would misuse (each was
// passed through and misbehaved): --benchmark_min_time not a positive number of seconds (nan
// ran past 60 s) or iterations, --benchmark_repetitions not in [1, 1000] (-5 failed in
// vector::reserve), and a --benchmark_out that is not a regular file or new path in an
// existing directory (/dev/full lost the output with exit 0).
int run_benchmarks(int argc, char** argv);
// The check above, on its own.
void validate_benchmark_arguments(int argc, char** argv);

}  // namespace ivv::bench
