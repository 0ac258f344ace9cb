// A small random number generator whose sequence is the same on every
// platform and compiler (the distributions of <random> are not), for
// generated assets and lab scenes that must be reproducible.
//
//   rl::SplitMix64 random(seed);  // the same sequence on every platform
//   const double angle = random.uniform(0.0, 6.28318);  // uniform in [0, 2 pi)
//   const std::uint64_t bits = random.next();
#pragma once

#include <cstdint>

namespace rl {

// SplitMix64 (Steele, Lea and Flood, 2014).
class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1), from the top 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }

  private:
    std::uint64_t state_;
};

}  // namespace rl
