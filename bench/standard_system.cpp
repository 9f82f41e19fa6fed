#include "bench/standard_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/lattice_placement.hpp"
#include "engine/random_stream.hpp"
#include "engine/rod_shape.hpp"
#include "engine/units.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::bench {

std::vector<SystemSpec> standard_systems() {
  std::vector<SystemSpec> systems = {{"single", 1, 30.0, 0.0}};
  for (const int scale : {1, 2, 4}) {
    const int rods = 319 * scale * scale;
    systems.push_back({std::to_string(rods), rods, kPaperBox * scale, kPaperArm * scale});
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

engine::Species rod_a_species(double kick_eps) {
  engine::Species species;
  species.name = "A";
  species.shape = engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity);
  species.noise.kick_eps = kick_eps;
  return species;
}

engine::Model build_model(const SystemSpec& system, double dt, std::uint64_t seed) {
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
  model.rods = place_on_lattice(model.species.front().shape, system.rod_count, model.box_x, model.box_y,
                                model.walls, placement);
  return model;
}

}  // namespace rodsort::bench
