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

constexpr char kMagic[8] = {'R', 'O', 'D', 'S', 'T', 'A', 'T', '2'};

template <typename T>
void put(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
void get(std::istream& in, T& value) {
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw std::runtime_error("state stream is truncated");
}

void put_point(std::ostream& out, const ContactPointState& point) {
  put(out, point.local_a);
  put(out, point.local_b);
  put(out, point.world_a);
  put(out, point.world_b);
  put(out, point.normal);
  put(out, point.friction_dir1);
  put(out, point.friction_dir2);
  put(out, point.distance);
  put(out, point.combined);
  put(out, point.solver);
  put(out, point.ids);
}

void get_point(std::istream& in, ContactPointState& point) {
  get(in, point.local_a);
  get(in, point.local_b);
  get(in, point.world_a);
  get(in, point.world_b);
  get(in, point.normal);
  get(in, point.friction_dir1);
  get(in, point.friction_dir2);
  get(in, point.distance);
  get(in, point.combined);
  get(in, point.solver);
  get(in, point.ids);
}

/// Bullet's manifolds hold at most four points.
constexpr std::uint32_t kMaxPointsPerManifold = 4;

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
  put(out, static_cast<std::uint64_t>(state.contacts.size()));
  for (const SurfaceContactState& contact : state.contacts) {
    put(out, contact.rod);
    put(out, contact.surface);
    put(out, contact.sphere);
    put(out, static_cast<std::uint32_t>(contact.points.size()));
    for (const ContactPointState& point : contact.points) put_point(out, point);
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
  std::uint64_t contact_count = 0;
  get(in, contact_count);
  // A sphere has at most one manifold with each plate and wall; bounding by 1000 per rod keeps a
  // corrupt count from allocating without limit (the contacts themselves are checked later).
  if (contact_count > 1000 * std::max<std::uint64_t>(count, 1)) {
    throw std::runtime_error("state claims an absurd number of contacts");
  }
  state.contacts.resize(contact_count);
  for (SurfaceContactState& contact : state.contacts) {
    get(in, contact.rod);
    get(in, contact.surface);
    get(in, contact.sphere);
    std::uint32_t points = 0;
    get(in, points);
    if (points == 0 || points > kMaxPointsPerManifold) {
      throw std::runtime_error("state has a contact manifold of " + std::to_string(points) +
                               " points (1 to 4 expected)");
    }
    contact.points.resize(points);
    for (ContactPointState& point : contact.points) get_point(in, point);
  }
  return state;
}

std::uint64_t hash_state(const State& state) {
  std::ostringstream bytes;
  write_state(bytes, state);
  return fingerprint(bytes.str());
}

void check_state(const State& state, std::size_t rod_count, int surface_count,
                 const std::vector<int>& sphere_counts) {
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
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    const SurfaceContactState& contact = state.contacts[k];
    const std::string which = "contact " + std::to_string(k) + " of the state";
    if (contact.rod < 0 || static_cast<std::size_t>(contact.rod) >= rod_count ||
        contact.surface < 0 || contact.surface >= surface_count || contact.sphere < 0 ||
        contact.sphere >= sphere_counts.at(static_cast<std::size_t>(contact.rod))) {
      throw std::invalid_argument(which + ": rod " + std::to_string(contact.rod) + ", surface " +
                                  std::to_string(contact.surface) + ", sphere " +
                                  std::to_string(contact.sphere) + " do not exist in the model");
    }
    if (k > 0 && !comes_before(state.contacts[k - 1], contact)) {
      throw std::invalid_argument(which + ": out of order or repeated");
    }
    if (contact.points.empty() || contact.points.size() > kMaxPointsPerManifold) {
      throw std::invalid_argument(which + ": " + std::to_string(contact.points.size()) +
                                  " points (1 to 4 expected)");
    }
    for (const ContactPointState& point : contact.points) {
      const bool finite = all_finite(point.local_a) && all_finite(point.local_b) &&
                          all_finite(point.world_a) && all_finite(point.world_b) &&
                          all_finite(point.normal) && all_finite(point.friction_dir1) &&
                          all_finite(point.friction_dir2) && std::isfinite(point.distance) &&
                          all_finite(point.combined) && all_finite(point.solver);
      if (!finite) throw std::invalid_argument(which + ": a value is not finite");
    }
  }
}

}  // namespace rodsort::engine
