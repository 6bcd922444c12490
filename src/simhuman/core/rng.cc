#include "simhuman/core/rng.h"

namespace simhuman::core {
namespace {
uint64_t SplitMix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
}  // namespace

uint64_t DeriveSeed(uint64_t seed, uint64_t a, uint64_t b, uint64_t c) {
  uint64_t h = SplitMix(seed);
  h = SplitMix(h ^ a);
  h = SplitMix(h ^ (b * 0x632be59bd9b4e019ULL));
  h = SplitMix(h ^ (c * 0x8cb92ba72f3d8dd7ULL));
  return h;
}

}  // namespace simhuman::core
