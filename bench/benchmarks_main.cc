// ./build/bench/ivv_bench [--benchmark_filter=REGEX] [--benchmark_repetitions=N] ...
#include "bench/benchmarks.h"

int main(int argc, char** argv) {
  return ivv::bench::run_benchmarks(argc, argv);
}
