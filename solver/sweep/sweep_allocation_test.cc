// Heap allocations of a sweep's rows on their way to the CSV, counted by replacing the global
// operator new in this test binary (as solver/allocation_test.cc does for an impact).
//
// A worker's rows go into a SweepRowBatch it keeps; the sink takes a delivered batch's contents
// and hands back the buffers of one it has written. Once the buffers have grown to a batch's
// size, formatting rows and delivering them allocates nothing, however many rows: so no row's
// memory is ever freed on another thread than the one that allocated it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "solver/simulate_batch.h"
#include "solver/sweep/sweep.h"

// counted_allocations.cc: the global operator new replaced by one that counts
long heap_allocations_so_far();

namespace ivv {
namespace {

namespace fs = std::filesystem;

// A sink writing a journal and a partial CSV for `req`, handed to deliver(sink), which returns
// the allocations it counted; the sink is then finished and its files removed.
template <class Deliver>
long allocations_into_sink(const SweepRequest& req, Deliver&& deliver) {
  const fs::path csv =
      fs::temp_directory_path() / ("ivv_sweep_allocation_" + std::to_string(getpid()) + ".csv");
  long allocations = 0;
  {
    SweepSink sink(req, {csv, false, "test"});
    allocations = deliver(sink);
    EXPECT_TRUE(sink.finish({}));
  }
  fs::remove(csv);
  return allocations;
}

// Rows of a 40 x 50 grid formatted from one separated and one captured result into a batch of
// `batch` rows at a time and delivered to a sink; returns the allocations after the first
// `warm` batches (when the buffers have grown).
long allocations_of_rows(std::size_t batch, std::size_t warm) {
  SweepRequest req;
  req.base.scene = paper_scene();
  req.velocities = log_grid(0.1, 10.0, 40);
  req.zetas = linear_grid(0.0, 1.0, 50);
  ImpactResult separated = simulate(point_request(req, 7));
  EXPECT_TRUE(separated.separated()) << separated.reason;
  ImpactResult captured = separated;
  captured.status = ImpactStatus::captured;
  return allocations_into_sink(req, [&](SweepSink& sink) {
    const SweepInputColumns inputs(req);
    SweepRowBatch rows;
    long before = heap_allocations_so_far();
    for (std::size_t first = 0, b = 0; first < sink.total(); first += batch, ++b) {
      if (b == warm) before = heap_allocations_so_far();
      for (std::size_t i = first; i < first + batch && i < sink.total(); ++i) {
        std::string& text = rows.begin_row(i);
        const std::size_t start = text.size();
        inputs.append(text, i);
        rows.end_row(append_sweep_csv_results(text, start, i % 3 ? separated : captured));
      }
      sink.deliver(rows);
    }
    return heap_allocations_so_far() - before;
  });
}

// One worker's batch and the sink's spare trade their buffers, two texts each (the rows and
// their journal lines); each grows by doubling, so a later batch a few characters longer than
// every earlier one (rows differ in length) may still grow each text once more: at most four
// allocations after the warm-up, against one a row (2,000 here) without the reuse.
constexpr long kMaxLateGrowths = 4;

TEST(SweepAllocations, RowsAllocateNothingOnceTheBatchBuffersHaveGrown) {
  EXPECT_LE(allocations_of_rows(32, 2), kMaxLateGrowths);
  EXPECT_LE(allocations_of_rows(7, 2), kMaxLateGrowths);
}

// Allocations of run_sweep_points on a grid of the 300 x 300 map's range and settings (--model
// auto, --integrator auto, rtol = atol = 1e-8), one thread, batches of kSweepBatchPoints.
long allocations_of_sweep(int velocities, int zetas) {
  SweepRequest req;
  req.base.scene = paper_scene();
  req.base.law = LawKind::elastoplastic;
  req.base.model = ModelKind::automatic;
  req.base.auto_integrator = true;
  req.base.options.rtol = req.base.options.atol = 1e-8;
  req.velocities = log_grid(0.1, 10.0, velocities);
  req.zetas = linear_grid(0.0, 1.0, zetas);
  req.threads = 1;
  return allocations_into_sink(req, [&](SweepSink& sink) {
    const long before = heap_allocations_so_far();
    run_sweep_points(req, sink, {});
    return heap_allocations_so_far() - before;
  });
}

// What a batch allocates, whatever its points: the index vector take() hands out; in
// simulate_batch the plans, the waiting points, the lanes' list and the points left for later;
// run_lanes' jobs; and each of the four lanes' first event list (a lane's later impacts reuse
// its memory, and the batch's results reuse theirs): ten, and two more for a row or journal
// buffer that grows once more (kMaxLateGrowths above, per text). An impact in the lanes
// allocated two event lists before (2.6 allocations a point on the map).
constexpr long kMaxPerBatch = 12;
// Where the lanes do not run (the ASan build, whose dop853 is baseline code; a CPU without AVX2
// and FMA; IVV_MACHINE_CODE=baseline), each point is simulated on its own and allocates its two
// event lists, as solver/allocation_test.cc bounds an impact.
constexpr long kPerPointOutsideTheLanes = 2;

TEST(SweepAllocations, PointsAllocateNothingOnlyTheirBatchesDo) {
  // 64 x 32 and 64 x 96 points: 16 and 48 batches; the difference leaves out the warm-up
  const long small = allocations_of_sweep(64, 32), large = allocations_of_sweep(64, 96);
  const long points = 64 * 96 - 64 * 32;
  const long batches = points / static_cast<long>(kSweepBatchPoints);
  SweepRequest grid;
  grid.base.scene = paper_scene();
  grid.velocities = {1.0};
  grid.zetas = {0.1};
  const SimulationRequest point = point_request(grid, 0);
  const bool lanes = runs_in_lanes(ValidatedRequest(point));
  EXPECT_LE(large - small, kMaxPerBatch * batches + (lanes ? 0 : kPerPointOutsideTheLanes * points))
      << "a sweep of " << points << " more points allocated " << large - small
      << " times more (points in SIMD lanes: " << (lanes ? "yes" : "no") << ")";
}

}  // namespace
}  // namespace ivv
