// One parallel loop for the whole project: parallel_for(n, threads, fn) calls fn(i) once for
// every i in [0, n) on a pool of worker threads that take indices in increasing order.
//
// Contract
// - Results are the caller's: fn writes into slot i of a vector sized n beforehand, so the
//   order of results never depends on scheduling and output built from them is identical for
//   any thread count.
// - An exception thrown by fn(i) stops the loop: no worker takes a new index, the workers
//   finish the calls in flight, and the caller receives ParallelError naming the index (the
//   lowest one, when several workers throw) with the original exception inside.
// - `stop` (optional): when it becomes true no new index is handed out and parallel_for
//   returns normally after the calls in flight; the caller knows which slots were filled.
// - `progress` (optional) is called after each completed fn(i) with (done, n), serialised,
//   on the worker thread that completed it.
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace ivv {

class ParallelError : public std::runtime_error {
 public:
  ParallelError(std::size_t index, std::exception_ptr cause, const std::string& what)
      : std::runtime_error("item " + std::to_string(index) + ": " + what),
        index_(index),
        cause_(std::move(cause)) {}
  std::size_t index() const { return index_; }
  // The exception fn(index) threw (std::rethrow_exception to inspect it).
  std::exception_ptr cause() const { return cause_; }

 private:
  std::size_t index_;
  std::exception_ptr cause_;
};

struct ParallelOptions {
  int threads = 0;  // 0: std::thread::hardware_concurrency(); never more than n
  std::function<void(std::size_t done, std::size_t total)> progress;
  const std::atomic<bool>* stop = nullptr;
};

// A worker count as a user gives it (--threads): >= 0, 0 for all cores. Throws
// InputError("--threads", ...) otherwise: the one check of every front end's thread count.
void validate_threads(int threads);

// The number of workers parallel_for would use for n items (>= 1).
int worker_count(std::size_t n, int threads);

void parallel_for(std::size_t n, const ParallelOptions& options,
                  const std::function<void(std::size_t)>& fn);

// The calling thread's time so far as the kernel's scheduler counted it (Linux:
// /proc/thread-self/schedstat, nanoseconds): on a core, and runnable but waiting for one. What is
// left of its wall time the thread was blocked (a lock, a condition variable, I/O) or not yet
// started. Waiting for a core is the machine's doing (other processes on the cores); being
// blocked is the program's. nullopt where the kernel does not say (not Linux, no schedstat).
struct ThreadSchedule {
  double running = 0.0;  // [s]
  double waiting = 0.0;  // [s]
};
std::optional<ThreadSchedule> thread_schedule();

inline void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
  parallel_for(n, ParallelOptions{threads, {}, nullptr}, fn);
}

}  // namespace ivv
