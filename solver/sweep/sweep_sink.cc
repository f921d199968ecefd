#include "solver/sweep/sweep_sink.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>

#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/format.h"
#include "solver/sweep/sweep_csv.h"

namespace ivv {
namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bit: a stable fingerprint of a sweep's inputs for its journal's header.
std::uint64_t fnv1a(std::string_view s, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

// A journal line's head, "index 0123456789abcdef ", as printf's "%zu %016llx " wrote it.
constexpr std::size_t kChecksumDigits = 16;
// "000102...feff": the two lower-case hexadecimal digits of every byte (the checksum's sixteen
// digits written a byte at a time: a digit at a time was ~100 instructions of a row's journal
// line).
constexpr std::array<char, 512> kHexBytes = [] {
  std::array<char, 512> t{};
  for (int b = 0; b < 256; ++b) {
    t[2 * b] = "0123456789abcdef"[b >> 4];
    t[2 * b + 1] = "0123456789abcdef"[b & 0xf];
  }
  return t;
}();

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
  if (sweep_journal_checksum(row) != sum) return std::nullopt;
  return std::make_pair(static_cast<std::size_t>(index), std::move(row));
}

[[noreturn]] void io_error(const fs::path& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path.string() + ": " + what);
}

}  // namespace

std::uint64_t sweep_journal_checksum(std::string_view row) {
  // Eight bytes a step (FNV-1a's byte a step was ~1,300 instructions of a 225-byte row, a sixth
  // of a point's work outside simulate()). Each step, s -> xorshift((s ^ w) K) with K odd, is a
  // bijection of the state for a fixed word and of the word for a fixed state: a row that
  // differs from the journalled one in a single word, at the same length, always differs in its
  // checksum; the length is mixed in first, so a row cut short does too.
  constexpr std::uint64_t kOdd = 0x9e3779b97f4a7c15ULL;  // 2^64 / golden ratio
  auto word = [](const char* p, std::size_t n) {  // little-endian whatever the machine's order
    std::uint64_t w = 0;
    std::memcpy(&w, p, n);
    if constexpr (std::endian::native == std::endian::big) w = __builtin_bswap64(w);
    return w;
  };
  auto mix = [](std::uint64_t h, std::uint64_t w) {
    h = (h ^ w) * kOdd;
    return h ^ (h >> 32);
  };
  std::uint64_t h = mix(0xcbf29ce484222325ULL, row.size());
  std::size_t i = 0;
  for (; i + 8 <= row.size(); i += 8) h = mix(h, word(row.data() + i, 8));
  h = mix(h, word(row.data() + i, row.size() - i));
  return mix(h * kOdd, h >> 29);
}

// ---- SweepRowBatch ---------------------------------------------------------------------------

std::string& SweepRowBatch::begin_row(std::size_t index) {
  Entry e;
  e.index = index;
  e.begin = text_.size();
  entries_.push_back(e);
  return text_;
}

void SweepRowBatch::end_row(const SweepRowFacts& facts) {
  Entry& e = entries_.back();
  e.size = text_.size() - e.begin;
  e.facts = facts;
  e.has_facts = true;
  const std::string_view row = std::string_view(text_).substr(e.begin, e.size);
  const std::uint64_t sum = sweep_journal_checksum(row);
  char head[48];
  char* end = std::to_chars(head, head + 24, e.index).ptr;
  *end++ = ' ';
  static_assert(2 * sizeof sum == kChecksumDigits);
  for (int shift = 56; shift >= 0; shift -= 8, end += 2)  // a byte, two digits, at a time
    std::memcpy(end, kHexBytes.data() + 2 * ((sum >> shift) & 0xff), 2);
  *end++ = ' ';
  e.line_begin = journal_.size();
  journal_.append(head, end);
  journal_.append(row);
  e.line_size = journal_.size() - e.line_begin;
}

void SweepRowBatch::add(std::size_t index, std::string_view row) {
  begin_row(index).append(row);
  end_row({});
  entries_.back().has_facts = false;
}

void SweepRowBatch::clear() {
  text_.clear();
  journal_.clear();
  entries_.clear();
  next_ = 0;
}

fs::path SweepSink::journal_path() const {
  return fs::path(options_.csv.string() + ".journal");
}

SweepSink::SweepSink(const SweepRequest& request, SweepOutputOptions options)
    : options_(std::move(options)),
      total_(point_count(request)),
      axis_count_(request.axes.size()),
      count_columns_{sweep_csv_column_index("route", axis_count_),
                     sweep_csv_column_index("integrator", axis_count_),
                     sweep_csv_column_index("status", axis_count_)} {
  validate(request);  // before any file is touched
  // Room for a chunk of rows and a delivery more, in both halves of the swap, and for a few
  // batches' journal lines: once reserved, no delivery allocates (sweep_allocation_test.cc).
  // Reserved, not filled: a page is touched when rows reach it.
  for (std::string* s : {&output_pending_, &output_out_})
    s->reserve(kOutputChunk + kOutputChunk / 8);
  for (std::string* s : {&journal_pending_, &journal_out_}) s->reserve(kOutputChunk / 8);
  if (!options_.stream) {
    open_journal(request);
    return;
  }
  if (options_.resume)
    throw InputError("--resume",
                     "a sweep to standard output (--out -) keeps no journal, so it cannot be "
                     "resumed: give --out FILE to have one");
  {
    std::lock_guard lock(mutex_);
    write_rows(sweep_csv_header(request.axes));
  }
  write_pending(Flush::all);
}

namespace {
// The journal's first line: its format's version, a fingerprint of everything that makes the
// sweep (the description, the columns, every value of every axis) and the point count.
std::string journal_header(const SweepRequest& request, const std::string& description,
                           std::size_t total) {
  std::string fingerprint = description + '\n' + sweep_csv_header(request.axes);
  for (double v : request.velocities) append_shortest(fingerprint, v), fingerprint += ' ';
  fingerprint += '\n';
  for (double z : request.zetas) append_shortest(fingerprint, z), fingerprint += ' ';
  if (request.scene_dashpot) fingerprint += "the scene's dashpot";
  for (const SceneAxis& axis : request.axes) {
    fingerprint += '\n' + axis.key + ' ';
    for (double v : axis.values) append_shortest(fingerprint, v), fingerprint += ' ';
  }
  // version 4: rows checksummed eight bytes at a time (version 3: FNV-1a, a byte at a time;
  // version 2 wrote the inputs with 17 digits, not in shortest round-trip form)
  char header[96];
  std::snprintf(header, sizeof header, "ivv-sweep-journal 4 %016llx %zu",
                static_cast<unsigned long long>(fnv1a(fingerprint)), total);
  return header;
}
}  // namespace

void SweepSink::open_journal(const SweepRequest& request) {
  const fs::path csv = options_.csv;
  if (csv.empty()) throw InputError("--out", "must name a file");
  std::error_code ec;
  if (fs::is_directory(csv, ec)) throw InputError("--out", csv.string() + " is a directory");
  const fs::path journal = journal_path();
  const fs::path partial = csv.string() + ".partial";
  // what a run killed while committing left behind (its PID no longer runs)
  remove_stale_temporaries(csv);
  if (!options_.sidecar.empty()) remove_stale_temporaries(options_.sidecar);

  const std::string journal_header = ivv::journal_header(request, options_.description, total_);

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
  // Unbuffered: the sink gathers the rows itself (output_pending_) and writes them a chunk at a
  // time outside its lock (write_pending), so stdio's buffer would only copy them once more.
  std::setvbuf(partial_, nullptr, _IONBF, 0);
  if (std::fputs(sweep_csv_header(request.axes).c_str(), partial_) < 0)
    io_error(partial, std::strerror(errno));
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
  std::setvbuf(journal_, nullptr, _IONBF, 0);  // as the partial: one write a flush
  if (!have_journal &&
      (std::fprintf(journal_, "%s\n", journal_header.c_str()) < 0 || std::fflush(journal_) != 0))
    io_error(journal, std::strerror(errno));
  {
    std::lock_guard lock(mutex_);
    write_ready();
    cursor_ = next_write_;  // rows read back contiguously from k are written; hand out the rest
  }
  write_pending(Flush::all);
}

std::uintmax_t SweepSink::read_journal_rows(std::istream& in, const SweepRequest& request) {
  std::uintmax_t whole = 0;  // bytes of whole lines
  std::string line;
  while (std::getline(in, line) && !in.eof()) {
    whole += line.size() + 1;
    std::optional<std::pair<std::size_t, std::string>> row = parse_journal_line(line, total_);
    if (!row || row->second.rfind(sweep_csv_inputs(point_inputs(request, row->first)), 0) != 0) {
      ++damaged_;
      continue;
    }
    if (row->first < next_write_ || resumed_rows_.count(row->first)) continue;  // first one wins
    count(row->second, facts(row->second));
    ++resumed_;
    resumed_rows_.emplace(row->first, std::move(row->second));
    write_ready();  // streams contiguous rows out: memory stays within the window
    if (output_pending_.size() >= kOutputChunk) write_pending(Flush::all);
  }
  return whole;
}

SweepSink::~SweepSink() {
  try {  // rows delivered but not yet written: into the journal, for --resume
    if (journal_) write_pending(Flush::all);
  } catch (const std::exception&) {  // the error that ended the sweep is already on its way
  }
  if (partial_) std::fclose(partial_);
  if (journal_) std::fclose(journal_);
}

std::size_t SweepSink::done() const {
  std::lock_guard lock(mutex_);
  return resumed_ + delivered_;
}

SweepRowFacts SweepSink::facts(std::string_view row) const {
  // the three columns in one pass over the row (the fields up to the status column, numbers and
  // the route and integrator names, hold no commas)
  std::array<std::size_t, 3> at{}, size{};  // route, integrator, status
  std::size_t pos = 0;
  for (int f = 0, got = 0; got < 3 && pos <= row.size(); ++f) {
    const std::size_t end = std::min(row.find(',', pos), row.size());
    for (int k = 0; k < 3; ++k)
      if (count_columns_[k] == f) {
        at[k] = pos;
        size[k] = end - pos;
        ++got;
      }
    pos = end + 1;
  }
  SweepRowFacts out{at[0], size[0], at[1], size[1], ImpactStatus::failed};
  const std::string_view s = row.substr(at[2], size[2]);
  if (s == to_string(ImpactStatus::separated)) out.status = ImpactStatus::separated;
  if (s == to_string(ImpactStatus::captured)) out.status = ImpactStatus::captured;
  return out;
}

void SweepSink::count(std::string_view row, const SweepRowFacts& facts) {
  // neighbouring rows mostly share their route and integrator: the last name counted is
  // compared first (a lookup in the map a row was ~300 instructions)
  auto tally = [](SweepCounts::Tally& counts, std::optional<SweepCounts::Tally::iterator>& last,
                  std::string_view name) {
    if (!last || (*last)->first != name) {
      auto it = counts.find(name);
      if (it == counts.end()) it = counts.emplace(std::string(name), 0).first;
      last = it;
    }
    ++(*last)->second;
  };
  tally(counts_.routes, last_route_, row.substr(facts.route, facts.route_size));
  tally(counts_.integrators, last_integrator_, row.substr(facts.integrator, facts.integrator_size));
  if (facts.status == ImpactStatus::separated)
    ++counts_.separated;
  else if (facts.status == ImpactStatus::captured)
    ++counts_.captured;
  else
    ++counts_.failed;
}

std::size_t SweepSink::written() const {
  std::lock_guard lock(mutex_);
  return next_write_;
}

bool SweepSink::exhausted() const {
  std::lock_guard lock(mutex_);
  return stop_ || cursor_ >= total_;
}

std::vector<std::size_t> SweepSink::take(std::size_t max, WhenAhead when_ahead,
                                         std::size_t workers) {
  std::unique_lock lock(mutex_);
  return take_locked(lock, max, when_ahead, workers);
}

std::vector<std::size_t> SweepSink::take_locked(std::unique_lock<std::mutex>& lock, std::size_t max,
                                                WhenAhead when_ahead, std::size_t workers) {
  std::vector<std::size_t> out;
  out.reserve(max);  // one allocation a batch, not one for every doubling
  while (out.empty()) {
    if (stop_ || cursor_ >= total_) return out;
    max = guided_batch_size(total_ - cursor_, workers, max);
    if (cursor_ >= next_write_ + options_.window) {
      if (when_ahead == WhenAhead::return_empty) return out;
      written_cv_.wait_for(lock, std::chrono::milliseconds(100));  // also polls stop_
      continue;
    }
    while (out.size() < max && cursor_ < total_ && cursor_ < next_write_ + options_.window) {
      if (!resumed_rows_.count(cursor_)) out.push_back(cursor_);  // resumed rows are not rerun
      ++cursor_;
    }
  }
  return out;
}

void SweepSink::prepare(SweepRowBatch& rows) const {
  std::vector<SweepRowBatch::Entry>& entries = rows.entries_;
  auto by_index = [](const SweepRowBatch::Entry& a, const SweepRowBatch::Entry& b) {
    return a.index < b.index;
  };
  if (!std::is_sorted(entries.begin(), entries.end(), by_index))
    std::stable_sort(entries.begin(), entries.end(), by_index);
  entries.erase(std::unique(entries.begin(), entries.end(),
                            [](const SweepRowBatch::Entry& a, const SweepRowBatch::Entry& b) {
                              return a.index == b.index;  // delivered twice: the first kept
                            }),
                entries.end());
  for (SweepRowBatch::Entry& e : entries)
    if (!e.has_facts) {
      e.facts = facts(std::string_view(rows.text_).substr(e.begin, e.size));
      e.has_facts = true;
    }
}

bool SweepSink::delivered_before(std::size_t index) const {
  if (index < next_write_ || resumed_rows_.count(index)) return true;
  for (const SweepRowBatch& b : parked_) {
    const auto at = std::partition_point(
        b.entries_.begin() + static_cast<std::ptrdiff_t>(b.next_), b.entries_.end(),
        [&](const SweepRowBatch::Entry& e) { return e.index < index; });
    if (at != b.entries_.end() && at->index == index) return true;
  }
  return false;
}

void SweepSink::deliver(std::size_t index, const std::string& row) {
  SweepRowBatch rows;
  rows.add(index, row);
  deliver(rows);
}

void SweepSink::deliver(const std::vector<std::pair<std::size_t, std::string>>& rows) {
  SweepRowBatch batch;
  for (const auto& [index, row] : rows) batch.add(index, row);
  deliver(batch);
}

void SweepSink::deliver(SweepRowBatch& rows) {
  prepare(rows);
  {
    std::lock_guard lock(mutex_);
    record_batch(rows);
  }
  write_pending(Flush::due);
}

std::vector<std::size_t> SweepSink::deliver_and_take(SweepRowBatch& rows, std::size_t max,
                                                     std::size_t workers) {
  prepare(rows);
  std::vector<std::size_t> next;
  {
    std::unique_lock lock(mutex_);
    record_batch(rows);
    next = take_locked(lock, max, WhenAhead::wait, workers);
  }
  write_pending(Flush::due);
  return next;
}

void SweepSink::record_batch(SweepRowBatch& rows) {
  std::vector<SweepRowBatch::Entry>& entries = rows.entries_;
  entries.erase(std::remove_if(entries.begin(), entries.end(),
                               [&](const SweepRowBatch::Entry& e) {
                                 return delivered_before(e.index);  // keep the first
                               }),
                entries.end());
  // the journal lines, a run of adjacent ones at a time (a whole batch of a worker in one)
  for (std::size_t k = 0; journal_ && k < entries.size();) {
    const std::size_t begin = entries[k].line_begin;
    std::size_t end = begin + entries[k].line_size;
    while (++k < entries.size() && entries[k].line_begin == end) end += entries[k].line_size;
    journal_pending_.append(rows.journal_, begin, end - begin);
  }
  for (const SweepRowBatch::Entry& e : entries)
    count(std::string_view(rows.text_).substr(e.begin, e.size), e.facts);
  delivered_ += entries.size();
  // the batch's contents wait here until written; the worker gets an emptied batch's buffers
  if (!entries.empty()) {
    SweepRowBatch spare;
    if (!spare_.empty()) {
      spare = std::move(spare_.back());
      spare_.pop_back();
    }
    parked_.push_back(std::move(rows));
    parked_.back().next_ = 0;
    rows = std::move(spare);
  }
  rows.clear();
  write_ready();
}

void SweepSink::write_ready() {
  bool wrote = false;
  for (;;) {
    if (auto r = resumed_rows_.begin(); r != resumed_rows_.end() && r->first == next_write_) {
      write_rows(r->second);
      resumed_rows_.erase(r);
      ++next_write_;
      wrote = true;
      continue;
    }
    auto b = std::find_if(parked_.begin(), parked_.end(), [&](const SweepRowBatch& p) {
      return p.entries_[p.next_].index == next_write_;
    });
    if (b == parked_.end()) break;
    // the batch's rows from here while they are the next ones (delivered rows are never
    // resumed ones: those are not handed out), in one write while adjacent in the batch's text
    const std::vector<SweepRowBatch::Entry>& entries = b->entries_;
    std::size_t k = b->next_;
    while (k < entries.size() && entries[k].index == next_write_) {
      const std::size_t begin = entries[k].begin;
      std::size_t end = begin + entries[k].size;
      for (++k, ++next_write_;
           k < entries.size() && entries[k].index == next_write_ && entries[k].begin == end;
           ++k, ++next_write_)
        end += entries[k].size;
      write_rows(std::string_view(b->text_).substr(begin, end - begin));
    }
    b->next_ = k;
    wrote = true;
    if (k == entries.size()) {  // written whole: its buffers are a spare
      b->clear();
      spare_.push_back(std::move(*b));
      if (b != parked_.end() - 1) *b = std::move(parked_.back());
      parked_.pop_back();
    }
  }
  if (wrote) written_cv_.notify_all();
}

void SweepSink::write_rows(std::string_view rows) {
  if (options_.stream && output_errno_ != 0) return;  // the reader is gone: nowhere to go
  output_pending_.append(rows);
}

bool SweepSink::output_due(Flush how) const {
  return how == Flush::all || options_.stream || output_pending_.size() >= kOutputChunk;
}

bool SweepSink::write_due(Flush how) const {
  if (!journal_pending_.empty()) return true;  // a journal line is written as soon as it can be
  return !output_pending_.empty() && output_due(how);
}

void SweepSink::write_pending(Flush how) {
  for (;;) {
    std::unique_lock io(io_mutex_, std::defer_lock);
    if (how == Flush::all)
      io.lock();
    else if (!io.try_lock())
      return;  // the thread writing now writes these bytes too before it lets go (below)
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (!write_due(how)) break;
        journal_out_.swap(journal_pending_);  // journal first: a row in the CSV is journalled
        if (output_due(how)) output_out_.swap(output_pending_);
      }
      write_out();
    }
    io.unlock();
    // bytes another thread left while this one held io_mutex_ (its try_lock failed): written
    // now, by this thread, so that none waits for the next delivery
    std::lock_guard lock(mutex_);
    if (!write_due(how)) return;
  }
}

void SweepSink::write_out() {
  if (!journal_out_.empty() && journal_ &&
      std::fwrite(journal_out_.data(), 1, journal_out_.size(), journal_) != journal_out_.size())
    io_error(journal_path(), std::strerror(errno));
  journal_out_.clear();
  if (output_out_.empty()) return;
  if (!options_.stream) {
    if (partial_ &&
        std::fwrite(output_out_.data(), 1, output_out_.size(), partial_) != output_out_.size())
      io_error(options_.csv.string() + ".partial", std::strerror(errno));
  } else if (output_errno_ == 0) {
    if (std::fwrite(output_out_.data(), 1, output_out_.size(), options_.stream) !=
            output_out_.size() ||
        std::fflush(options_.stream) != 0)
      stream_failed();
  }
  output_out_.clear();
}

void SweepSink::stream_failed() {
  if (output_errno_ == 0) output_errno_ = errno ? errno : EIO;
  stop_ = true;
}

namespace {
// The CSV replaces an earlier one after removing it (StagedFile::Replace): renamed over it, the
// 300 x 300 map's 20 MB cost the sweep 15-23 ms of serial time at its end, 3-6 % of a two-thread
// run. Between the removal and the rename there is no CSV, as there is no sidecar from its
// removal to its commit: a reader finds the old pair, nothing, or the new pair, never a partial
// file; a SIGKILL in between leaves the journal, and --resume makes the CSV.
constexpr StagedFile::Replace kCsvReplace = StagedFile::Replace::after_removing;
}  // namespace

bool SweepSink::finish_with_sidecar(
    const std::function<void(const SweepCounts&, std::ostream&)>& write_sidecar) {
  return commit_csv([&](StagedFile& csv) {
    std::optional<StagedFile> sidecar;
    if (!options_.sidecar.empty())
      sidecar.emplace(options_.sidecar, [&](std::ostream& out) { write_sidecar(counts_, out); });
    if (sidecar) fs::remove(sidecar->target());  // from here until its commit: no sidecar
    csv.commit(kCsvReplace);
    if (sidecar) sidecar->commit();
  });
}

bool SweepSink::finish(const std::function<void(const SweepCounts&)>& before_commit) {
  return commit_csv([&](StagedFile& csv) {
    if (before_commit) before_commit(counts_);
    csv.commit(kCsvReplace);
  });
}

bool SweepSink::commit_csv(const std::function<void(StagedFile& csv)>& between) {
  write_pending(Flush::all);
  std::lock_guard lock(mutex_);
  if (options_.stream) {  // nothing to commit: the rows are out
    if (std::fflush(options_.stream) != 0) stream_failed();
    return next_write_ == total_ && output_errno_ == 0;
  }
  const fs::path partial = options_.csv.string() + ".partial";
  if (next_write_ < total_) return false;  // journal and partial hold every row delivered
  const int closed = std::fclose(partial_);
  partial_ = nullptr;
  if (closed != 0) io_error(partial, std::strerror(errno));
  // the partial becomes the CSV's temporary first, so that between `before_commit` (the sidecar)
  // and the CSV's rename there is one rename, not the copy of the whole file (a SIGKILL during
  // that copy left a sidecar describing 300,000 points beside an older 2-row CSV). Renamed, not
  // copied: the copy of the 300 x 300 map's 20 MB was the last serial step of every sweep; a
  // SIGKILL after the rename leaves the journal, from which --resume rebuilds the partial.
  StagedFile csv(options_.csv, StagedFile::FromFile{partial});
  between(csv);
  std::fclose(journal_);
  journal_ = nullptr;
  fs::remove(journal_path());  // first: a journal never outlives its partial CSV
  fs::remove(partial);
  return true;
}

}  // namespace ivv
