// A sweep across MPI ranks (`mpirun -np N ivv sweep ...`). The header keeps <mpi.h> out of
// its users; only the `ivv_mpi` target links Open MPI.
//
// Rank 0 owns the output (journal, partial CSV, the final CSV and its sidecar) and hands out
// points in chunks on request (dynamic balancing: a point's cost varies 100x across a grid);
// it also computes with its own threads. The other ranks ask for a chunk, compute it with
// their threads and send the rows back with the next request. The CSV is byte-identical to a
// single-process run because rows are placed by index, never by arrival.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "solver/sweep/sweep.h"

namespace ivv::mpi {

// True when this process was started by mpirun/mpiexec (Open MPI or a PMI launcher). Without
// it MPI is never initialised, so the same binary runs alone as before.
bool launched_by_mpirun();

// MPI_Init_thread on construction (FUNNELED: only the main thread calls MPI), MPI_Finalize on
// destruction.
class World {
 public:
  World();
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rank 0 tells the others whether it could open its output (`exit_code` 0) or not: every
  // rank returns rank 0's exit code, so the others do not wait for work that never comes.
  int agree_on_start(int exit_code);
  // Ends every rank now with `code` (after an error that the protocol cannot report).
  [[noreturn]] void abort(int code);

 private:
  int rank_ = 0, size_ = 1;
};

// Runs the sweep across the ranks of `world`. On rank 0 `sink` receives every row (others:
// nullptr). Returns when every point is done or (rank 0) a stop was requested and the chunks
// in flight came back. A point that throws on any rank ends the sweep (every rank stops) and
// rank 0 throws std::runtime_error naming the point. An output that cannot be written ends
// the job with MPI_Abort. Returns (rank 0) the number of points each rank
// computed in this run, so the balance can be seen; other ranks: empty.
std::vector<std::size_t> run_sweep_ranks(World& world, const SweepRequest& request, SweepSink* sink,
                                         const SweepRunOptions& options);

}  // namespace ivv::mpi
