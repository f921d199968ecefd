#include "solver/sweep/sweep.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/format.h"
#include "solver/parallel.h"
#include "solver/plate/plate_law.h"
#include "solver/simulate_batch.h"

namespace ivv {
namespace {

// "sweep point 7 (--v0 1 --zeta 0.1, structure.thickness = 0.002)": the point as typed.
std::string point_label(const SweepRequest& req, std::size_t index, const PointInputs& in) {
  std::string label = "sweep point " + std::to_string(index) + " (--v0 ";
  append_shortest(label, in.v0);
  if (req.scene_dashpot) {
    label += ", the scene's dashpot";
  } else {
    label += " --zeta ";
    append_shortest(label, in.zeta);
  }
  for (std::size_t k = 0; k < req.axes.size(); ++k) {
    label += ", " + req.axes[k].key + " = ";
    append_shortest(label, in.axes[k]);
  }
  return label + ")";
}

// Times one worker of run_sweep_points into its SweepWorkerTime (none when `slot` is null):
// from construction to destruction, whichever way the worker ends.
class WorkerClock {
 public:
  using Clock = std::chrono::steady_clock;
  WorkerClock(SweepWorkerTime* slot, Clock::time_point origin)
      : slot_(slot), origin_(origin), start_(Clock::now()), schedule_(thread_schedule()) {}
  WorkerClock(const WorkerClock&) = delete;
  WorkerClock& operator=(const WorkerClock&) = delete;
  ~WorkerClock() {
    if (!slot_) return;
    const std::optional<ThreadSchedule> now = thread_schedule();
    slot_->start = seconds(start_);
    slot_->end = seconds(Clock::now());
    if (now && schedule_) {
      slot_->running = now->running - schedule_->running;
      slot_->waiting = now->waiting - schedule_->waiting;
    }
    slot_->points = points_;
  }
  void add_points(std::size_t n) { points_ += n; }

 private:
  double seconds(Clock::time_point t) const {
    return std::chrono::duration<double>(t - origin_).count();
  }
  SweepWorkerTime* slot_;
  Clock::time_point origin_, start_;
  std::optional<ThreadSchedule> schedule_;
  std::size_t points_ = 0;
};

// A finite plate's point: the full plate with the sweep's tolerances (solver/plate/plate_impact.h).
ImpactResult simulate_plate_point(const SimulationRequest& point) {
  PlateImpactOptions opt;
  opt.rtol = point.options.rtol;
  opt.atol = point.options.atol;
  // the mode cut-off chosen for the truncation tolerance `simulate` states (plate_impact.h)
  opt.truncation_tol = kPlateTruncationTol;
  opt.cutoff = kPlateFirstCutoff;
  return as_sweep_result(simulate_plate_law(point, opt));
}

// Point `index` run with `point` (req.base, or a point of the same grid before) made its request
// (assign_point_request); validated with what the grid's points share (`shared`) when given, by
// the point alone otherwise (one point: making the shared part would cost more than it saves).
// `inputs()` gives the point's PointInputs, for the message of a point that throws.
template <class Inputs>
ImpactResult simulate_point(const SweepRequest& req, const SweepPointRequests* shared,
                            std::size_t index, SimulationRequest& point, const Inputs& inputs) {
  try {
    assign_point_request(req, index, point);
    if (has_finite_plate(point.scene)) return simulate_plate_point(point);
    return simulate(shared ? shared->validated(index, point)
                           : ValidatedRequest::grid_point(req, point));
  } catch (const std::exception& e) {
    throw std::runtime_error(point_label(req, index, inputs()) + ": " + e.what());
  }
}

}  // namespace

namespace {
// Point `index`'s row into the worker's batch: the inputs copied from their text, the results
// formatted into the batch's buffer (no allocation once it has grown).
void append_row(const SweepInputColumns& inputs, std::size_t index, const ImpactResult& result,
                SweepRowBatch& rows) {
  std::string& text = rows.begin_row(index);
  const std::size_t start = text.size();
  inputs.append(text, index);
  rows.end_row(append_sweep_csv_results(text, start, result));
}

// What a worker keeps from one batch of points to the next, so that a batch allocates nothing
// once these have grown: each point's request (made from the base request at first, then by
// assign_point_request), the validated requests and their results.
struct BatchScratch {
  std::vector<SimulationRequest> requests;
  std::vector<ValidatedRequest> validated;
  std::vector<std::size_t> validated_at;  // the batch position of each validated request
  std::vector<ImpactResult> validated_results, results;
  SimulationRequest point;  // a point's request when the batch is run again point by point
};

// The results of the points `batch` into s.results, in the batch's order: the points together
// (simulate_batch: the paper's law in SIMD lanes), a finite plate's point on its own. A point
// whose run throws is found by running the batch again point by point, where simulate_point
// names it; a batch that throws where its points one by one do not is an error that says so
// (never a silent retry).
// `shared` may be null (one point: making it would cost more than it saves).
void compute_batch(const SweepRequest& req, const SweepPointRequests* shared,
                   std::span<const std::size_t> batch, BatchScratch& s) {
  const std::size_t n = batch.size();
  if (s.requests.size() < n) s.requests.resize(n, req.base);
  s.results.resize(n);
  s.validated.clear();
  s.validated_at.clear();
  try {
    for (std::size_t k = 0; k < n; ++k) {
      assign_point_request(req, batch[k], s.requests[k]);
      if (has_finite_plate(s.requests[k].scene)) {
        s.results[k] = simulate_plate_point(s.requests[k]);
        continue;
      }
      s.validated.push_back(shared ? shared->validated(batch[k], s.requests[k])
                                   : ValidatedRequest::grid_point(req, s.requests[k]));
      s.validated_at.push_back(k);
    }
    s.validated_results.resize(s.validated.size());
    simulate_batch(s.validated, s.validated_results);
  } catch (const std::exception& batch_error) {
    s.point = req.base;
    for (const std::size_t index : batch)
      simulate_point(req, shared, index, s.point, [&] { return point_inputs(req, index); });
    throw std::runtime_error(std::string("sweep points ") + std::to_string(batch.front()) + " to " +
                             std::to_string(batch.back()) +
                             " failed together but not one by one: " + batch_error.what());
  }
  for (std::size_t j = 0; j < s.validated.size(); ++j)
    std::swap(s.results[s.validated_at[j]], s.validated_results[j]);
}

// The points of `batch` (compute_batch), then their rows into the worker's batch of rows.
void run_sweep_batch(const SweepRequest& req, const SweepPointRequests& shared,
                     const SweepInputColumns& inputs, std::span<const std::size_t> batch,
                     BatchScratch& s, SweepRowBatch& rows) {
  compute_batch(req, &shared, batch, s);
  for (std::size_t k = 0; k < batch.size(); ++k) append_row(inputs, batch[k], s.results[k], rows);
}

// Points a batch of run_sweep, as run_sweep_points' workers take them (SweepRunOptions::batch).
constexpr std::size_t kSweepBatch = kSweepBatchPoints;
}  // namespace

std::string run_sweep_point(const SweepRequest& req, std::size_t index) {
  // a batch of one, so that the point's result is the sweep's to the bit (simulate_batch.h)
  BatchScratch scratch;
  const std::size_t indices[] = {index};
  compute_batch(req, nullptr, indices, scratch);
  return sweep_csv_row(point_inputs(req, index), scratch.results[0]);
}

std::vector<SweepPoint> run_sweep(const SweepRequest& req) {
  validate(req);
  std::vector<SweepPoint> points(point_count(req));
  const SweepPointRequests shared(req);
  ParallelOptions opt;
  opt.threads = req.threads;
  opt.stop = req.stop;
  // batches of up to kSweepBatch consecutive points, each computed together (compute_batch),
  // smaller near the end of the grid (guided_batch_size): batch b is [starts[b], starts[b + 1])
  const std::size_t workers = static_cast<std::size_t>(worker_count(points.size(), req.threads));
  std::vector<std::size_t> starts;
  for (std::size_t first = 0; first < points.size();
       first += guided_batch_size(points.size() - first, workers, kSweepBatch))
    starts.push_back(first);
  starts.push_back(points.size());
  std::atomic<std::size_t> points_done{0};
  if (req.progress)
    opt.progress = [&](std::size_t, std::size_t) {
      req.progress(points_done.load(), points.size());
    };
  try {
    parallel_for(starts.size() - 1, opt, [&](std::size_t b) {
      std::array<std::size_t, kSweepBatch> indices{};
      const std::size_t first = starts[b];
      const std::size_t n = starts[b + 1] - first;
      for (std::size_t k = 0; k < n; ++k) indices[k] = first + k;
      BatchScratch scratch;  // a batch's own: its requests are made from this sweep's base
      compute_batch(req, &shared, std::span<const std::size_t>(indices.data(), n), scratch);
      for (std::size_t k = 0; k < n; ++k) {
        PointInputs in = point_inputs(req, first + k);
        SweepPoint& p = points[first + k];
        p.result = std::move(scratch.results[k]);
        p.v0 = in.v0;
        p.zeta = in.zeta;
        p.axes = std::move(in.axes);
      }
      points_done += n;
    });
  } catch (const ParallelError& e) {
    std::rethrow_exception(e.cause());
  }
  return points;
}

void run_sweep_points(const SweepRequest& req, SweepSink& sink, const SweepRunOptions& opt) {
  // Each worker takes a batch of points, computes it, and delivers it and takes the next in one
  // call (deliver_and_take): one lock of the sink and one journal flush a batch. Delivering point
  // by point (a chunk of 256 per parallel_for, three locks a point) made two threads contend:
  // 13,849 context switches and 21 % more CPU time than one thread on the 300 x 300 map (perf
  // stat).
  // Each worker keeps its own batch of rows (SweepRowBatch): the sink hands buffers back, so no
  // row allocates and no buffer is freed on another thread (two threads spent 1.5 % more
  // instructions than one in malloc and free of rows made on one thread and written by the other).
  std::mutex progress_mutex;
  const SweepInputColumns inputs(req);
  const SweepPointRequests shared(req);
  ParallelOptions po;
  po.threads = worker_count(sink.total(), req.threads);
  const WorkerClock::Clock::time_point origin = WorkerClock::Clock::now();
  if (opt.workers) opt.workers->assign(static_cast<std::size_t>(po.threads), {});
  try {
    parallel_for(static_cast<std::size_t>(po.threads), po, [&](std::size_t worker) {
      WorkerClock clock(opt.workers ? &(*opt.workers)[worker] : nullptr, origin);
      SweepRowBatch rows;
      BatchScratch scratch;
      const auto workers = static_cast<std::size_t>(po.threads);
      std::vector<std::size_t> batch = sink.take(opt.batch, SweepSink::WhenAhead::wait, workers);
      for (;;) {
        if (opt.stop && *opt.stop) {  // a batch taken but not run is left for --resume
          sink.request_stop();
          return;
        }
        // take() and deliver_and_take() block until work is available or none is left
        if (batch.empty()) return;
        try {
          run_sweep_batch(req, shared, inputs, batch, scratch, rows);
        } catch (...) {
          sink.request_stop();  // the other workers take no more: the sweep ends
          sink.deliver(rows);   // the points done before it stay in the journal
          throw;
        }
        const std::size_t delivered = rows.size();
        clock.add_points(delivered);
        batch = sink.deliver_and_take(rows, opt.batch, workers);
        if (opt.progress) {  // once a point, as the callers count (mpi_sweep.cc)
          std::lock_guard lock(progress_mutex);
          const std::size_t done = sink.done();
          for (std::size_t k = 0; k < delivered; ++k) opt.progress(done, sink.total());
        }
      }
    });
  } catch (const ParallelError& e) {
    std::rethrow_exception(e.cause());
  }
}

}  // namespace ivv
