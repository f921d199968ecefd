#include "solver/parallel.h"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "scene/input_error.h"

namespace ivv {

void validate_threads(int threads) {
  if (threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
}

int worker_count(std::size_t n, int threads) {
  const int wanted = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  const std::size_t capped =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(1, wanted)), n);
  return static_cast<int>(std::max<std::size_t>(1, capped));
}

void parallel_for(std::size_t n, const ParallelOptions& options,
                  const std::function<void(std::size_t)>& fn) {
  if (n == 0) return;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards done, the progress callback and the first error
  std::size_t done = 0;
  std::size_t error_index = n;
  std::exception_ptr error;
  std::string error_what;

  auto stopping = [&] { return failed.load() || (options.stop && options.stop->load()); };
  auto worker = [&] {
    while (!stopping()) {
      const std::size_t i = next++;
      if (i >= n) return;
      try {
        fn(i);
        if (options.progress) {
          std::lock_guard lock(mutex);
          options.progress(++done, n);
        }
      } catch (...) {
        std::exception_ptr caught = std::current_exception();
        std::string what = "an exception not derived from std::exception";
        try {
          std::rethrow_exception(caught);
        } catch (const std::exception& e) {
          what = e.what();
        } catch (...) {
        }
        std::lock_guard lock(mutex);
        if (i < error_index) {
          error_index = i;
          error = caught;
          error_what = what;
        }
        failed = true;
        return;
      }
    }
  };

  const int workers = worker_count(n, options.threads);
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  try {
    for (int t = 1; t < workers; ++t) pool.emplace_back(worker);
  } catch (...) {  // no thread could be started: stop those that were, then report
    failed = true;
    for (auto& t : pool) t.join();
    throw;
  }
  worker();
  for (auto& t : pool) t.join();
  if (error) throw ParallelError(error_index, error, error_what);
}

std::optional<ThreadSchedule> thread_schedule() {
  std::FILE* f = std::fopen("/proc/thread-self/schedstat", "r");
  if (!f) return std::nullopt;
  unsigned long long running = 0, waiting = 0;  // [ns]
  const int read = std::fscanf(f, "%llu %llu", &running, &waiting);
  std::fclose(f);
  if (read != 2) return std::nullopt;
  return ThreadSchedule{1e-9 * static_cast<double>(running), 1e-9 * static_cast<double>(waiting)};
}

}  // namespace ivv
