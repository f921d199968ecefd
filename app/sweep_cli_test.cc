// `ivv sweep` as a user running a large study meets it: killed (SIGKILL, SIGTERM) and resumed,
// run across 2 MPI ranks, bad input refused before any file appears. Every comparison is byte
// for byte against an uninterrupted single-process run.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ivv_sweep_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t lines(const fs::path& p) {
  const std::string s = slurp(p);
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// Runs a shell command; returns its exit code (stderr to `err`).
int shell(const std::string& cmd, const fs::path& err) {
  const int status = std::system((cmd + " 2>" + err.string()).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A grid that takes about a second on one thread, so that a kill lands in the middle of it: the
// implicit rodas4 takes about 0.17 ms a point of the paper scene. With the default integrator
// (dop853 in SIMD lanes) the grid took 0.04 s, and a kill meant for its middle, after the
// journal's 1,000th row, sometimes came after its end (a test of this file failed so under
// ctest -j2).
const std::string kGrid =
    "sweep --scene paper --v0 0.05:20:100 --log --zeta 0:2:60 --integrator rodas4 -q";
constexpr std::size_t kPoints = 100 * 60;

std::string sweep_cmd(const fs::path& csv, const std::string& extra = "") {
  return std::string(IVV_BINARY) + " " + kGrid + " --out " + csv.string() + " " + extra;
}

// The reference: the same grid, uninterrupted, on 2 threads.
const std::string& reference_csv() {
  static const std::string csv = [] {
    const fs::path p = scratch("reference.csv");
    fs::remove(fs::path(p.string() + ".journal"));
    shell(sweep_cmd(p, "--threads 2"), scratch("reference.err"));
    return slurp(p);
  }();
  return csv;
}

// Starts the sweep, waits until its journal holds `rows` finished points, sends `sig`.
// Returns the exit status of the killed process (-signal if it died of it).
int start_and_kill(const fs::path& csv, int sig, std::size_t rows, const std::string& extra = "") {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string cmd = sweep_cmd(csv, "--threads 1 " + extra) + " 2>/dev/null";
    execl("/bin/sh", "sh", "-c", ("exec " + cmd).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const fs::path journal = csv.string() + ".journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(journal) && lines(journal) > rows) break;
    if (waitpid(pid, &status, WNOHANG) == pid)  // ended before the kill: the test says so
      return WIFSIGNALED(status) ? -WTERMSIG(status) : WEXITSTATUS(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, sig);
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? -WTERMSIG(status) : WEXITSTATUS(status);
}

TEST(SweepCli, KilledBySigkillThenResumedEqualsAnUninterruptedRun) {
  const std::string& expected = reference_csv();
  ASSERT_EQ(std::count(expected.begin(), expected.end(), '\n'), 1 + kPoints);
  const fs::path csv = scratch("sigkill.csv");
  EXPECT_EQ(start_and_kill(csv, SIGKILL, 1000), -SIGKILL);
  EXPECT_FALSE(fs::exists(csv)) << "no half-written CSV";
  EXPECT_TRUE(fs::exists(csv.string() + ".journal"));

  // Without --resume the journal is not silently thrown away.
  EXPECT_EQ(shell(sweep_cmd(csv, "--threads 2"), scratch("e1")), 2);
  EXPECT_NE(slurp(scratch("e1")).find("--resume"), std::string::npos);

  // Killed again while resuming, then resumed to the end.
  EXPECT_EQ(start_and_kill(csv, SIGKILL, 3000, "--resume"), -SIGKILL);
  const int rc = shell(sweep_cmd(csv, "--threads 2 --resume"), scratch("e2"));
  EXPECT_TRUE(rc == 0 || rc == 1) << slurp(scratch("e2"));  // 1: some points failed (named)
  EXPECT_NE(slurp(scratch("e2")).find("resuming"), std::string::npos);
  EXPECT_EQ(slurp(csv), expected);
  EXPECT_FALSE(fs::exists(csv.string() + ".journal"));
  EXPECT_FALSE(fs::exists(csv.string() + ".partial"));
}

TEST(SweepCli, SigtermStopsCleanlyAndSaysHowToResume) {
  const std::string& expected = reference_csv();
  const fs::path csv = scratch("sigterm.csv");
  const fs::path err = scratch("sigterm.err");
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string cmd = sweep_cmd(csv, "--threads 1") + " 2>" + err.string();
    execl("/bin/sh", "sh", "-c", ("exec " + cmd).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const fs::path journal = csv.string() + ".journal";
  // a sweep that ends (or dies) before it has journalled 1000 points is a failure, not a hang
  int status = 0;
  bool ended = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!(fs::exists(journal) && lines(journal) > 1000)) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no journal after 60 s";
    if (waitpid(pid, &status, WNOHANG) == pid) {
      ended = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_FALSE(ended) << "the sweep ended before it was interrupted: " << slurp(err);
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  EXPECT_FALSE(fs::exists(csv));
  const std::string message = slurp(err);
  EXPECT_NE(message.find("interrupted"), std::string::npos) << message;
  EXPECT_NE(message.find("--resume"), std::string::npos) << message;
  // The journal holds whole lines only: the points in flight were finished, not torn.
  const std::string j = slurp(journal);
  EXPECT_EQ(j.back(), '\n');

  const int rc = shell(sweep_cmd(csv, "--threads 2 --resume"), scratch("e3"));
  EXPECT_TRUE(rc == 0 || rc == 1) << slurp(scratch("e3"));
  EXPECT_EQ(slurp(csv), expected);
}

TEST(SweepCli, TwoMpiRanksWriteTheSameCsv) {
  const std::string& expected = reference_csv();
  // What Open MPI needs to run 2 ranks as root on a small box without a network, set here
  // for this test only.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  // Open MPI's own allocations outlive MPI_Finalize: under `make asan` LeakSanitizer would
  // fail the run on them (sanitizer builds only; the variable is ignored otherwise).
  setenv("LSAN_OPTIONS", "detect_leaks=0", 1);
  const fs::path csv = scratch("mpi.csv");
  const std::string cmd = std::string(IVV_MPIEXEC) +
                          " --oversubscribe --bind-to none -np 2 --mca btl self,vader " +
                          sweep_cmd(csv, "--threads 1");
  const int rc = shell(cmd, scratch("mpi.err"));
  EXPECT_TRUE(rc == 0 || rc == 1) << slurp(scratch("mpi.err"));
  EXPECT_EQ(slurp(csv), expected);
  // Both ranks computed a share (the CSV above merges their rows).
  unsigned long rank0 = 0, rank1 = 0;
  const std::string err = slurp(scratch("mpi.err"));
  const auto at = err.find("2 MPI ranks computed");
  ASSERT_NE(at, std::string::npos) << err;
  ASSERT_EQ(std::sscanf(err.c_str() + at, "2 MPI ranks computed %lu, %lu", &rank0, &rank1), 2);
  EXPECT_EQ(rank0 + rank1, kPoints);
  EXPECT_GT(rank1, 0u);
  const auto sidecar = nlohmann::json::parse(slurp(scratch("mpi.json")));
  const auto& c = sidecar["counts"];
  EXPECT_EQ(c["separated"].get<std::size_t>() + c["captured"].get<std::size_t>() +
                c["failed"].get<std::size_t>(),
            kPoints);
}

TEST(SweepCli, SidecarDescribesTheRun) {
  const fs::path csv = scratch("small.csv");
  ASSERT_EQ(
      shell(std::string(IVV_BINARY) +
                " sweep --scene paper --v0 0.5:5:4 --log --zeta 0,0.1,0.3 --out " + csv.string(),
            scratch("small.err")),
      0);
  const auto j = nlohmann::json::parse(slurp(scratch("small.json")));
  EXPECT_EQ(j["law"], "elastoplastic");
  // the defaults: the model and the integrator are chosen per point
  EXPECT_EQ(j["integrator"], "auto");
  EXPECT_EQ(j["model"], "auto");
  EXPECT_EQ(j["grid"]["points"], 12);
  EXPECT_EQ(j["grid"]["v0"]["spec"], "0.5:5:4");
  EXPECT_EQ(j["counts"]["separated"], 12);
  // what the choice was, per row: the undamped column by the closed form, the rest by dop853
  EXPECT_EQ(j["counts"]["routes"]["closed-form-elastoplastic"], 4);
  EXPECT_EQ(j["counts"]["routes"]["integrated"], 8);
  EXPECT_EQ(j["counts"]["integrators"]["none"], 4);
  EXPECT_EQ(j["counts"]["integrators"]["dop853"], 8);
  EXPECT_TRUE(j["tolerances"].contains("rtol"));
  EXPECT_TRUE(j["scene"].contains("mass"));
  EXPECT_FALSE(j["ivv"]["version"].get<std::string>().empty());
  EXPECT_FALSE(j["ivv"]["commit"].get<std::string>().empty());
}

// Bad input: exit 2 naming the flag, and no file of any kind.
TEST(SweepCli, BadInputLeavesNoFile) {
  struct Case {
    std::string args, flag;
  };
  for (const Case& c :
       {Case{"--law hunt-crossley --v0 1,2 --zeta 0,0.1", "--zeta"},
        Case{"--v0 1:2:1000000 --zeta 0:1:1000000", "--v0"},
        Case{"--v0 1,2 --zeta 0.1 --threads -1", "--threads"},
        Case{"--v0 1 --zeta 0 --set nosuch.key=1:2:3", "--set nosuch.key"},
        Case{"--v0 1 --zeta 0 --set impactor.mass=-1:1:3", "--set impactor.mass"},
        Case{"--v0 1 --zeta 0 --set impactor.mass=log:0:1:3", "--set impactor.mass"},
        Case{"--v0 1 --zeta 0 --set impactor.mass=2:1:3", "--set impactor.mass"},
        Case{"--v0 1 --zeta 0 --set impactor.mass", "--set"},
        Case{"--v0 1 --zeta 0 --set structure.thickness=0.001:0.01:3",
             "--set structure.thickness"}}) {
    const fs::path csv = scratch("bad.csv");
    const fs::path err = scratch("bad.err");
    EXPECT_EQ(
        shell(std::string(IVV_BINARY) + " sweep --scene paper " + c.args + " --out " + csv.string(),
              err),
        2)
        << c.args;
    EXPECT_NE(slurp(err).find(c.flag), std::string::npos) << slurp(err);
    EXPECT_EQ(slurp(err).find("bad_alloc"), std::string::npos) << slurp(err);
    for (const char* suffix : {"", ".journal", ".partial"})
      EXPECT_FALSE(fs::exists(csv.string() + suffix)) << c.args << suffix;
    EXPECT_FALSE(fs::exists(scratch("bad.json")));
  }
}

// IVV_MACHINE_CODE (solver/steppers/machine_code.h) takes baseline or fastest; anything else is
// bad input naming the variable, refused before any file appears.
TEST(SweepCli, MachineCodeFromTheEnvironmentIsBaselineOrFastest) {
  const fs::path csv = scratch("machine.csv");
  const fs::path err = scratch("machine.err");
  const std::string grid = " sweep --scene paper --v0 1,2 --zeta 0.1 -q --out " + csv.string();
  EXPECT_EQ(shell("IVV_MACHINE_CODE=avx512 " + std::string(IVV_BINARY) + grid, err), 2);
  EXPECT_NE(slurp(err).find("IVV_MACHINE_CODE"), std::string::npos) << slurp(err);
  for (const char* suffix : {"", ".journal", ".partial"})
    EXPECT_FALSE(fs::exists(csv.string() + suffix)) << suffix;
  for (const char* code : {"baseline", "fastest"}) {
    EXPECT_EQ(shell(std::string("IVV_MACHINE_CODE=") + code + " " + IVV_BINARY + grid, err), 0)
        << code << ": " << slurp(err);
    EXPECT_TRUE(fs::exists(csv)) << code;
    fs::remove(csv);
    fs::remove(scratch("machine.json"));
  }
}

// The rows of a shell command's standard output (stderr to `err`); `rc` its exit code.
std::string stdout_of(const std::string& cmd, const fs::path& err, int& rc) {
  const fs::path out = scratch("stdout.csv");
  rc = shell(cmd + " >" + out.string(), err);
  return slurp(out);
}

// `--out -`: the same bytes as the CSV file, on standard output, and no file of any kind.
TEST(SweepCli, OutDashStreamsTheCsvToStandardOutput) {
  const fs::path dir = scratch("stream-dir");
  fs::create_directories(dir);
  const std::string grid = " sweep --scene paper --v0 0.1:1:10 --zeta 0,0.1,1 -q --out ";
  ASSERT_EQ(shell(std::string(IVV_BINARY) + grid + scratch("file.csv").string(), scratch("f.err")),
            0);
  int rc = -1;
  const std::string rows =
      stdout_of("cd " + dir.string() + " && " + IVV_BINARY + grid + "-", scratch("s.err"), rc);
  EXPECT_EQ(rc, 0) << slurp(scratch("s.err"));
  EXPECT_EQ(rows, slurp(scratch("file.csv")));
  EXPECT_TRUE(fs::is_empty(dir)) << "no journal, partial or sidecar beside a stream";
  // and the values typed: 0.1:1:10 is 0.1, 0.2, ..., 1 (the naive formula printed
  // 0.30000000000000004 and 0.99999999999999989)
  std::istringstream in(rows);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> v0;
  while (std::getline(in, line))
    if (v0.empty() || v0.back() != line.substr(0, line.find(',')))
      v0.push_back(line.substr(0, line.find(',')));
  EXPECT_EQ(v0, (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8",
                                          "0.9", "1"}));
  // no journal, so no --resume
  EXPECT_EQ(shell(std::string(IVV_BINARY) + grid + "- --resume >/dev/null", scratch("r.err")), 2);
  EXPECT_NE(slurp(scratch("r.err")).find("--resume"), std::string::npos);
}

// `ivv sweep --out - | head`: the reader stops after three lines; the sweep stops with exit 0,
// no crash by SIGPIPE and nothing on stderr with -q.
TEST(SweepCli, OutDashIntoAPipeThatCloses) {
  const fs::path err = scratch("pipe.err");
  const fs::path head = scratch("pipe.head");
  const fs::path rc_file = scratch("pipe.rc");
  const std::string cmd = "bash -c '" + std::string(IVV_BINARY) + " " + kGrid + " --out - 2>" +
                          err.string() + " | head -3 >" + head.string() +
                          "; echo ${PIPESTATUS[0]} >" + rc_file.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(std::stoi(slurp(rc_file)), 0) << slurp(err);
  EXPECT_EQ(slurp(err), "");
  EXPECT_EQ(lines(head), 3u);
  EXPECT_EQ(slurp(head).rfind("v0,zeta,e,", 0), 0u);
}

// A scene value as an axis: a column named by its key, its unit in the sidecar and in --help.
TEST(SweepCli, SetSweepsASceneValue) {
  const fs::path csv = scratch("thickness.csv");
  ASSERT_EQ(shell(std::string(IVV_BINARY) +
                      " sweep --scene steel-ball-on-steel-plate --law hertz --v0 1,2 --set "
                      "structure.thickness=0.001:0.01:10 --set impactor.mass=log:0.001:0.1:3 -q "
                      "--out " +
                      csv.string(),
                  scratch("thickness.err")),
            0)
      << slurp(scratch("thickness.err"));
  const std::string rows = slurp(csv);
  EXPECT_EQ(rows.rfind("v0,zeta,structure.thickness,impactor.mass,e,", 0), 0u) << rows;
  EXPECT_EQ(lines(csv), 1u + 2 * 10 * 3);
  // row-major, the last axis fastest: the 7th row is v0 1, h = 0.003, m = 0.001
  std::istringstream in(rows);
  std::string line;
  for (int i = 0; i < 8; ++i) std::getline(in, line);
  EXPECT_EQ(line.rfind("1,", 0), 0u) << line;
  EXPECT_NE(line.find(",0.003,0.001,"), std::string::npos) << line;
  const auto j = nlohmann::json::parse(slurp(scratch("thickness.json")));
  EXPECT_EQ(j["columns"]["structure.thickness"], "m");
  EXPECT_EQ(j["columns"]["impactor.mass"], "kg");
  EXPECT_EQ(j["columns"]["v0"], "m/s");
  EXPECT_EQ(j["columns"]["F_max"], "N");
  EXPECT_EQ(j["grid"]["axes"][0]["key"], "structure.thickness");
  EXPECT_EQ(j["grid"]["axes"][0]["spec"], "0.001:0.01:10");
  EXPECT_EQ(j["grid"]["axes"][1]["log"], true);
  EXPECT_EQ(j["grid"]["points"], 60);
  // the CSV's every column has its unit in the sidecar
  std::istringstream header(rows.substr(0, rows.find('\n')));
  for (std::string name; std::getline(header, name, ',');)
    EXPECT_TRUE(j["columns"].contains(name)) << name;

  int rc = -1;
  const std::string help = stdout_of(std::string(IVV_BINARY) + " sweep --help", scratch("h"), rc);
  EXPECT_EQ(rc, 0);
  for (const char* unit : {"v0 [m/s]", "F_max [N]", "t_contact [s]", "structure.thickness [m]",
                           "impactor.mass [kg]", "target.yield_strength [Pa]"})
    EXPECT_NE(help.find(unit), std::string::npos) << unit;
}

}  // namespace
