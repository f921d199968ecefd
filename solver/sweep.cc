#include "solver/sweep.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "solver/atomic_file.h"
#include "solver/input_error.h"
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

std::string format(const char* fmt, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}
std::string exact(double x) {
  return format("%.17g", x);
}

// "v0,zeta," of a point: the start of its row, used to check rows read back from disk.
std::string row_prefix(const SweepRequest& req, std::size_t index) {
  const std::size_t nz = req.zetas.size();
  return exact(req.velocities[index / nz]) + ',' + exact(req.zetas[index % nz]) + ',';
}

std::string point_label(const SweepRequest& req, std::size_t index) {
  const std::size_t nz = req.zetas.size();
  return "sweep point " + std::to_string(index) + " (--v0 " + exact(req.velocities[index / nz]) +
         " --zeta " + exact(req.zetas[index % nz]) + ")";
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
std::string_view field_of(std::string_view row, int field) {
  std::size_t pos = 0;
  for (int f = 0; f < field && pos != std::string_view::npos; ++f) {
    pos = row.find(',', pos);
    if (pos != std::string_view::npos) ++pos;
  }
  if (pos == std::string_view::npos) return {};
  const std::size_t end = row.find_first_of(",\n", pos);
  return row.substr(pos, end == std::string_view::npos ? row.npos : end - pos);
}

[[noreturn]] void io_error(const fs::path& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path.string() + ": " + what);
}

}  // namespace

// ---- validation ----------------------------------------------------------------------------

std::size_t point_count(const SweepRequest& req) {
  return req.velocities.size() * req.zetas.size();
}

SimulationRequest point_request(const SweepRequest& req, std::size_t index) {
  const std::size_t nz = req.zetas.size();
  return with_point(req.base, req.velocities[index / nz], req.zetas[index % nz]);
}

void validate(const SweepRequest& req) {
  if (req.velocities.empty()) throw InputError("--v0", "the velocity grid is empty");
  if (req.zetas.empty()) throw InputError("--zeta", "the damping grid is empty");
  const double points =
      static_cast<double>(req.velocities.size()) * static_cast<double>(req.zetas.size());
  if (points > kMaxSweepPoints)
    throw InputError("--v0", "the grid --v0 x --zeta has " + std::to_string(req.velocities.size()) +
                                 " x " + std::to_string(req.zetas.size()) + " = " +
                                 format("%.3g", points) +
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
  for (double v : req.velocities) validate(with_point(req.base, v, req.zetas.front()));
  for (double z : req.zetas) validate(with_point(req.base, req.velocities.front(), z));
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

std::string sweep_csv_row(double v0, double zeta, const ImpactResult& r) {
  std::string row = exact(v0) + ',' + exact(zeta) + ',';
  if (r.ok()) {
    for (double x : {r.e, r.e_poisson, r.e_energetic, r.F_max, r.t_F_max, r.t_contact, r.z_max,
                     r.alpha_max, r.z_perm, r.energy.residual})
      row += format("%.12g", x) + ',';
  } else {
    row += std::string(10, ',');  // no number is better than a plausible wrong one
  }
  row += std::to_string(r.steps) + ',' + std::string(r.route) + ',' + std::string(r.integrator) +
         ',' + std::string(to_string(r.status)) + ',';
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
  return row + '\n';
}

std::string run_sweep_point(const SweepRequest& req, std::size_t index) {
  const SimulationRequest r = point_request(req, index);
  try {
    return sweep_csv_row(r.scene.velocity, req.zetas[index % req.zetas.size()],
                         simulate(ValidatedRequest::grid_point(req, r)));
  } catch (const std::exception& e) {
    throw std::runtime_error(point_label(req, index) + ": " + e.what());
  }
}

// ---- in memory -----------------------------------------------------------------------------

std::vector<SweepPoint> run_sweep(const SweepRequest& req) {
  validate(req);
  const std::size_t nz = req.zetas.size();
  std::vector<SweepPoint> points(point_count(req));
  ParallelOptions opt;
  opt.threads = req.threads;
  opt.progress = req.progress;
  try {
    parallel_for(points.size(), opt, [&](std::size_t i) {
      points[i].v0 = req.velocities[i / nz];
      points[i].zeta = req.zetas[i % nz];
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

// The partial CSV: the header and rows 0..k-1 in order (a torn last line is cut off). False when
// its header is not this sweep's (then it is rewritten from scratch).
bool SweepSink::read_partial(const SweepRequest& request, const fs::path& partial, std::size_t& k) {
  std::ifstream in(partial, std::ios::binary);
  std::string line;
  std::uintmax_t valid = 0;
  bool partial_ok = false;
  const std::string header = sweep_csv_header();
  if (std::getline(in, line) && !in.eof() && line + '\n' == header) {
    partial_ok = true;
    valid = header.size();
    while (k < total_ && std::getline(in, line) && !in.eof()) {
      if (line.rfind(row_prefix(request, k), 0) != 0) break;
      count(line);
      valid += line.size() + 1;
      ++k;
    }
  }
  in.close();
  if (partial_ok) fs::resize_file(partial, valid);
  return partial_ok;
}

// The journal: every finished point as "index row"; rows >= k are read back into pending_.
void SweepSink::read_journal(const SweepRequest& request, const fs::path& journal,
                             const std::string& journal_header, std::size_t k) {
  std::ifstream in(journal, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || in.eof() || line != journal_header)
    throw InputError("--resume", journal.string() +
                                     " was written by another sweep (scene, law, integrator, "
                                     "tolerances or grid differ): delete it or rerun that sweep");
  std::uintmax_t valid = line.size() + 1;
  while (std::getline(in, line) && !in.eof()) {
    valid += line.size() + 1;
    const std::size_t space = line.find(' ');
    if (space == std::string::npos || space == 0) continue;  // unreadable: recompute it
    char* end = nullptr;
    const unsigned long long index = std::strtoull(line.c_str(), &end, 10);
    if (end != line.c_str() + space || index >= total_ || index < k) continue;
    std::string row = line.substr(space + 1) + '\n';
    if (row.rfind(row_prefix(request, index), 0) != 0) continue;
    if (pending_.emplace(index, std::move(row)).second) count(pending_[index]);
  }
  in.close();
  fs::resize_file(journal, valid);  // drop a line torn by SIGKILL before appending
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

  std::string fingerprint = options_.description + '\n' + sweep_csv_header();
  for (double v : request.velocities) fingerprint += exact(v) + ' ';
  fingerprint += '\n';
  for (double z : request.zetas) fingerprint += exact(z) + ' ';
  char journal_header[96];
  std::snprintf(journal_header, sizeof journal_header, "ivv-sweep-journal 1 %016llx %zu",
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

  // The partial CSV: the header and rows 0..k-1 in order; the journal: rows >= k.
  std::size_t k = 0;
  bool partial_ok = false;
  if (options_.resume && have_journal && fs::exists(partial, ec))
    partial_ok = read_partial(request, partial, k);
  if (options_.resume && have_journal) read_journal(request, journal, journal_header, k);
  resumed_ = k + pending_.size();
  cursor_ = next_write_ = k;

  partial_ = std::fopen(partial.c_str(), partial_ok ? "ab" : "wb");
  if (!partial_)
    throw InputError("--out", "cannot write " + partial.string() + ": " + std::strerror(errno));
  if (!partial_ok && std::fputs(sweep_csv_header().c_str(), partial_) < 0)
    io_error(partial, std::strerror(errno));
  journal_ = std::fopen(journal.c_str(), have_journal ? "ab" : "wb");
  if (!journal_)
    throw InputError("--out", "cannot write " + journal.string() + ": " + std::strerror(errno));
  if (!have_journal &&
      (std::fprintf(journal_, "%s\n", journal_header) < 0 || std::fflush(journal_) != 0))
    io_error(journal, std::strerror(errno));
  std::lock_guard lock(mutex_);
  write_ready();
  cursor_ = next_write_;  // rows read back contiguously from k are written; hand out the rest
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
  ++counts_.routes[std::string(field_of(row, route))];
  ++counts_.integrators[std::string(field_of(row, integrator))];
  const std::string_view s = field_of(row, status);
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
  if (std::fprintf(journal_, "%zu %s", index, row.c_str()) < 0)
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

bool SweepSink::finish(const std::function<void(const SweepCounts&)>& before_commit) {
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
  if (before_commit) before_commit(counts_);
  write_file_atomically(options_.csv, [&](std::ostream& out) {
    std::ifstream in(partial, std::ios::binary);
    out << in.rdbuf();
  });
  std::fclose(journal_);
  journal_ = nullptr;
  fs::remove(journal_path());  // first: a journal never outlives its partial CSV
  fs::remove(partial);
  return true;
}

void run_sweep_points(const SweepRequest& req, SweepSink& sink, const SweepRunOptions& opt) {
  std::mutex progress_mutex;
  while (true) {
    if (opt.stop && *opt.stop) sink.request_stop();
    const std::vector<std::size_t> chunk = sink.take(opt.chunk, true);
    if (chunk.empty()) break;  // take() blocks until work is available or none is left
    ParallelOptions po;
    po.threads = req.threads;
    po.stop = opt.stop;
    try {
      parallel_for(chunk.size(), po, [&](std::size_t j) {
        sink.deliver(chunk[j], run_sweep_point(req, chunk[j]));
        if (opt.progress) {
          std::lock_guard lock(progress_mutex);
          opt.progress(sink.done(), sink.total());
        }
      });
    } catch (const ParallelError& e) {
      std::rethrow_exception(e.cause());
    }
  }
}

}  // namespace ivv
