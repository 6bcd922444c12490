#pragma once
/// Seeded random numbers. No global generator: stochastic code takes an Rng& or a seed.

#include <cstdint>
#include <random>

namespace simhuman::core {

/// Mixes a run seed with stream indices (iteration, rollout, ...) into an independent seed, so
/// results do not depend on thread scheduling. Pure function (splitmix64 based).
uint64_t DeriveSeed(uint64_t seed, uint64_t a, uint64_t b = 0, uint64_t c = 0);

/// A small seeded generator. Not thread-safe: one per thread or per stream.
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double Uniform(double lo = 0.0, double hi = 1.0) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  /// Normal with mean 0 and standard deviation `stddev`.
  double Normal(double stddev = 1.0) {
    return std::normal_distribution<double>(0.0, stddev)(engine_);
  }
  /// Uniform integer in [lo, hi].
  int UniformInt(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace simhuman::core
