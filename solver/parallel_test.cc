// parallel_for: every index once, results in index order for any thread count, a throwing
// worker reported with its index, a stop request honoured.
#include "solver/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ivv {
namespace {

// Work of uneven cost, so that threads finish out of order.
double uneven_work(std::size_t i) {
  double s = 0;
  const int n = static_cast<int>((i * 7919) % 5000);
  for (int k = 1; k <= n; ++k) s += std::sin(static_cast<double>(k + i));
  return s;
}

class ParallelForThreads : public ::testing::TestWithParam<int> {};

TEST_P(ParallelForThreads, EveryIndexOnceAndResultsIdenticalToSerial) {
  constexpr std::size_t n = 1000;
  std::vector<double> serial(n);
  for (std::size_t i = 0; i < n; ++i) serial[i] = uneven_work(i);

  std::vector<double> out(n, std::nan(""));
  std::vector<std::atomic<int>> calls(n);
  parallel_for(n, GetParam(), [&](std::size_t i) {
    ++calls[i];
    out[i] = uneven_work(i);
  });
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(calls[i].load(), 1) << i;
    // Bitwise equal: the same computation on the same input, whatever the thread.
    EXPECT_EQ(out[i], serial[i]) << i;
  }
}

TEST_P(ParallelForThreads, ExceptionReachesTheCallerWithItsIndex) {
  constexpr std::size_t n = 500, bad = 137;
  std::atomic<std::size_t> started{0};
  try {
    parallel_for(n, GetParam(), [&](std::size_t i) {
      ++started;
      if (i == bad) throw std::domain_error("point 137 is bad");
      uneven_work(i);
    });
    FAIL() << "parallel_for returned normally";
  } catch (const ParallelError& e) {
    EXPECT_EQ(e.index(), bad);
    EXPECT_NE(std::string(e.what()).find("item 137: point 137 is bad"), std::string::npos)
        << e.what();
    EXPECT_THROW(std::rethrow_exception(e.cause()), std::domain_error);
  }
  // The other workers stop taking work once the failure is recorded. With one thread that is
  // exact; with several, a worker preempted between its throw and the stop flag lets the others
  // run on (seen under load): promptness is asserted where it is deterministic.
  if (GetParam() == 1) {
    EXPECT_EQ(started.load(), bad + 1);
  }
}

TEST_P(ParallelForThreads, ProgressCountsEveryItemInOrder) {
  constexpr std::size_t n = 200;
  std::vector<std::size_t> seen;
  ParallelOptions opt;
  opt.threads = GetParam();
  opt.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, n);
    seen.push_back(done);
  };
  parallel_for(n, opt, [](std::size_t i) { uneven_work(i); });
  ASSERT_EQ(seen.size(), n);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(seen[k], k + 1);
}

TEST_P(ParallelForThreads, StopRequestEndsTheLoopWithoutError) {
  constexpr std::size_t n = 100000;
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> calls{0};
  ParallelOptions opt;
  opt.threads = GetParam();
  opt.stop = &stop;
  parallel_for(n, opt, [&](std::size_t i) {
    if (++calls == 50) stop = true;
    uneven_work(i % 10);
  });
  EXPECT_GE(calls.load(), 50u);
  EXPECT_LE(calls.load(), 50u + static_cast<std::size_t>(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Threads, ParallelForThreads, ::testing::Values(1, 2, 3, 4),
                         [](const auto& info) { return std::to_string(info.param) + "threads"; });

TEST(ParallelFor, LowestFailingIndexIsReportedWhenSeveralThrow) {
  // Every index >= 10 throws. Indices are handed out in increasing order and a worker always
  // runs the index it took, so index 10 is always run and always throws: it is the one named.
  try {
    parallel_for(1000, 4, [](std::size_t i) {
      if (i >= 10) throw std::runtime_error("bad");
    });
    FAIL() << "parallel_for returned normally";
  } catch (const ParallelError& e) {
    EXPECT_EQ(e.index(), 10u);
  }
}

TEST(ParallelFor, NonStandardExceptionIsStillNamed) {
  try {
    parallel_for(3, 2, [](std::size_t i) {
      if (i == 2) throw 42;
    });
    FAIL() << "parallel_for returned normally";
  } catch (const ParallelError& e) {
    EXPECT_EQ(e.index(), 2u);
    EXPECT_THROW(std::rethrow_exception(e.cause()), int);
  }
}

TEST(ParallelFor, EmptyRangeCallsNothing) {
  parallel_for(0, 4, [](std::size_t) { FAIL() << "called for an empty range"; });
  EXPECT_EQ(worker_count(0, 4), 1);
  EXPECT_EQ(worker_count(3, 8), 3);
  EXPECT_EQ(worker_count(100, 2), 2);
}

// A thread that spins for 50 ms of wall time is on a core or waiting for one all along: the
// kernel's two counts add up to the spin (less 5 ms: the two readings of /proc are taken
// microseconds apart, and the scheduler's clock is in nanoseconds), and it ran for some of it.
TEST(ThreadSchedule, CountsTheWallTimeOfABusyThreadAsRunningOrWaiting) {
  const std::optional<ThreadSchedule> before = thread_schedule();
  if (!before) {
    // the contract where the kernel does not say: nothing to read there, and nullopt every time
    std::FILE* f = std::fopen("/proc/thread-self/schedstat", "r");
    const bool readable = f != nullptr;
    if (f) std::fclose(f);
    EXPECT_FALSE(readable) << "schedstat is readable, but thread_schedule() gave nullopt";
    EXPECT_FALSE(thread_schedule());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  volatile unsigned long spins = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(50))
    spins = spins + 1;
  const std::optional<ThreadSchedule> after = thread_schedule();
  ASSERT_TRUE(after);
  const double running = after->running - before->running;
  const double waiting = after->waiting - before->waiting;
  EXPECT_GT(running, 0.0);
  EXPECT_GE(waiting, 0.0);
  EXPECT_GE(running + waiting, 0.045);
}

}  // namespace
}  // namespace ivv
