#pragma once

#include <cstdint>

namespace steerseg::speed {

// SplitMix64 (Steele, Lea, Flood 2014): the same numbers on every compiler and library, which
// the standard engines' distributions do not promise, so a seed gives the same forest and the
// same samples everywhere.
class SplitMix {
  public:
    explicit SplitMix(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31U);
    }
    // Uniform in [0, n) for n > 0 (the modulo bias is below 2^-40 for the counts used here).
    std::uint64_t below(std::uint64_t n) { return next() % n; }

  private:
    std::uint64_t state_;
};

} // namespace steerseg::speed
