#pragma once
// Random streams: one xoshiro256** generator per rod and per purpose (collision kick, white noise;
// also one per rough plate, drawn once when its surface is made),
// seeded from the scenario seed through splitmix64. Streams are independent of each other, so
// adding a consumer of randomness never changes the numbers another one draws, and their whole
// state is four words that a checkpoint stores.

#include <array>
#include <cmath>
#include <cstdint>

#include "engine/units.hpp"

namespace rodsort::engine {

enum class StreamPurpose : std::uint64_t {
  kCollisionKick = 1,
  kWhiteNoise = 2,
  kPlacement = 3,
  kRoughness = 4,
  kSolverOrder = 5  ///< per step (index = step): the order of the contacts in each solver sweep
};

class RandomStream {
 public:
  using State = std::array<std::uint64_t, 4>;

  RandomStream(std::uint64_t seed, std::uint64_t index, StreamPurpose purpose) {
    std::uint64_t mix = seed ^ (0x9e3779b97f4a7c15ULL * (index + 1)) ^
                        (0xd1b54a32d192ed03ULL * static_cast<std::uint64_t>(purpose));
    for (auto& word : state_) word = splitmix64(mix);
  }
  explicit RandomStream(const State& state) : state_(state) {}

  const State& state() const { return state_; }

  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// +1 or -1 with equal probability.
  double sign() { return (next() >> 63) != 0 ? 1.0 : -1.0; }

  /// Standard normal variate (Box-Muller; one of the pair is dropped so that the state stays
  /// four words).
  double normal() {
    const double u1 = 1.0 - uniform();  // in (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  State state_{};
};

}  // namespace rodsort::engine
