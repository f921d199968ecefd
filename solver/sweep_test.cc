// Sweeps: the one validation, rows that can be re-run exactly, failed rows without numbers,
// output independent of the thread count, and a journal that survives a torn last line.
#include "solver/sweep.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/input_error.h"

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
  for (auto chunk = sink.take(100, true); !chunk.empty(); chunk = sink.take(100, true))
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
  for (auto chunk = sink.take(100, true); !chunk.empty(); chunk = sink.take(100, true))
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
  EXPECT_EQ(sink.take(100, false), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(sink.take(100, false).empty());  // point 0 unfinished: nothing further
  EXPECT_FALSE(sink.exhausted());
  sink.deliver(0, run_sweep_point(req, 0));
  EXPECT_EQ(sink.take(100, false), (std::vector<std::size_t>{4}));
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

}  // namespace
}  // namespace ivv
