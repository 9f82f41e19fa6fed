#include "engine/state.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/fingerprint.hpp"

namespace rodsort::engine {
namespace {

constexpr char kMagic[8] = {'R', 'O', 'D', 'S', 'T', 'A', 'T', '1'};

template <typename T>
void put(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
void get(std::istream& in, T& value) {
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw std::runtime_error("state stream is truncated");
}

}  // namespace

void write_state(std::ostream& out, const State& state) {
  out.write(kMagic, sizeof kMagic);
  put(out, state.time);
  put(out, state.step);
  put(out, static_cast<std::uint64_t>(state.rods.size()));
  for (const RodState& rod : state.rods) {
    put(out, rod.position);
    put(out, rod.basis);
    put(out, rod.velocity);
    put(out, rod.angular_velocity);
    put(out, rod.image);
    const std::uint8_t touching =
        static_cast<std::uint8_t>((rod.touching[0] ? 1 : 0) | (rod.touching[1] ? 2 : 0));
    put(out, touching);
    put(out, rod.kick_rng);
    put(out, rod.noise_rng);
  }
}

State read_state(std::istream& in) {
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    throw std::runtime_error("not a rodsort state (bad magic)");
  }
  State state;
  std::uint64_t count = 0;
  get(in, state.time);
  get(in, state.step);
  get(in, count);
  constexpr std::uint64_t kMaxRods = 100'000'000;
  if (count > kMaxRods) throw std::runtime_error("state claims an absurd number of rods");
  state.rods.resize(count);
  for (RodState& rod : state.rods) {
    get(in, rod.position);
    get(in, rod.basis);
    get(in, rod.velocity);
    get(in, rod.angular_velocity);
    get(in, rod.image);
    std::uint8_t touching = 0;
    get(in, touching);
    rod.touching = {(touching & 1) != 0, (touching & 2) != 0};
    get(in, rod.kick_rng);
    get(in, rod.noise_rng);
  }
  return state;
}

std::uint64_t hash_state(const State& state) {
  std::ostringstream bytes;
  write_state(bytes, state);
  return fingerprint(bytes.str());
}

void check_state(const State& state, std::size_t rod_count) {
  if (state.rods.size() != rod_count) {
    throw std::invalid_argument("the state has " + std::to_string(state.rods.size()) +
                                " rods, the model " + std::to_string(rod_count));
  }
  if (!std::isfinite(state.time) || state.time < 0.0 || state.step < 0) {
    throw std::invalid_argument("the state's time (" + std::to_string(state.time) +
                                " s) or step (" + std::to_string(state.step) +
                                ") is negative or not finite");
  }
  const auto all_finite = [](const auto& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  };
  for (std::size_t i = 0; i < state.rods.size(); ++i) {
    const RodState& rod = state.rods[i];
    const std::string which = "rod " + std::to_string(i) + " of the state";
    if (!all_finite(rod.position)) throw std::invalid_argument(which + ": position not finite");
    if (!all_finite(rod.velocity) || !all_finite(rod.angular_velocity)) {
      throw std::invalid_argument(which + ": velocity not finite");
    }
    // Rows of a rotation matrix are orthonormal: R R^T = I, to rounding.
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        double dot = 0.0;
        for (int k = 0; k < 3; ++k) dot += rod.basis[3 * a + k] * rod.basis[3 * b + k];
        if (!(std::abs(dot - (a == b ? 1.0 : 0.0)) < 1e-9)) {
          throw std::invalid_argument(which + ": its frame (basis) is not a rotation");
        }
      }
    }
  }
}

}  // namespace rodsort::engine
