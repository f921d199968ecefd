#include "solver/sweep.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>

#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/format.h"
#include "solver/parallel.h"

namespace ivv {
namespace fs = std::filesystem;

std::vector<double> linear_grid(double lo, double hi, int n) {
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) g[i] = n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
  return g;
}

std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> g(n);
  const double a = std::log(lo), b = std::log(hi);
  for (int i = 0; i < n; ++i) g[i] = n == 1 ? lo : std::exp(a + (b - a) * i / (n - 1));
  if (n > 1) g.back() = hi;
  return g;
}

namespace {

// Room for a row without its reason: 12 numbers of at most 24 characters, the step count, the
// route, integrator and status names and the separators.
constexpr std::size_t kSweepRowCapacity = 12 * 24 + 20 + 3 * 32 + 17;

// Inputs at 17 significant digits (they read back exactly: a row can be re-run), results at
// 12; the same bytes as printf's %.17g and %.12g (solver/format.h).
constexpr int kInputDigits = 17;
constexpr int kResultDigits = 12;

std::string exact(double x) {
  return fmt(x, kInputDigits);
}

// Points per velocity: the zeta grid, or 1 when every point keeps the scene's own dashpot.
std::size_t zeta_count(const SweepRequest& req) {
  return req.scene_dashpot ? 1 : req.zetas.size();
}

// The zeta of point `index`: the grid's, or the derived zeta of the scene's own dashpot.
double point_zeta(const SweepRequest& req, std::size_t index) {
  if (!req.scene_dashpot) return req.zetas[index % req.zetas.size()];
  Scene s = req.base.scene;
  s.velocity = req.velocities[index];
  return derive(s).zeta;
}

// "v0,zeta," of a point: the start of its row, used to check rows read back from disk.
std::string row_prefix(const SweepRequest& req, std::size_t index) {
  return exact(req.velocities[index / zeta_count(req)]) + ',' + exact(point_zeta(req, index)) + ',';
}

std::string point_label(const SweepRequest& req, std::size_t index) {
  return "sweep point " + std::to_string(index) + " (--v0 " +
         exact(req.velocities[index / zeta_count(req)]) +
         (req.scene_dashpot ? std::string(", the scene's dashpot")
                            : " --zeta " + exact(point_zeta(req, index))) +
         ")";
}

SimulationRequest with_point(const SimulationRequest& base, double v0, double zeta) {
  SimulationRequest r = base;
  r.scene.velocity = v0;
  r.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  return r;
}

// FNV-1a, 64 bit: a stable fingerprint of a sweep's inputs for its journal.
std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

// One journal line "index checksum row" (row without its newline): the index and the row
// (newline restored) when the index is below `total` and the checksum matches; nullopt for a
// line that was edited, cut short or is not a journal row.
std::optional<std::pair<std::size_t, std::string>> parse_journal_line(const std::string& line,
                                                                      std::size_t total) {
  const std::size_t space = line.find(' ');
  if (space == std::string::npos || space == 0 || space + 18 > line.size()) return std::nullopt;
  if (line[space + 17] != ' ') return std::nullopt;
  char* end = nullptr;
  const unsigned long long index = std::strtoull(line.c_str(), &end, 10);
  if (end != line.c_str() + space || index >= total) return std::nullopt;
  const unsigned long long sum = std::strtoull(line.c_str() + space + 1, &end, 16);
  if (end != line.c_str() + space + 17) return std::nullopt;
  std::string row = line.substr(space + 18) + '\n';
  if (fnv1a(row) != sum) return std::nullopt;
  return std::make_pair(static_cast<std::size_t>(index), std::move(row));
}

// Field `name` of a row: its index is read off sweep_csv_header(), and the fields up to the
// status column (numbers, the route and integrator names) hold no commas.
int column_index(std::string_view name) {
  const std::string header = sweep_csv_header();
  std::string key(1, ',');
  key.append(name).push_back(',');
  const std::size_t at = header.find(key);
  if (at == std::string::npos)
    throw std::logic_error("sweep CSV header has no column '" + std::string(name) + "'");
  return static_cast<int>(std::count(header.begin(), header.begin() + at, ',')) + 1;
}
[[noreturn]] void io_error(const fs::path& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path.string() + ": " + what);
}

}  // namespace

// ---- validation ----------------------------------------------------------------------------

std::size_t point_count(const SweepRequest& req) {
  return req.velocities.size() * zeta_count(req);
}

SimulationRequest point_request(const SweepRequest& req, std::size_t index) {
  if (req.scene_dashpot) {
    SimulationRequest r = req.base;
    r.scene.velocity = req.velocities[index];
    return r;
  }
  const std::size_t nz = req.zetas.size();
  return with_point(req.base, req.velocities[index / nz], req.zetas[index % nz]);
}

namespace {
// A sweep that keeps the scene's own dashpot: no zeta grid, a dashpot to keep, each v0 valid.
void validate_scene_dashpot(const SweepRequest& req) {
  if (!req.zetas.empty())
    throw InputError("--zeta", "give either a zeta grid or keep the scene's own dashpot, not both");
  if (static_cast<double>(req.velocities.size()) > kMaxSweepPoints)
    throw InputError("--v0", "the grid has more than 1e8 points (split the study)");
  if (req.base.scene.damping.kind == Damping::Kind::none)
    throw InputError("--zeta", "missing: the scene has no dashpot of its own to keep");
  for (double v : req.velocities) {
    if (!(std::isfinite(v) && v > 0))
      throw InputError("--v0", "velocities must be finite and > 0 m/s, got " + exact(v));
    SimulationRequest r = req.base;
    r.scene.velocity = v;
    validate(r);
  }
}
}  // namespace

void validate(const SweepRequest& req) {
  validate_threads(req.threads);
  if (req.velocities.empty()) throw InputError("--v0", "the velocity grid is empty");
  if (req.scene_dashpot) return validate_scene_dashpot(req);
  if (req.zetas.empty()) throw InputError("--zeta", "the damping grid is empty");
  const double points =
      static_cast<double>(req.velocities.size()) * static_cast<double>(req.zetas.size());
  if (points > kMaxSweepPoints)
    throw InputError("--v0", "the grid --v0 x --zeta has " + std::to_string(req.velocities.size()) +
                                 " x " + std::to_string(req.zetas.size()) + " = " + fmt(points, 3) +
                                 " points; at most 1e8 are accepted (split the study)");
  for (double v : req.velocities)
    if (!(std::isfinite(v) && v > 0))
      throw InputError("--v0", "velocities must be finite and > 0 m/s, got " + exact(v));
  for (double z : req.zetas)
    if (!(std::isfinite(z) && z >= 0))
      throw InputError("--zeta",
                       "damping ratios must be finite and >= 0 (0: no dashpot), got " + exact(z));
  for (double z : req.zetas)
    if (z > 0 && !req.base.scene.yield_strength)
      throw InputError("--zeta",
                       "a damping ratio is defined with K_y and needs target.yield_strength; "
                       "this scene has none: use --zeta 0 (no dashpot)");
  // Every point is a valid request: each v0 and each zeta once (they enter separately); a
  // rate-dependent law with a dashpot is refused there, naming --zeta.
  // The grid's values were typed as --v0 and --zeta, not as the scene's impact.velocity and
  // damping.zeta: a point's error names the flag (`--v0 1e308` named impact.velocity).
  auto as_flag = [](const InputError& e, const char* flag) {
    const std::string what = e.what();
    return InputError(flag, what.substr(std::min(what.size(), e.field().size() + 2)));
  };
  for (double v : req.velocities) {
    try {
      validate(with_point(req.base, v, req.zetas.front()));
    } catch (const InputError& e) {
      if (e.field() == "impact.velocity") throw as_flag(e, "--v0");
      throw;
    }
  }
  for (double z : req.zetas) {
    try {
      validate(with_point(req.base, req.velocities.front(), z));
    } catch (const InputError& e) {
      if (e.field() == "damping.zeta") throw as_flag(e, "--zeta");
      throw;
    }
  }
}

ValidatedRequest ValidatedRequest::grid_point(const SweepRequest& /*grid: validated*/,
                                              const SimulationRequest& point) {
  return ValidatedRequest(point, Trusted{});
}

// ---- rows ----------------------------------------------------------------------------------

std::string sweep_csv_header() {
  return "v0,zeta,e,e_poisson,e_energetic,F_max,t_F_max,t_contact,z_max,alpha_max,z_perm,"
         "energy_residual,steps,route,integrator,status,reason\n";
}

void append_sweep_csv_row(std::string& row, double v0, double zeta, const ImpactResult& r) {
  append_general(row, v0, kInputDigits);
  row += ',';
  append_general(row, zeta, kInputDigits);
  row += ',';
  if (r.ok()) {
    for (double x : {r.e, r.e_poisson, r.e_energetic, r.F_max, r.t_F_max, r.t_contact, r.z_max,
                     r.alpha_max, r.z_perm, r.energy.residual}) {
      append_general(row, x, kResultDigits);
      row += ',';
    }
  } else {
    row.append(10, ',');  // no number is better than a plausible wrong one
  }
  append_integer(row, r.steps);
  for (std::string_view name : {r.route, r.integrator, to_string(r.status)}) {
    row += ',';
    row += name;
  }
  row += ',';
  if (!r.reason.empty()) {
    row += '"';
    for (char c : r.reason) {
      if (c == '"') row += '"';
      row += (c == '\n' || c == '\r') ? ' ' : c;
    }
    row += '"';
  } else if (!r.ok()) {
    row += "\"failed without a reason\"";
  }
  row += '\n';
}

std::string sweep_csv_row(double v0, double zeta, const ImpactResult& r) {
  std::string row;
  row.reserve(kSweepRowCapacity + r.reason.size());
  append_sweep_csv_row(row, v0, zeta, r);
  return row;
}

std::string run_sweep_point(const SweepRequest& req, std::size_t index) {
  const SimulationRequest r = point_request(req, index);
  try {
    return sweep_csv_row(r.scene.velocity, point_zeta(req, index),
                         simulate(ValidatedRequest::grid_point(req, r)));
  } catch (const std::exception& e) {
    throw std::runtime_error(point_label(req, index) + ": " + e.what());
  }
}

// ---- in memory -----------------------------------------------------------------------------

std::vector<SweepPoint> run_sweep(const SweepRequest& req) {
  validate(req);
  const std::size_t nz = zeta_count(req);
  std::vector<SweepPoint> points(point_count(req));
  ParallelOptions opt;
  opt.threads = req.threads;
  opt.progress = req.progress;
  opt.stop = req.stop;
  try {
    parallel_for(points.size(), opt, [&](std::size_t i) {
      points[i].v0 = req.velocities[i / nz];
      points[i].zeta = point_zeta(req, i);
      try {
        const SimulationRequest point = point_request(req, i);
        points[i].result = simulate(ValidatedRequest::grid_point(req, point));
      } catch (const std::exception& e) {
        throw std::runtime_error(point_label(req, i) + ": " + e.what());
      }
    });
  } catch (const ParallelError& e) {
    std::rethrow_exception(e.cause());
  }
  return points;
}

// ---- journalled output ---------------------------------------------------------------------

fs::path SweepSink::journal_path() const {
  return fs::path(options_.csv.string() + ".journal");
}

SweepSink::SweepSink(const SweepRequest& request, SweepOutputOptions options)
    : options_(std::move(options)), total_(point_count(request)) {
  validate(request);  // before any file is touched
  const fs::path csv = options_.csv;
  if (csv.empty()) throw InputError("--out", "must name a file");
  std::error_code ec;
  if (fs::is_directory(csv, ec)) throw InputError("--out", csv.string() + " is a directory");
  const fs::path journal = journal_path();
  const fs::path partial = csv.string() + ".partial";
  // what a run killed while committing left behind (its PID no longer runs)
  remove_stale_temporaries(csv);
  if (!options_.sidecar.empty()) remove_stale_temporaries(options_.sidecar);

  std::string fingerprint = options_.description + '\n' + sweep_csv_header();
  for (double v : request.velocities) fingerprint += exact(v) + ' ';
  fingerprint += '\n';
  for (double z : request.zetas) fingerprint += exact(z) + ' ';
  if (request.scene_dashpot) fingerprint += "the scene's dashpot";
  char journal_header[96];
  std::snprintf(journal_header, sizeof journal_header, "ivv-sweep-journal 2 %016llx %zu",
                static_cast<unsigned long long>(fnv1a(fingerprint)), total_);

  // A journal without a whole first line was cut off as it was created: it holds nothing.
  bool have_journal = false;
  if (fs::exists(journal, ec)) {
    std::ifstream in(journal, std::ios::binary);
    std::string line;
    have_journal = std::getline(in, line) && !in.eof();
  }
  if (have_journal && !options_.resume)
    throw InputError("--resume", journal.string() +
                                     " exists: an interrupted sweep left it. Add --resume to "
                                     "continue it, or delete it to start over");
  std::ifstream journal_in;
  std::uintmax_t valid = 0;
  if (options_.resume && have_journal) {
    journal_in.open(journal, std::ios::binary);
    std::string line;
    if (!std::getline(journal_in, line) || journal_in.eof() || line != journal_header)
      throw InputError("--resume", journal.string() +
                                       " was written by another sweep (scene, law, integrator, "
                                       "tolerances or grid differ) or by another version of "
                                       "ivv: delete it or rerun that sweep");
    valid = line.size() + 1;
  }
  // The partial CSV is rebuilt from the journal, whose rows carry checksums (an edited or
  // truncated row went into the final CSV with exit 0 when only "v0,zeta," was checked; a partial
  // row, like an unchecked journal row, could have been edited or cut short).
  partial_ = std::fopen(partial.c_str(), "wb");
  if (!partial_)
    throw InputError("--out", "cannot write " + partial.string() + ": " + std::strerror(errno));
  // 1 MiB, not stdio's 4 KiB: a 300 x 300 map's 17 MB are 17 writes, not 4,200
  partial_buffer_.resize(std::size_t{1} << 20);  // glibc ignores a size without a buffer
  std::setvbuf(partial_, partial_buffer_.data(), _IOFBF, partial_buffer_.size());
  if (std::fputs(sweep_csv_header().c_str(), partial_) < 0) io_error(partial, std::strerror(errno));
  // The journal: every finished point as "index checksum row", the checksum FNV-1a of the row
  // (with its newline). A row whose checksum, index or inputs do not match is not trusted: it
  // is counted in damaged_rows() and its point computed again.
  if (journal_in.is_open()) {
    valid += read_journal_rows(journal_in, request);
    journal_in.close();
    fs::resize_file(journal, valid);  // drop a line torn by SIGKILL before appending
  }
  journal_ = std::fopen(journal.c_str(), have_journal ? "ab" : "wb");
  if (!journal_)
    throw InputError("--out", "cannot write " + journal.string() + ": " + std::strerror(errno));
  // room for a batch of rows (SweepRunOptions::batch): one write a flush
  journal_buffer_.resize(std::size_t{1} << 16);
  std::setvbuf(journal_, journal_buffer_.data(), _IOFBF, journal_buffer_.size());
  if (!have_journal &&
      (std::fprintf(journal_, "%s\n", journal_header) < 0 || std::fflush(journal_) != 0))
    io_error(journal, std::strerror(errno));
  std::lock_guard lock(mutex_);
  write_ready();
  cursor_ = next_write_;  // rows read back contiguously from k are written; hand out the rest
}

std::uintmax_t SweepSink::read_journal_rows(std::istream& in, const SweepRequest& request) {
  std::uintmax_t whole = 0;  // bytes of whole lines
  std::string line;
  while (std::getline(in, line) && !in.eof()) {
    whole += line.size() + 1;
    std::optional<std::pair<std::size_t, std::string>> row = parse_journal_line(line, total_);
    if (!row || row->second.rfind(row_prefix(request, row->first), 0) != 0) {
      ++damaged_;
      continue;
    }
    if (row->first < next_write_ || pending_.count(row->first)) continue;  // first one wins
    count(row->second);
    ++resumed_;
    pending_.emplace(row->first, std::move(row->second));
    write_ready();  // streams contiguous rows out: memory stays within the window
  }
  return whole;
}

SweepSink::~SweepSink() {
  if (partial_) std::fclose(partial_);
  if (journal_) std::fclose(journal_);
}

std::size_t SweepSink::done() const {
  std::lock_guard lock(mutex_);
  return resumed_ + delivered_;
}

void SweepSink::count(const std::string& row) {
  static const int status = column_index("status"), route = column_index("route"),
                   integrator = column_index("integrator");
  // the three columns in one pass over the row
  std::array<std::string_view, 3> fields;  // route, integrator, status
  const std::array<int, 3> wanted = {route, integrator, status};
  std::size_t pos = 0;
  for (int f = 0, got = 0; got < 3 && pos <= row.size(); ++f) {
    const std::size_t end = std::min(row.find(',', pos), row.size());
    for (int k = 0; k < 3; ++k)
      if (wanted[k] == f) {
        fields[k] = std::string_view(row).substr(pos, end - pos);
        ++got;
      }
    pos = end + 1;
  }
  ++counts_.routes[std::string(fields[0])];
  ++counts_.integrators[std::string(fields[1])];
  const std::string_view s = fields[2];
  if (s == to_string(ImpactStatus::separated))
    ++counts_.separated;
  else if (s == to_string(ImpactStatus::captured))
    ++counts_.captured;
  else
    ++counts_.failed;
}

bool SweepSink::exhausted() const {
  std::lock_guard lock(mutex_);
  return stop_ || cursor_ >= total_;
}

std::vector<std::size_t> SweepSink::take(std::size_t max, bool block) {
  std::unique_lock lock(mutex_);
  std::vector<std::size_t> out;
  while (out.empty()) {
    if (stop_ || cursor_ >= total_) return out;
    if (cursor_ >= next_write_ + options_.window) {
      if (!block) return out;
      written_cv_.wait_for(lock, std::chrono::milliseconds(100));  // also polls stop_
      continue;
    }
    while (out.size() < max && cursor_ < total_ && cursor_ < next_write_ + options_.window) {
      if (!pending_.count(cursor_)) out.push_back(cursor_);  // resumed rows are not rerun
      ++cursor_;
    }
  }
  return out;
}

void SweepSink::record(std::size_t index, const std::string& row) {
  if (index < next_write_ || pending_.count(index)) return;  // delivered before: keep the first
  // "index checksum row" as printf's "%zu %016llx %s" wrote it, formatted here (once a point)
  char head[48];
  char* p = std::to_chars(head, head + 20, index).ptr;
  *p++ = ' ';
  const std::uint64_t sum = fnv1a(row);
  for (int shift = 60; shift >= 0; shift -= 4) *p++ = "0123456789abcdef"[(sum >> shift) & 0xf];
  *p++ = ' ';
  if (std::fwrite(head, 1, static_cast<std::size_t>(p - head), journal_) !=
          static_cast<std::size_t>(p - head) ||
      std::fwrite(row.data(), 1, row.size(), journal_) != row.size())
    io_error(journal_path(), std::strerror(errno));
  count(row);
  ++delivered_;
  pending_.emplace(index, row);
}

void SweepSink::deliver(std::size_t index, const std::string& row) {
  std::lock_guard lock(mutex_);
  record(index, row);
  if (std::fflush(journal_) != 0) io_error(journal_path(), std::strerror(errno));
  write_ready();
}

void SweepSink::deliver(const std::vector<std::pair<std::size_t, std::string>>& rows) {
  std::lock_guard lock(mutex_);
  for (const auto& [index, row] : rows) record(index, row);
  if (std::fflush(journal_) != 0) io_error(journal_path(), std::strerror(errno));
  write_ready();
}

void SweepSink::write_ready() {
  bool wrote = false;
  for (auto it = pending_.begin(); it != pending_.end() && it->first == next_write_;
       it = pending_.erase(it), ++next_write_) {
    if (std::fputs(it->second.c_str(), partial_) < 0)
      io_error(options_.csv.string() + ".partial", std::strerror(errno));
    wrote = true;
  }
  if (wrote) written_cv_.notify_all();
}

bool SweepSink::finish_with_sidecar(
    const std::function<void(const SweepCounts&, std::ostream&)>& write_sidecar) {
  return commit_csv([&](StagedFile& csv) {
    std::optional<StagedFile> sidecar;
    if (!options_.sidecar.empty())
      sidecar.emplace(options_.sidecar, [&](std::ostream& out) { write_sidecar(counts_, out); });
    if (sidecar) fs::remove(sidecar->target());  // from here until its commit: no sidecar
    csv.commit();
    if (sidecar) sidecar->commit();
  });
}

bool SweepSink::finish(const std::function<void(const SweepCounts&)>& before_commit) {
  return commit_csv([&](StagedFile& csv) {
    if (before_commit) before_commit(counts_);
    csv.commit();
  });
}

bool SweepSink::commit_csv(const std::function<void(StagedFile& csv)>& between) {
  std::lock_guard lock(mutex_);
  const fs::path partial = options_.csv.string() + ".partial";
  if (next_write_ < total_) {
    std::fflush(partial_);
    std::fflush(journal_);
    return false;
  }
  const int closed = std::fclose(partial_);
  partial_ = nullptr;
  if (closed != 0) io_error(partial, std::strerror(errno));
  // the CSV is copied to its temporary first, so that between `before_commit` (the sidecar)
  // and the CSV's rename there is one rename, not the copy of the whole file (a SIGKILL during
  // that copy left a sidecar describing 300,000 points beside an older 2-row CSV)
  StagedFile csv(options_.csv, [&](std::ostream& out) {
    std::ifstream in(partial, std::ios::binary);
    out << in.rdbuf();
  });
  between(csv);
  std::fclose(journal_);
  journal_ = nullptr;
  fs::remove(journal_path());  // first: a journal never outlives its partial CSV
  fs::remove(partial);
  return true;
}

void run_sweep_points(const SweepRequest& req, SweepSink& sink, const SweepRunOptions& opt) {
  // Each worker takes a batch of points, computes it and delivers it in one call: one lock of
  // the sink and one journal flush a batch. Delivering point by point (a chunk of 256 per
  // parallel_for, three locks a point) made two threads contend: 13,849 context switches and
  // 21 % more CPU time than one thread on the 300 x 300 map (perf stat).
  std::mutex progress_mutex;
  ParallelOptions po;
  po.threads = worker_count(sink.total(), req.threads);
  try {
    parallel_for(static_cast<std::size_t>(po.threads), po, [&](std::size_t) {
      std::vector<std::pair<std::size_t, std::string>> rows;
      for (;;) {
        if (opt.stop && *opt.stop) sink.request_stop();
        const std::vector<std::size_t> batch = sink.take(opt.batch, true);
        if (batch.empty()) return;  // take() blocks until work is available or none is left
        rows.clear();
        try {
          for (const std::size_t i : batch) rows.emplace_back(i, run_sweep_point(req, i));
        } catch (...) {
          sink.request_stop();  // the other workers take no more: the sweep ends with this
          sink.deliver(rows);   // the points done before it stay in the journal
          throw;
        }
        sink.deliver(rows);
        if (opt.progress) {  // once a point, as the callers count (mpi_sweep.cc)
          std::lock_guard lock(progress_mutex);
          const std::size_t done = sink.done();
          for (std::size_t k = 0; k < rows.size(); ++k) opt.progress(done, sink.total());
        }
      }
    });
  } catch (const ParallelError& e) {
    std::rethrow_exception(e.cause());
  }
}

}  // namespace ivv
