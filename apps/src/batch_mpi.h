#pragma once
// `tetblend batch` over the ranks of an MPI run (mpirun, srun). Rank 0 does
// what a one-process run does (lock, journal, resume decision, summaries,
// .pvd) and hands out the pending jobs one at a time on request; the other
// ranks load the model, blend the jobs they are given, write those jobs'
// files and send each job's outcome back with their next request.
//
// Messages (all to or from rank 0):
//   start     broadcast from rank 0: the pending job indices and a hash of
//             the spec's and the model's bytes (a rank that reads other
//             bytes, e.g. a stale copy on a node, runs nothing), or "no run"
//             when rank 0 failed before handing out work;
//   request   worker -> 0: the outcome of the job it just finished (or
//             nothing), asking for another; 0 answers with a job index or -1;
//   bye       worker -> 0 once all its job threads ended: "" or why it could
//             not work at all (then rank 0 and the others do its share).
//
// Without MPI at build time, or without an MPI launcher's environment at run
// time, joinBatchWorld() returns nullptr and the batch runs as one process.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tetblend::cli {

class BatchWorld {
 public:
  virtual ~BatchWorld() = default;  ///< MPI_Finalize
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Whether several threads of this process may call requestJob (MPI
  /// thread level SERIALIZED or better).
  virtual bool threadsMayTalk() const = 0;

  /// Prints "tetblend: error: <why>" and ends every rank (MPI_Abort): rank 0
  /// failed while the others wait for work.
  [[noreturn]] virtual void abort(const std::string& why) = 0;

  // Rank 0.
  /// Broadcasts the pending job indices and `inputs` (a hash of the spec's
  /// and the model's bytes, which every rank must see alike); `ok` false: no
  /// run (rank 0 failed).
  virtual void start(bool ok, std::uint64_t inputs, const std::vector<std::int64_t>& pending) = 0;
  /// Serves the other ranks until each said bye: for a request, calls
  /// onOutcome(rank, message) when it carries one, then answers nextJob()
  /// (a job index, or -1 for "no more"); for a bye with a reason, calls
  /// onRetired(rank, reason). Polls, sleeping briefly when idle.
  virtual void serve(const std::function<std::int64_t()>& nextJob,
                     const std::function<void(int, const std::string&)>& onOutcome,
                     const std::function<void(int, const std::string&)>& onRetired) = 0;

  // Other ranks.
  /// Waits for rank 0's start; false when there is no run.
  virtual bool awaitStart(std::uint64_t& inputs, std::vector<std::int64_t>& pending) = 0;
  /// Sends `outcome` ("" for none) and returns the next job index, or -1.
  /// Thread-safe (serialised inside).
  virtual std::int64_t requestJob(const std::string& outcome) = 0;
  /// Tells rank 0 this rank is done; `reason` non-empty: it could not work.
  virtual void bye(const std::string& reason) = 0;
};

/// MPI_Init_thread and the world, when built with MPI and started by an MPI
/// launcher (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK or
/// MPI_LOCALNRANKS in the environment) with more than one rank; nullptr
/// otherwise (a one-rank world is finalised at once).
std::unique_ptr<BatchWorld> joinBatchWorld();

}  // namespace tetblend::cli
