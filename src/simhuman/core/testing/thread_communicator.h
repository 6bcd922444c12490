#pragma once
/// For tests only: the ranks of a job as threads of one process, so that collective code
/// (core::AgreeOk, data-parallel PPO) is tested without mpirun. Sums run in rank order, as
/// the Communicator contract asks.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "simhuman/core/communicator.h"

namespace simhuman::core::testing {

/// `size` ranks sharing one state; Run() calls a function once per rank, each on its thread.
class ThreadGroup {
 public:
  explicit ThreadGroup(int size) : size_(size), blobs_(size), sums_(size) {}

  /// Runs fn(communicator of rank r) on `size` threads and joins them.
  void Run(const std::function<void(Communicator&)>& fn) {
    std::vector<std::thread> threads;
    for (int r = 0; r < size_; ++r) {
      threads.emplace_back([this, r, &fn] {
        Rank comm(this, r);
        fn(comm);
      });
    }
    for (std::thread& t : threads) t.join();
  }

 private:
  class Rank final : public Communicator {
   public:
    Rank(ThreadGroup* g, int rank) : g_(g), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return g_->size_; }
    std::string name() const override { return "threads"; }
    Status Barrier() override {
      g_->Wait();
      return absl::OkStatus();
    }
    Status AllreduceSum(float* data, int64_t n) override { return Sum(data, n); }
    Status AllreduceSum(double* data, int64_t n) override { return Sum(data, n); }
    StatusOr<std::vector<std::string>> Gather(const std::string& blob, int root) override {
      g_->blobs_[rank_] = blob;
      g_->Wait();
      std::vector<std::string> out;
      if (rank_ == root) out = g_->blobs_;
      g_->Wait();
      return out;
    }
    Status Broadcast(std::string* blob, int root) override {
      if (rank_ == root) g_->blobs_[root] = *blob;
      g_->Wait();
      *blob = g_->blobs_[root];
      g_->Wait();
      return absl::OkStatus();
    }
    void PostToRoot(std::string message) override {
      if (rank_ == 0) return;
      std::lock_guard<std::mutex> l(g_->mutex_);
      g_->posts_.emplace_back(rank_, std::move(message));
    }
    std::vector<std::pair<int, std::string>> Poll() override {
      std::vector<std::pair<int, std::string>> out;
      if (rank_ != 0) return out;
      std::lock_guard<std::mutex> l(g_->mutex_);
      out.swap(g_->posts_);
      return out;
    }
    StatusOr<std::vector<std::pair<int, std::string>>> FinishPosts() override {
      g_->Wait();
      std::vector<std::pair<int, std::string>> out = Poll();
      g_->Wait();
      return out;
    }

   private:
    template <typename T>
    Status Sum(T* data, int64_t n) {
      g_->sums_[rank_].assign(data, data + n);
      g_->Wait();
      for (int64_t i = 0; i < n; ++i) {
        T s = 0;
        for (int r = 0; r < g_->size_; ++r) s += static_cast<T>(g_->sums_[r][i]);
        data[i] = s;
      }
      g_->Wait();
      ++stats_.allreduce_calls;
      stats_.allreduce_bytes += n * static_cast<int64_t>(sizeof(T));
      return absl::OkStatus();
    }
    ThreadGroup* g_;
    int rank_;
  };

  // a reusable barrier over the ranks
  void Wait() {
    std::unique_lock<std::mutex> l(mutex_);
    const int64_t generation = generation_;
    if (++waiting_ == size_) {
      waiting_ = 0;
      ++generation_;
      cv_.notify_all();
    } else {
      cv_.wait(l, [&] { return generation != generation_; });
    }
  }

  int size_;
  std::mutex mutex_;
  std::condition_variable cv_;
  int waiting_ = 0;
  int64_t generation_ = 0;
  std::vector<std::string> blobs_;
  std::vector<std::vector<long double>> sums_;
  std::vector<std::pair<int, std::string>> posts_;
};

}  // namespace simhuman::core::testing
