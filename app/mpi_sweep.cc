#include "app/mpi_sweep.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "solver/parallel.h"

namespace ivv::mpi {
namespace {

enum Tag : int {
  kRequest = 1,  // rank -> 0: rows of a finished chunk ("index row" lines), and an order for
                 // one more chunk
  kWork = 2,     // 0 -> rank: indices (uint64); none means: no more work
  kFinal = 3,    // rank -> 0: rows of its last chunk; the rank is done
  kError = 4,    // rank -> 0: a point threw; the message names it; the rank is done
};

// Open MPI's blocking calls poll without sleeping: a rank waiting for an answer would take a
// core from the threads that compute. These wait by polling every 200 us instead.
constexpr auto kPollInterval = std::chrono::microseconds(200);

MPI_Status wait_for_message(int source, int tag) {
  MPI_Status status;
  for (int flag = 0;;) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(kPollInterval);
  }
}

void wait_for(MPI_Request& request) {
  for (int flag = 0;;) {
    MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
    if (flag) return;
    std::this_thread::sleep_for(kPollInterval);
  }
}

std::string receive_text(int source, int tag, MPI_Status* status) {
  MPI_Status probe = wait_for_message(source, tag);
  int count = 0;
  MPI_Get_count(&probe, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, probe.MPI_SOURCE, probe.MPI_TAG, MPI_COMM_WORLD,
           status ? status : MPI_STATUS_IGNORE);
  return text;
}

void send_text(const std::string& text, int dest, int tag) {
  MPI_Request request;
  MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD,
            &request);
  wait_for(request);
}

void send_work(const std::vector<std::size_t>& indices, int dest) {
  std::vector<std::uint64_t> v(indices.begin(), indices.end());
  MPI_Request request;
  MPI_Isend(v.data(), static_cast<int>(v.size()), MPI_UINT64_T, dest, kWork, MPI_COMM_WORLD,
            &request);
  wait_for(request);
}

// Rows come back as "index row\n" lines; a row itself contains no newline. Returns how many.
std::size_t deliver_lines(const std::string& text, SweepSink& sink) {
  std::vector<std::pair<std::size_t, std::string>> rows;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t space = text.find(' ', pos), end = text.find('\n', pos);
    if (space == std::string::npos || end == std::string::npos || space > end)
      throw std::runtime_error("a malformed row came back from an MPI rank");
    rows.emplace_back(std::stoull(text.substr(pos, space - pos)),
                      text.substr(space + 1, end - space));
    pos = end + 1;
  }
  sink.deliver(rows);
  return rows.size();
}

std::vector<std::uint64_t> receive_work() {
  MPI_Status probe = wait_for_message(0, kWork);
  int count = 0;
  MPI_Get_count(&probe, MPI_UINT64_T, &count);
  std::vector<std::uint64_t> chunk(static_cast<std::size_t>(count));
  MPI_Recv(chunk.data(), count, MPI_UINT64_T, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return chunk;
}

// The rank's side: keep one chunk on order while computing another (so that the answer is
// there when the chunk is done), send each chunk's rows with the next order, until rank 0
// says there is no more work.
void serve_as_worker(const SweepRequest& req) {
  send_text("", 0, kRequest);
  std::vector<std::uint64_t> chunk = receive_work();
  std::string rows;  // of the previous chunk
  while (!chunk.empty()) {
    send_text(rows, 0, kRequest);
    std::vector<std::string> out(chunk.size());
    try {
      // No stop flag: rank 0 decides when to stop; a chunk in flight is always finished.
      parallel_for(chunk.size(), req.threads,
                   [&](std::size_t j) { out[j] = run_sweep_point(req, chunk[j]); });
    } catch (const ParallelError& e) {
      std::string what = e.what();
      try {
        std::rethrow_exception(e.cause());
      } catch (const std::exception& cause) {
        what = cause.what();
      } catch (...) {
      }
      send_text(what, 0, kError);  // rank 0 stops handing out work, then answers the order
      receive_work();              // (dropped: the sweep ends with the error)
      return;
    }
    rows.clear();
    for (std::size_t j = 0; j < chunk.size(); ++j) rows += std::to_string(chunk[j]) + ' ' + out[j];
    chunk = receive_work();
  }
  send_text(rows, 0, kFinal);
}

// Rank 0's main thread: hands chunks to the other `ranks` ranks and delivers their rows to
// the sink (polling, so that it does not spin a core that workers need), until each has sent
// its final rows or an error. `delivered(rank, rows)` is called after each delivery. Returns the
// first error a rank reported ("" when none); throws when the sink cannot write.
std::string answer_ranks(int ranks, SweepSink& sink, const SweepRunOptions& options,
                         std::size_t chunk,
                         const std::function<void(int, std::size_t)>& delivered) {
  std::string remote_error;
  int active = ranks;
  std::deque<int> waiting;  // ranks that asked while the reorder window was full
  auto answer = [&](int rank) {
    const std::vector<std::size_t> work = sink.take(chunk, SweepSink::WhenAhead::return_empty);
    if (work.empty() && !sink.exhausted()) return false;  // window full: ask again later
    send_work(work, rank);
    return true;
  };
  while (active > 0) {
    if (options.stop && *options.stop) sink.request_stop();
    for (std::size_t n = waiting.size(); n > 0; --n) {
      const int rank = waiting.front();
      waiting.pop_front();
      if (!answer(rank)) waiting.push_back(rank);
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    const std::string text = receive_text(status.MPI_SOURCE, status.MPI_TAG, nullptr);
    if (status.MPI_TAG == kError) {
      if (remote_error.empty()) remote_error = text;
      sink.request_stop();
      --active;
      continue;
    }
    delivered(status.MPI_SOURCE, deliver_lines(text, sink));
    if (status.MPI_TAG == kFinal)
      --active;
    else if (!answer(status.MPI_SOURCE))
      waiting.push_back(status.MPI_SOURCE);
  }
  return remote_error;
}

// Rank 0: its own threads take chunks from the sink like any rank, while the main thread
// answers the other ranks (polling, so that it does not spin a core that workers need).
std::vector<std::size_t> coordinate(World& world, const SweepRequest& req, SweepSink& sink,
                                    const SweepRunOptions& options, std::size_t chunk) {
  std::mutex progress_mutex;
  std::vector<std::size_t> computed(static_cast<std::size_t>(world.size()), 0);
  SweepRunOptions local = options;
  local.batch = std::min(chunk, options.batch);
  local.progress = [&](std::size_t done, std::size_t total) {
    std::lock_guard lock(progress_mutex);
    if (options.progress) options.progress(done, total);
  };
  SweepRunOptions own_options = local;
  own_options.progress = [&](std::size_t done, std::size_t total) {
    {
      std::lock_guard lock(progress_mutex);
      ++computed[0];
    }
    local.progress(done, total);
  };
  std::exception_ptr local_error;
  std::thread own([&] {
    try {
      run_sweep_points(req, sink, own_options);
    } catch (...) {
      local_error = std::current_exception();
      sink.request_stop();
    }
  });

  std::string remote_error;
  try {
    remote_error =
        answer_ranks(world.size() - 1, sink, options, chunk, [&](int rank, std::size_t rows) {
          {
            std::lock_guard lock(progress_mutex);
            computed[static_cast<std::size_t>(rank)] += rows;
          }
          if (rows) local.progress(sink.done(), sink.total());
        });
  } catch (const std::exception& e) {
    // The output could not be written: the ranks still computing cannot be told through the
    // protocol, so the job ends here (the journal keeps what was finished).
    sink.request_stop();
    own.join();
    std::fprintf(stderr, "ivv: failed: %s\n", e.what());
    world.abort(1);
  }
  own.join();
  if (!remote_error.empty()) throw std::runtime_error(remote_error);
  if (local_error) std::rethrow_exception(local_error);
  return computed;
}

}  // namespace

bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

World::World() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

World::~World() {
  MPI_Finalize();
}

int World::agree_on_start(int exit_code) {
  MPI_Bcast(&exit_code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return exit_code;
}

void World::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

std::vector<std::size_t> run_sweep_ranks(World& world, const SweepRequest& req, SweepSink* sink,
                                         const SweepRunOptions& options) {
  // Chunks of up to 1024 points (~0.1-1 s of work at 0.1-1 ms a point): messages and the
  // service loop's 1 ms polling cost little against them, even on a loaded machine, and
  // eight chunks per worker keep the slowest one from holding up the end of the sweep.
  const std::size_t workers = static_cast<std::size_t>(world.size()) *
                              static_cast<std::size_t>(worker_count(point_count(req), req.threads));
  const std::size_t chunk = std::clamp<std::size_t>(point_count(req) / (8 * workers), 1, 1024);
  if (world.rank() == 0) return coordinate(world, req, *sink, options, chunk);
  serve_as_worker(req);
  return {};
}

}  // namespace ivv::mpi
