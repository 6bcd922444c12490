#pragma once
/// The processes of one job (MPI ranks) as a small interface with no MPI in it: rank, size,
/// barrier, sums over all ranks, a gather of byte blobs to one rank, a broadcast, and
/// non-blocking progress messages to rank 0. `SerialCommunicator` is the one-process job;
/// the Open MPI implementation lives in dist/ (dist/mpi_communicator.h) and only app/ creates
/// it, so modules take a `Communicator&` and never include mpi.h.
///
/// Collective calls (Barrier, AllreduceSum, Gather, Broadcast, AgreeOk, CheckSameOnAllRanks,
/// FinishPosts) must be made by every rank in the same order; a rank that skips one makes
/// the others wait. Code that may fail on one rank only therefore decides together with
/// AgreeOk before the next collective. Thread-safety: one thread per process calls it.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::core {

/// What the communication of a job cost so far on this rank.
struct CommStats {
  int64_t allreduce_calls = 0;
  int64_t allreduce_bytes = 0;  ///< payload bytes passed to AllreduceSum (per rank)
  double allreduce_s = 0;       ///< wall time inside AllreduceSum, waits for other ranks included
};

/// The ranks of one job. See the file comment for the rules of collective calls.
class Communicator {
 public:
  virtual ~Communicator() = default;
  /// This process's rank, 0 .. size()-1.
  virtual int rank() const = 0;
  /// Number of ranks (1 for a process started without mpirun).
  virtual int size() const = 0;
  /// "serial" or the MPI library's version line.
  virtual std::string name() const = 0;
  /// Waits until every rank has called it, without keeping a core busy (a rank that has no
  /// work left calls it before the next collective).
  virtual Status Barrier() = 0;
  /// In place: every rank's `data[0..n)` becomes the element-wise sum over ranks. The order of
  /// the sum depends only on size(), so the same inputs give the same bits.
  virtual Status AllreduceSum(float* data, int64_t n) = 0;
  virtual Status AllreduceSum(double* data, int64_t n) = 0;
  /// On `root`: every rank's `blob`, in rank order; on the others: an empty vector.
  virtual StatusOr<std::vector<std::string>> Gather(const std::string& blob, int root) = 0;
  /// `*blob` of `root` replaces `*blob` on every rank.
  virtual Status Broadcast(std::string* blob, int root) = 0;
  /// Sends `message` to rank 0 without waiting (rank 0 posting to itself is a no-op). The
  /// message is delivered when rank 0 calls Poll or FinishPosts.
  virtual void PostToRoot(std::string message) = 0;
  /// On rank 0: the posted messages that have arrived, as (source rank, message); never waits.
  /// On the other ranks: empty.
  virtual std::vector<std::pair<int, std::string>> Poll() = 0;
  /// Collective: completes every PostToRoot. Rank 0 gets the messages Poll has not returned
  /// yet (the others get an empty vector).
  virtual StatusOr<std::vector<std::pair<int, std::string>>> FinishPosts() = 0;
  /// Communication cost of this rank so far.
  const CommStats& stats() const { return stats_; }

 protected:
  CommStats stats_;
};

/// The job of one process: rank 0 of 1; collectives return at once, sums are the identity.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::string name() const override { return "serial"; }
  Status Barrier() override { return absl::OkStatus(); }
  Status AllreduceSum(float* data, int64_t n) override;
  Status AllreduceSum(double* data, int64_t n) override;
  StatusOr<std::vector<std::string>> Gather(const std::string& blob, int root) override;
  Status Broadcast(std::string* blob, int root) override;
  void PostToRoot(std::string) override {}
  std::vector<std::pair<int, std::string>> Poll() override { return {}; }
  StatusOr<std::vector<std::pair<int, std::string>>> FinishPosts() override {
    return std::vector<std::pair<int, std::string>>{};
  }
};

/// Collective: OK when `local` is OK on every rank; otherwise every rank returns the error of
/// the lowest failing rank (its code, its message prefixed with "rank R: " when the job has
/// more than one rank), so all ranks stop together instead of waiting for each other.
Status AgreeOk(Communicator& comm, const Status& local);

/// Collective: InvalidArgument on every rank unless `value` is the same on all ranks. The
/// message names `what` and the ranks that differ from rank 0, with their 64-bit hashes.
Status CheckSameOnAllRanks(Communicator& comm, const std::string& what, const std::string& value);

/// FNV-1a 64-bit hash of `bytes`, as 16 hex digits.
std::string HashHex(const std::string& bytes);

/// HashHex of the file at `path` (e.g. /proc/self/exe). NotFound naming the path if unreadable.
StatusOr<std::string> FileHashHex(const std::string& path);

}  // namespace simhuman::core
