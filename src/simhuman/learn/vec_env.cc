#include "simhuman/learn/vec_env.h"

#include <algorithm>
#include <cstring>

#include "simhuman/core/check.h"
#include "simhuman/core/rng.h"

namespace simhuman::learn {

WorkerPool::WorkerPool(int threads) {
  for (int t = 1; t < std::max(1, threads); ++t) workers_.emplace_back([this] { Loop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  cv_.notify_all();
  for (auto& w : workers_) w.join();
}

void WorkerPool::RunChunk() {
  while (true) {
    int i;
    {
      std::lock_guard<std::mutex> lock(mu_);
      if (next_ >= n_) return;
      i = next_++;
    }
    (*fn_)(i);
  }
}

void WorkerPool::Loop() {
  uint64_t seen = 0;
  while (true) {
    {
      std::unique_lock<std::mutex> lock(mu_);
      cv_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      ++busy_;
    }
    RunChunk();
    {
      std::lock_guard<std::mutex> lock(mu_);
      --busy_;
    }
    done_cv_.notify_all();
  }
}

void WorkerPool::ParallelFor(int n, const std::function<void(int)>& fn) {
  if (workers_.empty()) {
    for (int i = 0; i < n; ++i) fn(i);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mu_);
    fn_ = &fn;
    n_ = n;
    next_ = 0;
    ++generation_;
  }
  cv_.notify_all();
  RunChunk();
  std::unique_lock<std::mutex> lock(mu_);
  done_cv_.wait(lock, [&] { return next_ >= n_ && busy_ == 0; });
  fn_ = nullptr;
}

VecEnv::VecEnv(std::unique_ptr<VecTask> task, int threads, uint64_t seed)
    : task_(std::move(task)), pool_(threads), seed_(seed) {
  const int e = task_->num_envs();
  obs_.assign(static_cast<size_t>(e) * task_->obs_dim(), 0.f);
  terminal_obs_ = obs_;
  rewards_.assign(e, 0.f);
  terminated_.assign(e, 0);
  truncated_.assign(e, 0);
  ended_.assign(e, 0);
  ep_ret_.assign(e, 0.0);
  ep_len_.assign(e, 0);
  ep_count_.assign(e, 0);
  ep_done_.assign(e, EpisodeStats());
}

uint64_t VecEnv::episodes_started() const {
  uint64_t n = 0;
  for (uint64_t c : ep_count_) n += c;
  return n;
}

void VecEnv::ResetAll(uint64_t episode_base) {
  const int d = obs_dim();
  pool_.ParallelFor(num_envs(), [&](int i) {
    ep_count_[i] = episode_base;
    task_->Reset(i, core::DeriveSeed(seed_, static_cast<uint64_t>(i), ep_count_[i]++),
                 obs_.data() + static_cast<size_t>(i) * d);
    ep_ret_[i] = 0;
    ep_len_[i] = 0;
    if (amp_dim_ > 0) task_->AmpFeatures(i, amp_cur_.data() + static_cast<size_t>(i) * amp_dim_);
  });
}

absl::Status VecEnv::EnableAmp() {
  const int f = task_->amp_feature_dim();
  if (f <= 0) {
    return absl::UnimplementedError("task '" + task_->name() +
                                    "' has no AMP features; AMP needs the walk task");
  }
  amp_dim_ = f;
  amp_cur_.assign(static_cast<size_t>(num_envs()) * f, 0.f);
  amp_pairs_.assign(static_cast<size_t>(num_envs()) * 2 * f, 0.f);
  return absl::OkStatus();
}

void VecTask::AmpFeatures(int, float*) {
  SH_CHECK(false, "AmpFeatures called on a task without AMP features");
}

core::StatusOr<std::vector<float>> VecTask::AmpClipFeatures(const MotionClip&) const {
  return absl::UnimplementedError("task '" + name() +
                                  "' has no AMP features; AMP needs the walk task");
}

void VecEnv::StepOne(int i, const float* action) {
  const int d = obs_dim();
  float* o = obs_.data() + static_cast<size_t>(i) * d;
  StepInfo info;
  task_->Step(i, action, o, &info);
  rewards_[i] = info.reward;
  terminated_[i] = info.terminated;
  truncated_[i] = info.truncated && !info.terminated;
  ep_ret_[i] += info.reward;
  ++ep_len_[i];
  ended_[i] = info.terminated || info.truncated;
  if (amp_dim_ > 0) {
    const size_t f = static_cast<size_t>(amp_dim_);
    float* pair = amp_pairs_.data() + i * 2 * f;
    float* cur = amp_cur_.data() + i * f;
    std::memcpy(pair, cur, sizeof(float) * f);
    task_->AmpFeatures(i, pair + f);
    std::memcpy(cur, pair + f, sizeof(float) * f);
  }
  if (ended_[i]) {
    std::memcpy(terminal_obs_.data() + static_cast<size_t>(i) * d, o, sizeof(float) * d);
    ep_done_[i] = EpisodeStats{ep_ret_[i], ep_len_[i], info.success, info.terminated};
    task_->Reset(i, core::DeriveSeed(seed_, static_cast<uint64_t>(i), ep_count_[i]++), o);
    if (amp_dim_ > 0) task_->AmpFeatures(i, amp_cur_.data() + static_cast<size_t>(i) * amp_dim_);
    ep_ret_[i] = 0;
    ep_len_[i] = 0;
  }
}

void VecEnv::CollectFinished() {
  finished_.clear();
  for (int i = 0; i < num_envs(); ++i) {
    if (ended_[i]) finished_.push_back(ep_done_[i]);
  }
}

void VecEnv::Step(const float* actions) {
  const int a = act_dim();
  pool_.ParallelFor(num_envs(), [&](int i) { StepOne(i, actions + static_cast<size_t>(i) * a); });
  CollectFinished();
}

void VecEnv::StepChunked(const ChunkPolicy& policy, int chunks) {
  const int e = num_envs(), a = act_dim();
  chunks = std::clamp(chunks, 1, e);
  chunk_actions_.resize(static_cast<size_t>(e) * a);
  pool_.ParallelFor(chunks, [&](int c) {
    const int begin = static_cast<int>(static_cast<int64_t>(e) * c / chunks);
    const int end = static_cast<int>(static_cast<int64_t>(e) * (c + 1) / chunks);
    policy(begin, end, obs_.data(), chunk_actions_.data());
    for (int i = begin; i < end; ++i)
      StepOne(i, chunk_actions_.data() + static_cast<size_t>(i) * a);
  });
  CollectFinished();
}

}  // namespace simhuman::learn
