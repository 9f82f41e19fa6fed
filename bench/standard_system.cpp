#include "bench/standard_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/filled_state.hpp"
#include "bench/lattice_placement.hpp"
#include "engine/random_stream.hpp"
#include "engine/rod_shape.hpp"
#include "engine/units.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::bench {

std::vector<SystemSpec> standard_systems() {
  std::vector<SystemSpec> systems = {{"single", 1, 30.0, 0.0}};
  for (const bool full : {false, true}) {
    for (const int scale : {1, 2, 4}) {
      const int rods = 319 * scale * scale;
      systems.push_back({std::to_string(rods) + (full ? "-full" : ""), rods, kPaperBox * scale,
                         kPaperArm * scale, full});
    }
  }
  for (const int tiles : {1, 2, 4}) {
    const int rods = 319 * tiles * tiles;
    systems.push_back(
        {"319-filled" + (tiles == 1 ? std::string() : "-x" + std::to_string(rods / 319)), rods,
         kPaperBox * tiles, kPaperArm, true, tiles});
  }
  return systems;
}

SystemSpec find_system(const std::string& name) {
  std::string known;
  for (const SystemSpec& system : standard_systems()) {
    if (system.name == name) return system;
    known += (known.empty() ? "" : ", ") + system.name;
  }
  throw std::invalid_argument("unknown system '" + name + "'; expected one of " + known);
}

namespace {

/// Rods packed into `trap` from its apex: rows across the bisector, one rod length (plus the
/// clearance) apart, each rod on the bisector's direction with its thin end toward the apex (the
/// species' spheres grow in `axial` toward the thin end, so the heading is the bisector reversed),
/// as many as fit inside the inner faces with the clearance, up to `most`.
std::vector<engine::RodInit> pack_in_trap(const engine::RodShape& shape, const trap::VTrap& trap,
                                          int most) {
  const double clearance = kPlacementClearance;
  const double spacing = 2.0 * shape.max_radius + clearance;  // between neighbours in a row
  double axial_min = 0.0, axial_max = 0.0;
  for (const engine::Sphere& sphere : shape.spheres) {
    axial_min = std::min(axial_min, sphere.axial - sphere.radius);
    axial_max = std::max(axial_max, sphere.axial + sphere.radius);
  }
  const double length = axial_max - axial_min;
  const double slope = std::tan(trap.opening_angle() / 2.0);
  const double depth = trap.arm_length() * std::cos(trap.opening_angle() / 2.0);
  const Eigen::Vector2d along = trap.bisector();
  const Eigen::Vector2d across(-along.y(), along.x());
  const double heading = trap.bisector_angle() + kPi;
  std::vector<engine::RodInit> rods;
  // Row by row from the apex: the rod's tip nearest the apex at `tip`, its far end at tip + length.
  for (double tip = clearance; tip + length <= depth; tip += length + clearance) {
    // With heading = bisector + pi, body axial a lies at -a along the bisector from the centre:
    // the thin end (largest axial) is nearest the apex.
    const double centre_along = tip + axial_max;
    // Across the row: every sphere, at s along the bisector, r + clearance from the inner face,
    // which lies (s slope - |y|) cos(theta / 2) from a point at y.
    double room = 1e300;
    for (const engine::Sphere& sphere : shape.spheres) {
      room = std::min(room, (centre_along - sphere.axial) * slope -
                                (sphere.radius + clearance) / std::cos(trap.opening_angle() / 2.0));
    }
    if (room < 0.0) continue;
    const int beside = static_cast<int>(std::floor(room / spacing));
    for (int k = -beside; k <= beside; ++k) {
      if (static_cast<int>(rods.size()) == most) return rods;
      const Eigen::Vector2d centre = trap.apex() + centre_along * along + (spacing * k) * across;
      rods.push_back({0, centre.x(), centre.y(), heading});
    }
  }
  return rods;
}

}  // namespace

engine::Species rod_a_species(double kick_eps) {
  engine::Species species;
  species.name = "A";
  species.shape = engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity);
  species.noise.kick_eps = kick_eps;
  return species;
}

engine::Model build_model(const SystemSpec& system, double dt, std::uint64_t seed) {
  if (system.filled_tiles > 0) {
    return tile_model(build_model(find_system("319-full"), dt, seed), system.filled_tiles);
  }
  engine::Model model;
  model.box_x = system.box;
  model.box_y = system.box;
  model.drive = engine::Drive::paper();
  model.dt = dt;
  model.seed = seed;

  model.species.push_back(rod_a_species(kPaperKickEps));

  if (system.trap_arm > 0.0) {
    const trap::VTrap trap =
        trap::centered_v_trap(system.box, system.box, degrees_to_radians(kTrapAngleDegrees),
                              system.trap_arm, kTrapWallThickness);
    model.walls = trap.walls();
  }

  if (system.rod_count == 1) {
    model.rods.push_back({0, system.box / 2, system.box / 2, 0.0});
    return model;
  }
  engine::RandomStream placement(seed, 0, engine::StreamPurpose::kPlacement);
  if (!system.full_trap) {
    model.rods = place_on_lattice(model.species.front().shape, system.rod_count, model.box_x,
                                  model.box_y, model.walls, placement);
    return model;
  }
  const trap::VTrap trap =
      trap::centered_v_trap(system.box, system.box, degrees_to_radians(kTrapAngleDegrees),
                            system.trap_arm, kTrapWallThickness);
  model.rods = pack_in_trap(model.species.front().shape, trap, system.rod_count);
  // The rest on the lattice outside: the trap's interior is kept clear by a block standing over
  // its triangle for the placement alone.
  std::vector<engine::Wall> keep_out = model.walls;
  const double depth = trap.arm_length() * std::cos(trap.opening_angle() / 2.0);
  const double mouth = trap.arm_length() * std::sin(trap.opening_angle() / 2.0);
  const Eigen::Vector2d middle = trap.apex() + 0.5 * depth * trap.bisector();
  keep_out.push_back({middle.x(), middle.y(), 0.5 * depth, mouth, trap.bisector_angle()});
  const std::vector<engine::RodInit> outside = place_on_lattice(
      model.species.front().shape, system.rod_count - static_cast<int>(model.rods.size()),
      model.box_x, model.box_y, keep_out, placement);
  model.rods.insert(model.rods.end(), outside.begin(), outside.end());
  return model;
}

}  // namespace rodsort::bench
