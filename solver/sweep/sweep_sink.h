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

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <istream>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "solver/result.h"
#include "solver/sweep/sweep_grid.h"

namespace ivv {

class StagedFile;  // solver/atomic_file.h

struct SweepCounts {
  std::size_t separated = 0, captured = 0, failed = 0;
  // rows per route and per integrator (the CSV's columns): what --model auto and
  // --integrator auto chose over the grid
  // (std::less<>: a row's name is looked up as a string_view, with no string made for it)
  std::map<std::string, std::size_t, std::less<>> routes, integrators;
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
  // Rows in the output so far (the partial CSV or the stream): the first unfinished point's
  // index, every earlier one written in order; at most done().
  std::size_t written() const;
  // Stop handing out work (a signal arrived). take() returns nothing from then on.
  void request_stop() { stop_ = true; }
  bool stop_requested() const { return stop_; }

  // What take() does while the next index is more than `window` ahead of the first unfinished
  // one: wait for the writer to catch up, or return nothing at once (a caller with other work).
  enum class WhenAhead { wait, return_empty };

  // Up to `max` indices not yet done, in increasing order. Empty and exhausted(): no work left
  // to hand out (finished or stopping).
  std::vector<std::size_t> take(std::size_t max, WhenAhead when_ahead);
  bool exhausted() const;

  // Records a finished point: appended to the journal (flushed), then written to the partial
  // CSV once every earlier point is written.
  void deliver(std::size_t index, const std::string& row);
  // The same for a batch (e.g. a chunk from another MPI rank): one flush of the journal. The
  // rows are moved into the sink.
  void deliver(std::vector<std::pair<std::size_t, std::string>> rows);
  // deliver(rows), then take(max, WhenAhead::wait) in the same hold of the lock: one lock a batch
  // for a worker that goes on (two, delivering and taking apart, met more often at the lock).
  std::vector<std::size_t> deliver_and_take(std::vector<std::pair<std::size_t, std::string>> rows,
                                            std::size_t max);

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
  // What the counts take from a row: where its route and integrator are, and its status.
  struct RowFacts {
    std::size_t route = 0, route_size = 0, integrator = 0, integrator_size = 0;
    ImpactStatus status = ImpactStatus::failed;
  };
  // A finished row with its journal line's head ("index checksum ") and its facts, made before
  // the lock is taken.
  struct PreparedRow {
    std::size_t index = 0;
    std::string row;
    std::array<char, 48> head{};
    std::size_t head_size = 0;
    RowFacts facts;
  };
  RowFacts facts(const std::string& row) const;
  PreparedRow prepare(std::size_t index, std::string row) const;
  std::vector<PreparedRow> prepare(std::vector<std::pair<std::size_t, std::string>> rows) const;
  void record_batch(std::vector<PreparedRow>& rows);  // caller holds mutex_; flushes
  std::vector<std::size_t> take_locked(std::unique_lock<std::mutex>& lock, std::size_t max,
                                       WhenAhead when_ahead);
  void write_ready();                                         // caller holds mutex_
  void record(PreparedRow&& row);                             // caller holds mutex_
  void count(const std::string& row, const RowFacts& facts);  // caller holds mutex_
  // Reads the journal's rows after its header into pending_ (and the partial CSV); returns the
  // bytes of its whole lines.
  std::uintmax_t read_journal_rows(std::istream& in, const SweepRequest& request);
  void open_journal(const SweepRequest& request);  // the constructor's file work
  void write_row(const std::string& row);          // to the partial CSV or the stream
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
  std::map<std::size_t, std::string> pending_;  // finished, waiting for earlier points
  bool wrote_ = false;  // record() wrote a row directly since write_ready() last notified
  SweepCounts counts_;
  std::FILE* journal_ = nullptr;
  std::FILE* partial_ = nullptr;
  std::vector<char> journal_buffer_, partial_buffer_;  // their stdio buffers (setvbuf)
};

struct SweepRunOptions {
  const std::atomic<bool>* stop = nullptr;  // set by a signal handler: stop handing out work
  // Called once for every point delivered (a batch at a time), serialised.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Points a worker takes at a time and delivers together (one lock and one journal flush):
  // 32 points are about 0.4 ms of the paper scene's work; a SIGKILL loses at most a batch a
  // worker, computed again on --resume.
  std::size_t batch = 32;
};

// Runs every point not yet done on request.threads workers (parallel_for, one worker an index),
// each taking `batch` points at a time from `sink` and delivering their rows together.
// Returns when all points are done or a stop was requested (then the points in flight are
// finished and delivered). A throwing point ends the sweep with std::runtime_error naming it.
void run_sweep_points(const SweepRequest& request, SweepSink& sink, const SweepRunOptions& options);

}  // namespace ivv
