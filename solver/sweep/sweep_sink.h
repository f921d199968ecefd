// A sweep streamed to a CSV for large studies (solver/sweep/sweep.h runs it in memory).
//
// Rows are written in index order as they complete (a bounded reorder window, so memory does not
// grow with the grid); every finished point is also appended to a journal beside the output, so
// a sweep stopped at any moment (SIGKILL included) resumes without recomputing what it
// finished, and the final CSV is byte-identical to an uninterrupted run. The CSV appears whole
// or not at all (write_file_atomically).
//
// Or, to a stream (standard output: `ivv sweep --out -`): the same rows in the same order as
// they complete, flushed a batch at a time, with neither journal nor atomic commit (so no
// resume). A reader that stops reading (`| head`) ends the sweep quietly: output_closed().
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <istream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/result.h"
#include "solver/sweep/sweep_csv.h"
#include "solver/sweep/sweep_grid.h"

namespace ivv {

class StagedFile;  // solver/atomic_file.h

struct SweepCounts {
  std::size_t separated = 0, captured = 0, failed = 0;
  // rows per route and per integrator (the CSV's columns): what --model auto and
  // --integrator auto chose over the grid
  // (std::less<>: a row's name is looked up as a string_view, with no string made for it)
  using Tally = std::map<std::string, std::size_t, std::less<>>;
  Tally routes, integrators;
};

struct SweepOutputOptions {
  std::filesystem::path csv;  // the CSV; beside it CSV.journal and CSV.partial while running
  bool resume = false;        // continue from the journal of an interrupted run
  // Identifies the sweep in the journal (e.g. the sidecar's description of every input): a
  // journal written under another description is refused on --resume.
  std::string description;
  // Rows may complete at most this far ahead of the first unfinished one (memory bound).
  std::size_t window = 1 << 16;
  // The JSON sidecar committed with the CSV by finish_with_sidecar(); empty: none.
  std::filesystem::path sidecar = {};
  // Not null: the rows go to this stream (standard output) as they complete, after the header;
  // no journal, no partial, no resume (resume must be false), no sidecar; `csv` only names the
  // output in messages.
  std::FILE* stream = nullptr;
};

// The checksum of a journal row (with its newline), 64 bits, eight bytes of the row a step: the
// journal's lines are "index checksum row" (checksum in 16 hex digits).
std::uint64_t sweep_journal_checksum(std::string_view row);

// Finished rows on their way to a SweepSink, built by one worker: the rows' text back to back,
// and for each its point's index, its place in the text, its journal checksum and its facts
// (SweepRowFacts). A worker keeps one batch and reuses it: the sink takes a delivered batch's
// contents and hands back buffers of a batch it has written, so after the first batches no row
// allocates, and no buffer is freed on another thread than the one that allocated it.
class SweepRowBatch {
 public:
  // The text to append point `index`'s row to (its bytes from text().size() on); then end_row()
  // with the facts of the row appended (append_sweep_csv_results gives them).
  std::string& begin_row(std::size_t index);
  void end_row(const SweepRowFacts& facts);
  // A row made elsewhere (read back, or from an MPI rank): its facts are read from it by the
  // sink that receives it.
  void add(std::size_t index, std::string_view row);
  void clear();  // keeps the buffers
  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }
  std::size_t index(std::size_t k) const { return entries_[k].index; }
  std::string_view row(std::size_t k) const {
    return std::string_view(text_).substr(entries_[k].begin, entries_[k].size);
  }

 private:
  friend class SweepSink;
  // text_ holds the rows back to back, as the CSV takes them; journal_ the same rows as journal
  // lines, "index checksum row" (made by end_row, outside the sink's lock). A worker's batch
  // then goes to each file in one write.
  struct Entry {
    std::size_t index = 0;
    std::size_t begin = 0, size = 0;            // the row in text_, newline included
    std::size_t line_begin = 0, line_size = 0;  // its journal line in journal_
    SweepRowFacts facts;
    bool has_facts = false;  // false: add()ed; the sink reads them from the row
  };
  std::string text_, journal_;
  std::vector<Entry> entries_;
  std::size_t next_ = 0;  // the sink's: the first entry not yet written to the output
};

// Journal, reorder window and partial CSV of one sweep (or the reorder window and a stream).
// Thread-safe: any number of threads take() work and deliver() rows.
class SweepSink {
 public:
  // Validates the request, then opens (or, with resume, reopens) the journal and rebuilds the
  // partial CSV from the journal's checksummed rows. Throws InputError naming the flag: a bad grid,
  // --out, or --resume (an existing journal without --resume, a journal of another sweep,
  // --resume with a stream). With a stream: validates, then writes the header.
  SweepSink(const SweepRequest& request, SweepOutputOptions options);
  ~SweepSink();
  SweepSink(const SweepSink&) = delete;
  SweepSink& operator=(const SweepSink&) = delete;

  std::size_t total() const { return total_; }
  std::size_t resumed() const { return resumed_; }  // points read back from a previous run
  // Journal lines not trusted on --resume (checksum, index or inputs do not match: edited or
  // cut short); their points are computed again.
  std::size_t damaged_rows() const { return damaged_; }
  std::size_t done() const;  // resumed + delivered
  // Rows in the output so far (the partial CSV or the stream, or on their way to it: rows are
  // written a chunk at a time, and all of them by finish()): the first unfinished point's
  // index, every earlier one in order; at most done().
  std::size_t written() const;
  // Stop handing out work (a signal arrived). take() returns nothing from then on.
  void request_stop() { stop_ = true; }
  bool stop_requested() const { return stop_; }

  // What take() does while the next index is more than `window` ahead of the first unfinished
  // one: wait for the writer to catch up, or return nothing at once (a caller with other work).
  enum class WhenAhead { wait, return_empty };

  // Up to `max` indices not yet done, in increasing order. Empty and exhausted(): no work left
  // to hand out (finished or stopping).
  // `workers` > 1 (the workers that share the rest): near the end of the grid at most
  // 1/(2 workers) of the points not yet handed out, at least one, so that the workers finish
  // together rather than one waiting for another's last full batch (a 60 x 30 map's second
  // worker sat idle for 2.6 ms of a 12 ms two-thread run with batches of 32).
  std::vector<std::size_t> take(std::size_t max, WhenAhead when_ahead, std::size_t workers = 1);
  bool exhausted() const;

  // Records a finished point: appended to the journal, then to the partial CSV once every
  // earlier point is there. A point delivered twice keeps its first row. The journal line is
  // written before the call returns, or, while another thread is writing, by that thread as
  // soon as its write ends (write_pending): a SIGKILL loses at most the batches in flight.
  void deliver(std::size_t index, const std::string& row);
  // The same for a batch (e.g. a chunk from another MPI rank): one flush of the journal.
  void deliver(const std::vector<std::pair<std::size_t, std::string>>& rows);
  // The same for a worker's batch: `rows` comes back empty, with buffers to reuse.
  void deliver(SweepRowBatch& rows);
  // deliver(rows), then take(max, WhenAhead::wait) in the same hold of the lock: one lock a batch
  // for a worker that goes on (two, delivering and taking apart, met more often at the lock).
  std::vector<std::size_t> deliver_and_take(SweepRowBatch& rows, std::size_t max,
                                            std::size_t workers = 1);

  // When every point is done: `before_commit` (e.g. the sidecar), the CSV written atomically,
  // journal and partial removed; returns true. Otherwise leaves journal and partial for
  // --resume and returns false.
  bool finish(const std::function<void(const SweepCounts&)>& before_commit);
  // finish(), committing the CSV and the sidecar (options.sidecar, filled by `write_sidecar`)
  // as a pair (a SIGKILL between them once left a sidecar beside a CSV it did not describe): both
  // are written to temporaries first, then the old sidecar is removed, the CSV renamed into place
  // and the sidecar last, so a reader (or a SIGKILL at any moment) never pairs a sidecar with a CSV
  // it does not describe: at worst a CSV has no sidecar yet.
  bool finish_with_sidecar(
      const std::function<void(const SweepCounts&, std::ostream&)>& write_sidecar);
  const SweepCounts& counts() const { return counts_; }
  std::filesystem::path journal_path() const;
  // Stream output only: the stream refused a write (the reader closed the pipe: EPIPE, or a
  // full disk): the sweep stops as after request_stop(), and rows after it are dropped. The
  // errno of the failed write, 0 while the stream takes every row.
  int output_error() const { return output_errno_; }

 private:
  // finish() and finish_with_sidecar(): while points are missing, flushes journal and partial
  // for --resume and returns false; otherwise stages the CSV (a copy of the partial), calls
  // `between`, which commits it (and a sidecar around it), then removes journal and partial.
  bool commit_csv(const std::function<void(StagedFile& csv)>& between);
  SweepRowFacts facts(std::string_view row) const;
  // Outside the lock: orders the batch's entries by index (the first of a repeated index kept)
  // and reads the facts of rows that came without them.
  void prepare(SweepRowBatch& rows) const;
  // Caller holds mutex_: journals the rows not delivered before (one flush), counts them, and
  // writes what is ready; the batch's contents stay in the sink until written, `rows` gets
  // spare buffers.
  void record_batch(SweepRowBatch& rows);
  bool delivered_before(std::size_t index) const;  // caller holds mutex_
  std::vector<std::size_t> take_locked(std::unique_lock<std::mutex>& lock, std::size_t max,
                                       WhenAhead when_ahead, std::size_t workers);
  void write_ready();                                            // caller holds mutex_
  void count(std::string_view row, const SweepRowFacts& facts);  // caller holds mutex_
  // Reads the journal's rows after its header into pending_ (and the partial CSV); returns the
  // bytes of its whole lines.
  std::uintmax_t read_journal_rows(std::istream& in, const SweepRequest& request);
  void open_journal(const SweepRequest& request);  // the constructor's file work
  // Rows for the partial CSV or the stream, into output_pending_ (caller holds mutex_).
  void write_rows(std::string_view rows);
  // The files are written outside mutex_, by one thread at a time (io_mutex_): a worker that
  // delivers appends its journal lines and the rows now in order to the pending bytes under
  // mutex_ (a copy), and whichever thread holds io_mutex_ writes them. Writing under mutex_ (a
  // journal write a batch, the partial CSV a MiB at a time) blocked the other worker for 2-13 ms
  // of a 0.35 s two-thread 300 x 300 map (scheduler statistics, SweepWorkerTime), against
  // 0.4-3.6 ms for the same run to a stream with no files.
  //   Flush::due: if no thread is writing, the journal lines, and the rows once a chunk
  //   (kOutputChunk) has gathered (a stream: every delivery); Flush::all: everything, waiting for
  //   a writing thread to finish first (commit, the end of --resume's read-back).
  enum class Flush { due, all };
  void write_pending(Flush how);
  // The rows are due to be written (how, a stream, or a chunk gathered); caller holds mutex_.
  bool output_due(Flush how) const;
  bool write_due(Flush how) const;  // journal lines or due rows pending; caller holds mutex_
  void write_out();                 // caller holds io_mutex_: journal_out_, then output_out_
  static constexpr std::size_t kOutputChunk = std::size_t{1} << 20;  // a 300 x 300 map: 20 writes
  void stream_failed();  // records errno of a failed write to the stream and stops the sweep

  SweepOutputOptions options_;
  std::size_t total_ = 0;
  std::size_t resumed_ = 0;
  std::size_t damaged_ = 0;
  std::size_t axis_count_ = 0;          // scene axes: the CSV's result columns come after them
  std::array<int, 3> count_columns_{};  // the route, integrator and status columns' indices
  std::atomic<int> output_errno_{0};
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::condition_variable written_cv_;
  std::size_t cursor_ = 0;      // next index to hand out
  std::size_t next_write_ = 0;  // first index not yet in the partial CSV
  std::size_t delivered_ = 0;
  // Rows read back from the journal (--resume), waiting for earlier points; they are not
  // handed out again.
  std::map<std::size_t, std::string> resumed_rows_;
  // Delivered batches waiting for earlier points (each from its next_ entry on), and emptied
  // ones whose buffers go back to the workers (no allocation a row, none freed across threads).
  std::vector<SweepRowBatch> parked_, spare_;
  SweepCounts counts_;
  // the entries of counts_ the last row counted went to (map iterators outlive insertions)
  std::optional<SweepCounts::Tally::iterator> last_route_, last_integrator_;
  // Bytes for the journal and for the output, delivered but not yet written (guarded by
  // mutex_), and the ones being written (guarded by io_mutex_; swapped with the pending ones,
  // so their buffers are reused and no delivery allocates once they have grown).
  std::string journal_pending_, output_pending_;
  std::mutex io_mutex_;
  std::string journal_out_, output_out_;
  std::FILE* journal_ = nullptr;  // unbuffered: write_out() writes a flush's bytes at once
  std::FILE* partial_ = nullptr;
};

// One worker of run_sweep_points, timed (SweepRunOptions::workers): what tells a sweep that
// leaves its threads idle (a lock, the end of the grid) from a machine that does not give them
// a core (ivv bench's two-thread map).
struct SweepWorkerTime {
  double start = 0.0, end = 0.0;  // [s] from the sweep's start: the worker's first, last instant
  // [s] between the two, on a core and waiting for one (solver/parallel.h, thread_schedule);
  // NaN where the kernel does not say. end - start - running - waiting: blocked.
  double running = std::numeric_limits<double>::quiet_NaN();
  double waiting = std::numeric_limits<double>::quiet_NaN();
  std::size_t points = 0;  // the points it computed
};

// The points a sweep's worker computes together (SweepRunOptions::batch, run_sweep).
inline constexpr std::size_t kSweepBatchPoints = 128;

// The size of the next batch of a sweep on `workers` workers with `left` points not handed out:
// `max`, shrinking near the end of the grid to a share of what is left, left / (2 workers), at
// least one point, so that the workers end together (guided scheduling). Handing out 128
// points to the end, a worker of the 200 x 50 map (26 ms) was idle for half a batch on average.
inline std::size_t guided_batch_size(std::size_t left, std::size_t workers, std::size_t max) {
  if (workers <= 1) return std::max<std::size_t>(1, std::min(left, max));
  return std::clamp<std::size_t>(left / (2 * workers), 1, max);
}

struct SweepRunOptions {
  const std::atomic<bool>* stop = nullptr;  // set by a signal handler: stop handing out work
  // Called once for every point delivered (a batch at a time), serialised.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Points a worker takes at a time and delivers together (one lock and one journal flush); a
  // SIGKILL loses at most a batch a worker, computed again on --resume. 128 points are about
  // 0.4 ms of the paper scene's work. On the 300 x 300 map (rtol 1e-8, --model auto), against
  // 32 points: one thread 0.266 -> 0.260 s (16 alternating runs, medians; 256 points: 0.261 s),
  // as the lanes run short at the end of every batch; two threads 0.147 -> 0.138 s (10 rounds,
  // within this machine's noise), with a third of the context switches (perf stat: 100 a map ->
  // 35), each a lock one worker waited for. Near the end of the grid take() hands out less
  // (SweepSink::take), so the workers still end together.
  std::size_t batch = kSweepBatchPoints;
  // Not null: one entry a worker, filled as each ends.
  std::vector<SweepWorkerTime>* workers = nullptr;
};

// Runs every point not yet done on request.threads workers (parallel_for, one worker an index),
// each taking `batch` points at a time from `sink` and delivering their rows together.
// Returns when all points are done or a stop was requested (then the points in flight are
// finished and delivered). A throwing point ends the sweep with std::runtime_error naming it.
void run_sweep_points(const SweepRequest& request, SweepSink& sink, const SweepRunOptions& options);

}  // namespace ivv
