// Sweeps: the one validation, rows that can be re-run exactly, failed rows without numbers,
// output independent of the thread count, and a journal that survives a torn last line.
#include "solver/sweep/sweep.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>

#include "scene/input_error.h"
#include "scene/scene_json.h"
#include "solver/plate/plate_impact.h"
#include "solver/request_options.h"

namespace ivv {
namespace {

namespace fs = std::filesystem;

SweepRequest paper_grid(std::size_t nv, std::size_t nz) {
  SweepRequest req;
  req.base.scene = load_scene("paper");
  req.velocities = log_grid(0.1, 10.0, static_cast<int>(nv));
  req.zetas = linear_grid(0.0, 1.0, static_cast<int>(nz));
  return req;
}

std::string field_of(const SweepRequest& req) {
  try {
    validate(req);
  } catch (const InputError& e) {
    return e.field();
  }
  return "";
}

// A worker's one request, made point after point in any order (zeta 0 after a dashpot, a
// velocity row revisited), is the request point_request() copies from the base: the same scene
// in every input, the same law, integrator and options. With the scene's own dashpot, and with
// scene axes (where the base is copied).
TEST(SweepGrid, AssignedPointRequestIsThePointRequest) {
  SweepRequest plain = paper_grid(3, 4);  // zetas 0, 1/3, 2/3, 1
  plain.base.options.rtol = 1e-7;
  SweepRequest own = paper_grid(3, 1);
  own.base.scene.damping = Damping::ratio(0.2);
  own.zetas.clear();
  own.scene_dashpot = true;
  SweepRequest axes = paper_grid(2, 2);
  axes.axes = {{"impactor.mass", {0.1, 0.5, 2.0}}};
  for (const SweepRequest* req : {&plain, &own, &axes}) {
    SimulationRequest made = req->base;
    const std::size_t n = point_count(*req);
    for (std::size_t k = 0; k < 2 * n; ++k) {
      const std::size_t index = (k * 7 + 3) % n;  // every point, out of order, twice
      assign_point_request(*req, index, made);
      const SimulationRequest copied = point_request(*req, index);
      EXPECT_EQ(scene_json(made.scene).dump(), scene_json(copied.scene).dump()) << index;
      EXPECT_EQ(made.law, copied.law);
      EXPECT_EQ(made.integrator, copied.integrator);
      EXPECT_EQ(made.options.rtol, copied.options.rtol);
    }
  }
}

TEST(SweepValidate, HuntCrossleyWithADashpotIsBadInputNamingZeta) {
  SweepRequest req = paper_grid(2, 2);  // zetas 0 and 1
  req.base.law = LawKind::hunt_crossley;
  EXPECT_EQ(field_of(req), "--zeta");
  req.zetas = {0.0};
  EXPECT_EQ(field_of(req), "");
}

TEST(SweepValidate, HugeGridIsRefusedBeforeAnythingIsAllocated) {
  SweepRequest req = paper_grid(1, 1);
  req.velocities.assign(1'000'000, 1.0);
  req.zetas.assign(1'000'000, 0.1);  // 1e12 points: run_sweep would need ~1e15 bytes
  EXPECT_EQ(field_of(req), "--v0");
  EXPECT_THROW(run_sweep(req), InputError);
}

// A sweep that keeps the scene's own dashpot (a [structure]): one point per v0, each run with
// the structure's c, the zeta column the derived zeta of that c.
TEST(SweepSceneDashpot, KeepsTheStructureDashpot) {
  SweepRequest req;
  req.base.scene = load_scene("paper");
  Structure plate;
  plate.density = 1580.0;
  plate.thickness = 0.02;
  plate.bending_stiffness = 4.036e9 * 0.02 * 0.02 * 0.02;
  req.base.scene.damping = Damping::from_structure(plate);
  req.velocities = {0.5, 2.0};
  req.scene_dashpot = true;
  EXPECT_EQ(field_of(req), "");
  ASSERT_EQ(point_count(req), 2u);
  const double c = structure_dashpot(plate, 7.9e9, 0.3).c;
  for (std::size_t i = 0; i < 2; ++i) {
    const SimulationRequest r = point_request(req, i);
    EXPECT_EQ(r.scene.velocity, req.velocities[i]);
    EXPECT_EQ(derive(r.scene).c, c);
  }
  const auto points = run_sweep(req);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].zeta, derive(req.base.scene).zeta);
  EXPECT_LT(points[1].result.e, points[0].result.e);  // e falls with v0 at fixed c (paper)
  req.zetas = {0.1};
  EXPECT_EQ(field_of(req), "--zeta");  // both a grid and the scene's dashpot
  req.zetas.clear();
  req.base.scene.damping = Damping::none();
  EXPECT_EQ(field_of(req), "--zeta");  // no dashpot to keep
}

TEST(SweepValidate, NonFiniteOrNegativeValuesNameTheirFlag) {
  SweepRequest req = paper_grid(2, 2);
  req.velocities[1] = -1.0;
  EXPECT_EQ(field_of(req), "--v0");
  req = paper_grid(2, 2);
  req.zetas[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(field_of(req), "--zeta");
}

// `sweep --v0 1e308` named impact.velocity, a field the user never typed.
TEST(SweepValidate, OutOfRangeGridValueNamesTheFlagNotTheSceneField) {
  SweepRequest req = paper_grid(2, 2);
  req.velocities[1] = 1e308;
  EXPECT_EQ(field_of(req), "--v0");
}

// Inputs were written with 17 digits (0.10000000000000001), so that a reader's `v0 == 0.1`
// matched nothing it had typed; the shortest form reads back as the same double all the same.
TEST(SweepRows, InputsInShortestRoundTripFormAndFailedRowsNoNumbers) {
  ImpactResult failed;
  failed.status = ImpactStatus::failed;
  failed.reason = "step size underflow, \"quoted\"";
  failed.e = 0.0;  // what a failed result holds; it must not reach the CSV
  failed.steps = 12;
  const std::string row = sweep_csv_row(0.1, 1.0 / 3.0, failed);
  EXPECT_EQ(row,
            "0.1,0.3333333333333333,,,,,,,,,,,12,integrated,none,failed,"
            "\"step size underflow, \"\"quoted\"\"\"\n");
  // the shortest form reads back to the same double
  EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0);

  ImpactResult ok;
  ok.status = ImpactStatus::separated;
  ok.e = 0.5;
  ok.integrator = "dop853";
  EXPECT_EQ(sweep_csv_row(1.0, 0.0, ok),
            "1,0,0.5,0,0,0,0,0,0,0,0,0,0,integrated,dop853,separated,\n");
}

TEST(SweepRun, ResultsAreIdenticalForAnyThreadCount) {
  SweepRequest req = paper_grid(6, 4);
  req.threads = 1;
  const auto one = run_sweep(req);
  req.threads = 3;
  const auto three = run_sweep(req);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    EXPECT_EQ(sweep_csv_row(one[i].v0, one[i].zeta, one[i].result),
              sweep_csv_row(three[i].v0, three[i].zeta, three[i].result))
        << i;
}

TEST(SweepRun, ProgressCountsPointsAndBatchesShrinkNearTheEnd) {
  SweepRequest req = paper_grid(20, 10);  // 200 points
  req.threads = 2;
  std::vector<std::size_t> done;
  std::mutex mutex;  // parallel_for serialises the calls; the vector is guarded all the same
  req.progress = [&](std::size_t d, std::size_t total) {
    std::lock_guard lock(mutex);
    EXPECT_EQ(total, 200u);
    done.push_back(d);
  };
  run_sweep(req);
  ASSERT_FALSE(done.empty());
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_EQ(done.back(), 200u);
  // 200 points on two workers: batches of 50, 37, 28, 21, ... (guided_batch_size), not one of
  // 128 and one of 72, which would leave a worker idle for most of the second
  std::size_t batches = 0;
  for (std::size_t left = 200; left > 0; ++batches) left -= guided_batch_size(left, 2, 128);
  EXPECT_EQ(done.size(), batches);
  EXPECT_GT(batches, 8u);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ivv_sweep_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string run_to_csv(const SweepRequest& req, const fs::path& csv, bool resume) {
  SweepSink sink(req, {csv, resume, "test"});
  run_sweep_points(req, sink, {});
  EXPECT_TRUE(sink.finish({}));
  EXPECT_FALSE(fs::exists(sink.journal_path()));
  return slurp(csv);
}

TEST(SweepSink, StreamedCsvEqualsTheInMemoryRows) {
  SweepRequest req = paper_grid(5, 3);
  std::string expected = sweep_csv_header();
  for (const auto& p : run_sweep(req)) expected += sweep_csv_row(p.v0, p.zeta, p.result);
  EXPECT_EQ(run_to_csv(req, scratch("stream.csv"), false), expected);
}

// Each worker of a two-thread sweep says how many points it computed (together, the grid) and
// when it began and ended; on a core and waiting for one fit inside its span (1 ms: the kernel's
// counts and the steady clock are read microseconds apart).
TEST(SweepSink, EachWorkerStatesItsPointsAndWhereItsTimeWent) {
  SweepRequest req = paper_grid(8, 5);
  req.threads = 2;
  SweepSink sink(req, {scratch("workers.csv"), false, "test"});
  std::vector<SweepWorkerTime> workers;
  SweepRunOptions opt;
  opt.workers = &workers;
  opt.batch = 4;
  run_sweep_points(req, sink, opt);
  EXPECT_TRUE(sink.finish({}));
  ASSERT_EQ(workers.size(), 2u);
  std::size_t points = 0;
  for (const SweepWorkerTime& w : workers) {
    points += w.points;
    EXPECT_LE(0.0, w.start);
    EXPECT_LE(w.start, w.end);
    if (std::isnan(w.running)) continue;  // no scheduler statistics from this kernel
    EXPECT_GE(w.running, 0.0);
    EXPECT_GE(w.waiting, 0.0);
    // The kernel brings a running thread's counts up to date at its scheduler ticks (4 ms at
    // HZ = 250), so each of the two readings may lag by one: 1 ms of slack failed 1 run in 40
    // on a loaded machine (2.6 ms counted in a 2.3 ms interval). A count that was not the
    // worker's own interval (the thread's total) would exceed it by far more.
    constexpr double kTwoSchedulerTicks = 2 * 4e-3;  // [s]
    EXPECT_LE(w.running + w.waiting, w.end - w.start + kTwoSchedulerTicks);
  }
  EXPECT_EQ(points, sink.total());
}

// Shared among two workers, batches shrink near the end of the grid to a quarter of what is left
// (at least one point), so neither waits long for the other's last batch; alone, a worker takes
// full batches to the end. Every point is handed out once, in order, either way.
TEST(SweepSink, BatchesShrinkNearTheEndWhenWorkersShare) {
  const SweepRequest req = paper_grid(20, 10);  // 200 points
  auto sizes = [&](std::size_t workers) {
    const fs::path csv = scratch("shares" + std::to_string(workers) + ".csv");
    SweepSink sink(req, {csv, false, "test"});
    std::vector<std::size_t> out, handed;
    for (auto chunk = sink.take(32, SweepSink::WhenAhead::return_empty, workers); !chunk.empty();
         chunk = sink.take(32, SweepSink::WhenAhead::return_empty, workers)) {
      const std::size_t left = sink.total() - handed.size();
      if (workers > 1) {
        EXPECT_LE(chunk.size(), std::max<std::size_t>(1, left / (2 * workers)));
      }
      out.push_back(chunk.size());
      handed.insert(handed.end(), chunk.begin(), chunk.end());
    }
    for (std::size_t i = 0; i < handed.size(); ++i) EXPECT_EQ(handed[i], i);
    EXPECT_EQ(handed.size(), sink.total());
    EXPECT_FALSE(sink.finish({}));  // nothing delivered: journal and partial stay, removed here
    fs::remove(sink.journal_path());
    fs::remove(csv.string() + ".partial");
    return out;
  };
  EXPECT_EQ(sizes(1), (std::vector<std::size_t>{32, 32, 32, 32, 32, 32, 8}));
  const std::vector<std::size_t> shared = sizes(2);
  EXPECT_EQ(std::vector<std::size_t>(shared.begin(), shared.begin() + 3),
            (std::vector<std::size_t>{32, 32, 32}));  // 200, 168, 136 left: a quarter is >= 32
  EXPECT_EQ(shared[3], 26u);                          // 104 left
  EXPECT_EQ(shared.back(), 1u);
}

TEST(SweepSink, ResumeReadsBackFinishedPointsAndToleratesATornLine) {
  SweepRequest req = paper_grid(5, 3);
  req.threads = 2;
  const std::string expected = run_to_csv(req, scratch("whole.csv"), false);

  // An interrupted run: points 0-5 and 9 finished (journal), then a torn line (SIGKILL in the
  // middle of a write).
  const fs::path csv = scratch("torn.csv");
  {
    SweepSink sink(req, {csv, false, "test"});
    for (std::size_t i : {0, 1, 2, 3, 4, 5, 9}) sink.deliver(i, run_sweep_point(req, i));
    EXPECT_FALSE(sink.finish({}));
  }
  { std::ofstream(fs::path(csv.string() + ".journal"), std::ios::app) << "11 0.1,0.5,0.3"; }

  // Without --resume an existing journal is refused; another sweep's journal too.
  EXPECT_THROW(SweepSink(req, {csv, false, "test"}), InputError);
  EXPECT_THROW(SweepSink(req, {csv, true, "another sweep"}), InputError);

  SweepSink sink(req, {csv, true, "test"});
  EXPECT_EQ(sink.resumed(), 7u);
  std::vector<std::size_t> computed;
  for (auto chunk = sink.take(100, SweepSink::WhenAhead::wait); !chunk.empty();
       chunk = sink.take(100, SweepSink::WhenAhead::wait))
    for (std::size_t i : chunk) {
      computed.push_back(i);
      sink.deliver(i, run_sweep_point(req, i));
    }
  EXPECT_EQ(computed, (std::vector<std::size_t>{6, 7, 8, 10, 11, 12, 13, 14}));
  ASSERT_TRUE(sink.finish({}));
  EXPECT_EQ(slurp(csv), expected);
}

// Only the "v0,zeta," prefix of a journal row was checked, so a row whose e
// or status was edited went into the final CSV, and a row cut short became a short CSV row;
// the partial CSV was trusted the same way. Each journal row now carries a checksum: a row that
// fails it is computed again, and the partial CSV is rebuilt from the journal.
TEST(SweepSink, DamagedJournalRowIsRecomputedNotTrusted) {
  SweepRequest req = paper_grid(5, 3);
  const std::string expected = run_to_csv(req, scratch("whole-damaged.csv"), false);
  const fs::path csv = scratch("damaged.csv");
  {
    SweepSink sink(req, {csv, false, "test"});
    for (std::size_t i = 0; i < 10; ++i) sink.deliver(i, run_sweep_point(req, i));
    EXPECT_FALSE(sink.finish({}));
  }
  const fs::path journal = csv.string() + ".journal";
  const fs::path partial = csv.string() + ".partial";
  std::string text = slurp(journal);
  // line 2 (point 1): one digit of a result changed; line 4 (point 3): the status changed;
  // line 6 (point 5): cut short, as a truncated line with its newline
  std::vector<std::string> lines;
  for (std::size_t at = 0, next; at < text.size(); at = next + 1) {
    next = text.find('\n', at);
    lines.push_back(text.substr(at, next - at));
  }
  ASSERT_GE(lines.size(), 11u);
  std::string& edited = lines[2];
  const std::size_t digit =
      edited.find_first_of("123456789", edited.find(',', edited.find(',') + 1));
  edited[digit] = edited[digit] == '9' ? '8' : '9';
  const std::size_t status = lines[4].find("separated");
  ASSERT_NE(status, std::string::npos);
  lines[4].replace(status, 9, "captured");
  lines[6].resize(lines[6].size() / 2);
  std::string damaged;
  for (const std::string& l : lines) damaged += l + '\n';
  { std::ofstream(journal, std::ios::binary | std::ios::trunc) << damaged; }
  // and the partial CSV's first row edited: the journal is the record, not the partial
  std::string csv_text = slurp(partial);
  csv_text[csv_text.find('\n') + 1] = '7';
  { std::ofstream(partial, std::ios::binary | std::ios::trunc) << csv_text; }

  SweepSink sink(req, {csv, true, "test"});
  EXPECT_EQ(sink.damaged_rows(), 3u);
  EXPECT_EQ(sink.resumed(), 7u);
  std::vector<std::size_t> computed;
  for (auto chunk = sink.take(100, SweepSink::WhenAhead::wait); !chunk.empty();
       chunk = sink.take(100, SweepSink::WhenAhead::wait))
    for (std::size_t i : chunk) {
      computed.push_back(i);
      sink.deliver(i, run_sweep_point(req, i));
    }
  EXPECT_EQ(computed, (std::vector<std::size_t>{1, 3, 5, 10, 11, 12, 13, 14}));
  ASSERT_TRUE(sink.finish({}));
  EXPECT_EQ(slurp(csv), expected);
}

// The sidecar was written before the CSV was renamed into place, and a run
// killed while copying left its temporary for ever. The pair is committed sidecar last, and a
// dead process's temporary is removed by the next run on the same output.
TEST(SweepSink, CsvAndSidecarCommittedAsAPairAndDeadTemporariesRemoved) {
  SweepRequest req = paper_grid(2, 1);
  const fs::path csv = scratch("pair.csv");
  const fs::path json = scratch("pair.json");
  pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0);  // reaped: its PID names no process now
  const fs::path stale = scratch(".pair.csv.tmp" + std::to_string(child) + "-42");
  const fs::path live = scratch(".pair.csv.tmp" + std::to_string(getpid() == 1 ? 2 : 1) + "-7");
  { std::ofstream(stale) << "left by a killed run"; }
  { std::ofstream(live) << "a running process's"; }
  SweepOutputOptions opt{csv, false, "test"};
  opt.sidecar = json;
  SweepSink sink(req, opt);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));  // PID 1 runs: its temporary is not ours to remove
  fs::remove(live);
  run_sweep_points(req, sink, {});
  ASSERT_TRUE(sink.finish_with_sidecar([](const SweepCounts& counts, std::ostream& out) {
    out << "{\"separated\": " << counts.separated << "}\n";
  }));
  EXPECT_EQ(slurp(json), "{\"separated\": 2}\n");
  const std::string rows = slurp(csv);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 3);  // header and two points
  for (const auto& entry : fs::directory_iterator(csv.parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".pair."), std::string::npos) << entry.path();
}

TEST(SweepSink, WindowBoundsHowFarAheadWorkIsHandedOut) {
  SweepRequest req = paper_grid(10, 1);
  SweepOutputOptions opt{scratch("window.csv"), false, "test"};
  opt.window = 4;
  SweepSink sink(req, opt);
  EXPECT_EQ(sink.take(100, SweepSink::WhenAhead::return_empty),
            (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(sink.take(100, SweepSink::WhenAhead::return_empty)
                  .empty());  // point 0 unfinished: nothing further
  EXPECT_FALSE(sink.exhausted());
  sink.deliver(0, run_sweep_point(req, 0));
  EXPECT_EQ(sink.take(100, SweepSink::WhenAhead::return_empty), (std::vector<std::size_t>{4}));
}

// Under --model auto and --integrator auto what runs differs from point to point; each row
// says what produced it: the undamped column is the exact closed form, the damped one dop853.
TEST(SweepCsv, EachRowSaysWhatProducedIt) {
  SweepRequest req = paper_grid(2, 2);  // zetas 0 and 1
  req.zetas = {0.0, 0.1};
  req.base.model = ModelKind::automatic;
  req.base.auto_integrator = true;
  for (const SweepPoint& p : run_sweep(req)) {
    ASSERT_TRUE(p.result.ok()) << p.result.reason;
    const std::string row = sweep_csv_row(p.v0, p.zeta, p.result);
    if (p.zeta == 0.0) {
      EXPECT_EQ(p.result.route, "closed-form-elastoplastic");
      EXPECT_EQ(p.result.integrator, "none");
      EXPECT_NE(row.find(",closed-form-elastoplastic,none,"), std::string::npos) << row;
    } else {
      EXPECT_EQ(p.result.route, "integrated");
      EXPECT_EQ(p.result.integrator, "dop853");
      EXPECT_NE(row.find(",integrated,dop853,"), std::string::npos) << row;
    }
  }
  EXPECT_NE(sweep_csv_header().find(",steps,route,integrator,status,"), std::string::npos);
}

// ---- grids ---------------------------------------------------------------------------------

// The naive lo + i (hi - lo)/(n - 1) gave 0.30000000000000004 for 0.1:1:10's third point: a
// reader's `v0 == 0.3` found nothing. Each point is now the double of the decimal typed.
TEST(LinearGrid, HoldsTheDecimalsTyped) {
  EXPECT_EQ(linear_grid(0.1, 1.0, 10),
            (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}));
  EXPECT_EQ(linear_grid(0.0, 1.0, 5), (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(linear_grid(-0.3, 0.3, 7), (std::vector<double>{-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3}));
  EXPECT_EQ(linear_grid(0.02, 0.98, 97)[35], 0.37);
  EXPECT_EQ(linear_grid(1e-3, 1e-2, 10)[6], 0.007);
  EXPECT_EQ(linear_grid(100.0, 1000.0, 4), (std::vector<double>{100.0, 400.0, 700.0, 1000.0}));
  EXPECT_EQ(linear_grid(1.5e8, 2.5e8, 3), (std::vector<double>{1.5e8, 2e8, 2.5e8}));
  EXPECT_EQ(linear_grid(0.7, 0.7, 3), (std::vector<double>{0.7, 0.7, 0.7}));
  EXPECT_EQ(linear_grid(0.7, 2.0, 1), std::vector<double>{0.7});
}

// Where the step has no finite decimal (thirds), or the endpoints are too many decades apart to
// share a 64-bit integer scale, the naive formula stays, with both endpoints exact.
TEST(LinearGrid, StepsWithoutAFiniteDecimalKeepTheFormulaAndExactEnds) {
  const std::vector<double> thirds = linear_grid(0.0, 1.0, 4);
  EXPECT_EQ(thirds, (std::vector<double>{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0}));
  const std::vector<double> wide = linear_grid(1e-300, 1.0, 3);
  EXPECT_EQ(wide.front(), 1e-300);
  EXPECT_EQ(wide[1], 1e-300 + (1.0 - 1e-300) * 1 / 2);
  EXPECT_EQ(wide.back(), 1.0);
  // a span beyond the largest double: the points stay finite
  for (double x : linear_grid(-1.5e308, 1.7e308, 4)) EXPECT_TRUE(std::isfinite(x)) << x;
  const std::vector<double> odd = linear_grid(0.05, 20.0, 100);  // step 0.2015...
  EXPECT_EQ(odd.front(), 0.05);
  EXPECT_EQ(odd.back(), 20.0);
}

// Typed grids LO:HI:N with decimal steps (lo = a 10^-e, step = b 10^-e, 2 to 200 points): each
// point is exactly the double of its decimal (a + i b) 10^-e, and differs from the naive
// lo + i (hi - lo)/(n - 1) by at most 4 ulps of the larger endpoint (the naive value carries at
// most four roundings of half an ulp, the decimal point one: together under 3 ulps).
TEST(LinearGrid, DecimalStepsGiveTheDecimalOfEveryPoint) {
  std::mt19937 random(20261125);  // a fixed seed: the same 2,000 grids every run
  for (int k = 0; k < 2000; ++k) {
    const long a = static_cast<long>(random() % 2000000) - (k % 3 == 0 ? 1000000 : 0);
    const long b = 1 + static_cast<long>(random() % 100000);
    const int n = 2 + static_cast<int>(random() % 199);
    const std::string e = "e-" + std::to_string(random() % 8);
    const double lo = std::stod(std::to_string(a) + e);
    const double hi = std::stod(std::to_string(a + b * (n - 1)) + e);
    const std::vector<double> g = linear_grid(lo, hi, n);
    ASSERT_EQ(g.size(), static_cast<std::size_t>(n));
    const double big = std::max(std::abs(lo), std::abs(hi));
    const double ulp = std::nextafter(big, INFINITY) - big;
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(g[i], std::stod(std::to_string(a + b * i) + e)) << lo << ":" << hi << ":" << n;
      EXPECT_LE(std::abs(g[i] - (lo + (hi - lo) * i / (n - 1))), 4 * ulp) << lo << ":" << hi;
    }
  }
}

// exp(log(lo)) may differ from lo by an ulp: the first point of a log grid is lo itself.
TEST(LogGrid, EndpointsAreExactlyThoseTyped) {
  for (double lo : {0.05, 0.1, 0.3, 1e-3, 7.7})
    for (int n : {2, 3, 100}) {
      const std::vector<double> g = log_grid(lo, 20.0, n);
      EXPECT_EQ(g.front(), lo) << lo << " " << n;
      EXPECT_EQ(g.back(), 20.0) << lo << " " << n;
    }
}

// ---- scene axes ----------------------------------------------------------------------------

SweepRequest paper_grid_with_axes() {
  SweepRequest req = paper_grid(2, 2);  // v0 0.1, 10; zeta 0, 1
  req.axes = {{"impactor.mass", {0.1, 0.5, 2.0}}, {"target.yield_strength", {1e8, 3e8}}};
  return req;
}

// Every derived parameter of `a` and `b` the same double, bit for bit (NaN for NaN where absent).
bool same_bits(const DerivedParameters& a, const DerivedParameters& b) {
  for (auto field :
       {&DerivedParameters::effective_radius, &DerivedParameters::effective_mass,
        &DerivedParameters::E_star, &DerivedParameters::K_h, &DerivedParameters::z_y,
        &DerivedParameters::K_y, &DerivedParameters::omega0, &DerivedParameters::zeta,
        &DerivedParameters::c, &DerivedParameters::v_yield, &DerivedParameters::zener_lambda})
    if (std::bit_cast<std::uint64_t>(a.*field) != std::bit_cast<std::uint64_t>(b.*field))
      return false;
  return true;
}

// The derived parameters a point gets from what the grid's points share are derive() of the
// point's own scene, bit for bit, at every point of a v0 x zeta grid (zeta 0 included: no
// dashpot) whose base scene carries a dashpot of its own (replaced at each point); grids that
// change the scene point by point (scene axes, the scene's own dashpot) derive each point's scene.
TEST(SweepGrid, SharedDerivationGivesEachPointsDeriveToTheBit) {
  SweepRequest grid = paper_grid(9, 7);
  grid.base.scene.damping = Damping::coefficient(500.0);
  grid.base.scene.velocity = 42.0;
  SweepRequest own = paper_grid(4, 1);
  own.base.scene.damping = Damping::zener(0.3);
  own.zetas.clear();
  own.scene_dashpot = true;
  const SweepRequest axes = paper_grid_with_axes();
  EXPECT_TRUE(SweepPointRequests(grid).shares_derivation());
  EXPECT_FALSE(SweepPointRequests(own).shares_derivation());
  EXPECT_FALSE(SweepPointRequests(axes).shares_derivation());
  for (const SweepRequest* req : std::initializer_list<const SweepRequest*>{&grid, &own, &axes}) {
    const SweepPointRequests shared(*req);
    SimulationRequest point = req->base;
    for (std::size_t i = 0; i < point_count(*req); ++i) {
      assign_point_request(*req, i, point);
      const DerivedParameters want = derive(point_request(*req, i).scene);
      EXPECT_TRUE(same_bits(shared.derived(i, point), want)) << i;
      EXPECT_TRUE(same_bits(shared.validated(i, point).derived(), want)) << i;
    }
  }
}

TEST(SweepAxes, PointsAreRowMajorWithTheLastAxisFastest) {
  const SweepRequest req = paper_grid_with_axes();
  EXPECT_EQ(field_of(req), "");
  ASSERT_EQ(point_count(req), 2u * 2u * 3u * 2u);
  for (std::size_t iv = 0, i = 0; iv < 2; ++iv)
    for (std::size_t iz = 0; iz < 2; ++iz)
      for (std::size_t im = 0; im < 3; ++im)
        for (std::size_t iy = 0; iy < 2; ++iy, ++i) {
          const SimulationRequest r = point_request(req, i);
          EXPECT_EQ(r.scene.velocity, req.velocities[iv]) << i;
          EXPECT_EQ(derive(r.scene).zeta, req.zetas[iz]) << i;
          EXPECT_EQ(r.scene.mass, req.axes[0].values[im]) << i;
          EXPECT_EQ(r.scene.yield_strength, req.axes[1].values[iy]) << i;
          const PointInputs in = point_inputs(req, i);
          EXPECT_EQ(in.axes, (std::vector<double>{req.axes[0].values[im], req.axes[1].values[iy]}));
        }
}

TEST(SweepAxes, TheCsvHasAColumnPerAxisInItsUnit) {
  const SweepRequest req = paper_grid_with_axes();
  EXPECT_EQ(sweep_csv_header(req.axes).rfind("v0,zeta,impactor.mass,target.yield_strength,e,", 0),
            0u);
  const std::vector<SweepColumn> columns = sweep_csv_columns(req.axes);
  ASSERT_GT(columns.size(), 4u);
  EXPECT_EQ(columns[2].unit, "kg");
  EXPECT_EQ(columns[3].unit, "Pa");
  for (const SweepColumn& c : columns)
    if (c.name == "F_max") {
      EXPECT_EQ(c.unit, "N");
    }
  // run in memory: each row carries its axis values; the heavier impactor strikes harder
  SweepRequest small = req;
  small.velocities = {1.0};
  small.zetas = {0.0};
  const std::vector<SweepPoint> points = run_sweep(small);
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[4].axes, (std::vector<double>{2.0, 1e8}));
  EXPECT_GT(points[4].result.F_max, points[0].result.F_max);
  EXPECT_EQ(sweep_csv_row({1.0, 0.0, points[4].axes}, points[4].result).rfind("1,0,2,1e+08,", 0),
            0u);
}

TEST(SweepAxes, BadAxesNameTheirFlag) {
  SweepRequest req = paper_grid_with_axes();
  req.axes[0].key = "impactor.mas";
  EXPECT_EQ(field_of(req), "--set impactor.mas");
  req = paper_grid_with_axes();
  req.axes[1].values[1] = -1.0;
  EXPECT_EQ(field_of(req), "--set target.yield_strength");
  req = paper_grid_with_axes();
  req.axes[0].values[0] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(field_of(req), "--set impactor.mass");
  req = paper_grid_with_axes();
  req.axes.push_back(req.axes[0]);
  EXPECT_EQ(field_of(req), "--set impactor.mass");  // given twice
  req = paper_grid_with_axes();
  req.axes.push_back({"structure.thickness", {0.002}});  // the paper has no [structure]
  EXPECT_EQ(field_of(req), "--set structure.thickness");
}

// v0 = 1e-100 m/s and m = 1e-100 kg are each a valid impact with the other at its first value,
// but together the spring's energy scale K_h (v0/omega0)^{5/2} underflows double: a corner of
// the grid no single-value check sees, refused before anything runs.
TEST(SweepAxes, AnInvalidCornerOfTheGridIsBadInput) {
  SweepRequest req = paper_grid(1, 1);
  req.velocities = {1.0, 1e-100};
  req.axes = {{"impactor.mass", {0.5, 1e-100}}};
  SweepRequest one_at_a_time = req;
  one_at_a_time.velocities = {1e-100};
  one_at_a_time.axes[0].values = {0.5};
  EXPECT_EQ(field_of(one_at_a_time), "");
  one_at_a_time.velocities = {1.0};
  one_at_a_time.axes[0].values = {1e-100};
  EXPECT_EQ(field_of(one_at_a_time), "");
  try {
    validate(req);
    ADD_FAILURE() << "the corner v0 = 1e-100 m/s, m = 1e-100 kg passed";
  } catch (const InputError& e) {
    EXPECT_TRUE(e.field() == "--v0" || e.field() == "--set impactor.mass") << e.what();
    EXPECT_NE(std::string(e.what()).find("corner"), std::string::npos) << e.what();
  }
}

// A journal names its grid: --resume with the same axes reads it back, with another value of an
// axis refuses it (the rows would describe other impacts).
TEST(SweepAxes, ResumeAcceptsTheSameAxesAndRefusesChangedOnes) {
  SweepRequest req = paper_grid_with_axes();
  req.velocities = {1.0};
  const fs::path csv = scratch("axes.csv");
  {
    SweepSink sink(req, {csv, false, "test"});
    for (std::size_t i : {0, 1, 2}) sink.deliver(i, run_sweep_point(req, i));
    EXPECT_FALSE(sink.finish({}));
  }
  SweepRequest changed = req;
  changed.axes[0].values[1] = 0.6;
  EXPECT_THROW(SweepSink(changed, {csv, true, "test"}), InputError);
  changed = req;
  std::swap(changed.axes[0], changed.axes[1]);  // the same values, another order of rows
  EXPECT_THROW(SweepSink(changed, {csv, true, "test"}), InputError);
  SweepSink sink(req, {csv, true, "test"});
  EXPECT_EQ(sink.resumed(), 3u);
  EXPECT_EQ(sink.damaged_rows(), 0u);
  run_sweep_points(req, sink, {});
  ASSERT_TRUE(sink.finish({}));
  std::string expected = sweep_csv_header(req.axes);
  for (const SweepPoint& p : run_sweep(req))
    expected += sweep_csv_row({p.v0, p.zeta, p.axes}, p.result);
  EXPECT_EQ(slurp(csv), expected);
}

// ---- a stream (standard output) ------------------------------------------------------------

TEST(SweepStream, RowsGoToTheStreamInGridOrderWithoutJournal) {
  SweepRequest req = paper_grid(5, 3);
  req.threads = 2;
  const std::string expected = run_to_csv(req, scratch("for-stream.csv"), false);
  std::FILE* stream = std::tmpfile();
  ASSERT_NE(stream, nullptr);
  SweepOutputOptions opt{scratch("stream-named.csv"), false, "test"};
  opt.stream = stream;
  SweepSink sink(req, opt);
  run_sweep_points(req, sink, {});
  EXPECT_TRUE(sink.finish({}));
  EXPECT_EQ(sink.output_error(), 0);
  EXPECT_EQ(sink.written(), sink.total());
  EXPECT_FALSE(fs::exists(sink.journal_path()));
  EXPECT_FALSE(fs::exists(scratch("stream-named.csv")));
  std::rewind(stream);
  std::string got;
  for (int c; (c = std::fgetc(stream)) != EOF;) got += static_cast<char>(c);
  std::fclose(stream);
  EXPECT_EQ(got, expected);
  opt.resume = true;  // a stream keeps no journal to resume from
  EXPECT_THROW(SweepSink(req, opt), InputError);
}

// `ivv sweep --out - | head`: the reader goes away; the sweep stops, quietly, without a throw.
TEST(SweepStream, AReaderThatStopsReadingStopsTheSweep) {
  SweepRequest req = paper_grid(50, 40);
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  close(fds[0]);  // nobody reads
  std::FILE* stream = fdopen(fds[1], "w");
  ASSERT_NE(stream, nullptr);
  void (*previous)(int) = std::signal(SIGPIPE, SIG_IGN);
  SweepOutputOptions opt{"standard output", false, "test"};
  opt.stream = stream;
  {
    SweepSink sink(req, opt);
    EXPECT_NO_THROW(run_sweep_points(req, sink, {}));
    EXPECT_EQ(sink.output_error(), EPIPE);
    EXPECT_FALSE(sink.finish({}));
    EXPECT_LT(sink.done(), sink.total());  // stopped, not run to the end
    EXPECT_LE(sink.written(), sink.done());
  }
  std::signal(SIGPIPE, previous);
  std::fclose(stream);
}

// ---- rows made once, written in order -------------------------------------------------------

// The input columns formatted once a sweep are the bytes of the inputs formatted point by point:
// on a v0 x zeta grid, with scene axes (the last fastest), and with the scene's dashpot (zeta
// derived at each point).
TEST(SweepCsv, InputColumnsAreThoseOfEachPointFormattedAlone) {
  SweepRequest dashpot;
  dashpot.base.scene = load_scene("paper");
  dashpot.base.scene.damping = Damping::coefficient(40.0);
  dashpot.velocities = {0.5, 2.0, 3.1};
  dashpot.scene_dashpot = true;
  for (const SweepRequest& req : {paper_grid(7, 5), paper_grid_with_axes(), dashpot}) {
    const SweepInputColumns columns(req);
    for (std::size_t i = 0; i < point_count(req); ++i) {
      std::string row = "x", expected = "x";  // appended after what the row holds already
      columns.append(row, i);
      expected += sweep_csv_inputs(point_inputs(req, i));
      EXPECT_EQ(row, expected) << i;
    }
  }
}

// The facts the counts take from a row (route, integrator, status) are where the row has them,
// for a separated, a captured and a failed row (whose result columns are empty).
TEST(SweepCsv, RowFactsPointAtTheRowsOwnColumns) {
  ImpactResult separated = simulate(point_request(paper_grid(2, 2), 0));
  ASSERT_TRUE(separated.separated()) << separated.reason;
  ImpactResult captured = separated;
  captured.status = ImpactStatus::captured;
  ImpactResult failed;
  failed.route = "closed-form-elastoplastic";
  failed.reason = "a \"quoted\" reason";
  for (const ImpactResult& r : {separated, captured, failed}) {
    std::string row = "0.1,0,";
    const SweepRowFacts f = append_sweep_csv_results(row, 0, r);
    EXPECT_EQ(row, sweep_csv_row(0.1, 0.0, r));
    EXPECT_EQ(row.substr(f.route, f.route_size), r.route);
    EXPECT_EQ(row.substr(f.integrator, f.integrator_size), r.integrator);
    EXPECT_EQ(row[f.route - 1], ',');
    EXPECT_EQ(row.substr(f.integrator + f.integrator_size, to_string(r.status).size() + 2),
              "," + std::string(to_string(r.status)) + ",");
    EXPECT_EQ(f.status, r.status);
  }
}

// The journal's row checksum changes with any one byte of a row changed (a digit edited, a
// status rewritten a byte at a time) and with the row cut short at any length.
TEST(SweepSink, JournalChecksumSeesEveryOneByteEditAndEveryCut) {
  const std::string row = run_sweep_point(paper_grid(3, 3), 4);
  const std::uint64_t sum = sweep_journal_checksum(row);
  for (std::size_t k = 0; k < row.size(); ++k)
    for (char c : {'0', '9', ',', '\n', '\0'}) {
      if (row[k] == c) continue;
      std::string edited = row;
      edited[k] = c;
      EXPECT_NE(sweep_journal_checksum(edited), sum) << k << " " << int(c);
    }
  for (std::size_t n = 0; n < row.size(); ++n)
    EXPECT_NE(sweep_journal_checksum(std::string_view(row).substr(0, n)), sum) << n;
}

// Batches delivered out of order (a worker ahead of another), one of them unsorted, and a point
// delivered twice: the CSV holds every row once, in grid order, the first delivery of a point
// kept, and the counts count each point once. The delivered batch comes back empty.
TEST(SweepSink, BatchesOutOfOrderGiveTheRowsInGridOrderOnce) {
  const SweepRequest req = paper_grid(5, 3);
  const std::string expected = run_to_csv(req, scratch("batches-whole.csv"), false);
  std::vector<std::string> rows;
  for (std::size_t i = 0; i < point_count(req); ++i) rows.push_back(run_sweep_point(req, i));
  const fs::path csv = scratch("batches.csv");
  SweepSink sink(req, {csv, false, "test"});
  ASSERT_EQ(sink.take(100, SweepSink::WhenAhead::return_empty).size(), 15u);
  SweepRowBatch batch;
  auto deliver = [&](std::vector<std::size_t> indices) {
    for (std::size_t i : indices) batch.add(i, rows[i]);
    sink.deliver(batch);
    EXPECT_TRUE(batch.empty());
  };
  deliver({10, 11, 12, 13, 14});
  deliver({9, 5, 7, 6, 8});  // unsorted
  EXPECT_EQ(sink.written(), 0u);
  batch.add(7, "a second row of point 7 is dropped\n");
  deliver({3, 4});
  batch.add(1, rows[1]);
  batch.add(1, "a second row of point 1 in the same batch is dropped\n");
  deliver({0, 2});
  EXPECT_EQ(sink.written(), 15u);
  EXPECT_EQ(sink.done(), 15u);
  ASSERT_TRUE(sink.finish({}));
  EXPECT_EQ(slurp(csv), expected);
  EXPECT_EQ(sink.counts().separated + sink.counts().captured + sink.counts().failed, 15u);
}

// A sweep of the drop-weight coupon over v0 and the laminate's thickness: each row is the full
// plate's run at that point (the same numbers as simulate_plate_impact), no zeta.
SweepRequest coupon_grid() {
  RequestOptions o;
  o.scene = "drop-weight-coupon";
  SweepRequest req;
  req.base = to_sweep_base(o);
  req.velocities = {1.0, 2.0};
  req.scene_dashpot = true;
  req.axes = {{"structure.thickness", {0.003, 0.004}}};
  req.threads = 1;
  return req;
}

TEST(SweepFinitePlate, EachRowIsThePlatesRunAtThatPoint) {
  const SweepRequest req = coupon_grid();
  const std::vector<SweepPoint> points = run_sweep(req);
  ASSERT_EQ(points.size(), 4u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SimulationRequest r = point_request(req, i);
    PlateImpactOptions opt;  // as ivv simulate: the cut-off chosen for its truncation tolerance
    opt.truncation_tol = kPlateTruncationTol;
    opt.cutoff = kPlateFirstCutoff;
    const PlateImpactResult plate = simulate_plate_impact(r.scene, r.law, r.parameters, opt);
    EXPECT_LE(plate.truncation_error, kPlateTruncationTol) << i;
    ASSERT_TRUE(plate.ok) << plate.reason;
    EXPECT_EQ(points[i].result.e, plate.e) << i;  // same run, same bits
    EXPECT_EQ(points[i].result.F_max, plate.F_max) << i;
    EXPECT_EQ(points[i].result.route, "finite-plate");
    EXPECT_TRUE(std::isnan(points[i].zeta)) << "a finite plate has no dashpot, so no zeta";
  }
  EXPECT_GT(points[3].result.e, 0.9);  // 2 m/s on 4 mm: the coupon throws the striker back
}

TEST(SweepFinitePlate, DashpotAndIntegratorFlagsAreBadInput) {
  SweepRequest req = coupon_grid();
  req.scene_dashpot = false;
  req.zetas = {0.1};
  EXPECT_EQ(field_of(req), "--zeta");
  RequestOptions o;
  o.scene = "drop-weight-coupon";
  o.integrator = "rodas4";
  EXPECT_THROW(to_sweep_base(o), InputError);
  o.integrator = "auto";
  o.expression.force = "K_h*z^1.5";
  EXPECT_NO_THROW(to_sweep_base(o));           // an expression law runs on the plate
  o.expression.force = "K_h*z^1.5 + 10*zdot";  // a rate-dependent one does not: named
  try {
    to_sweep_base(o);
    ADD_FAILURE() << "a rate-dependent expression law accepted on a finite plate";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--force");
  }
}

}  // namespace
}  // namespace ivv
