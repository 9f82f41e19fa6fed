#pragma once
// Models for engine tests, built by hand (the engine knows no YAML): the paper's drive, materials
// and rod A, in a periodic cell of a given size.

#include <vector>

#include "engine/model.hpp"
#include "engine/rod_shape.hpp"
#include "engine/units.hpp"

namespace rodsort::engine::testing {

inline Species rod_species(const RodProfile& profile, double kick_eps = 0.0, double white_Dr = 0.0) {
  Species species;
  species.name = "A";
  species.shape = make_rod_shape(profile, kBrassDensity);
  species.noise.kick_eps = kick_eps;
  species.noise.white_Dr = white_Dr;
  return species;
}

/// The paper's drive in a periodic cell, no rods yet.
inline Model paper_model(double box_mm, double dt = 1.0e-4) {
  Model model;
  model.box_x = box_mm;
  model.box_y = box_mm;
  model.drive = Drive::paper();
  model.dt = dt;
  return model;
}

/// One rod of `species` at the centre of a 30 mm cell, heading along +x.
inline Model single_rod_model(const Species& species, double dt = 1.0e-4, std::uint64_t seed = 1) {
  Model model = paper_model(30.0, dt);
  model.seed = seed;
  model.species.push_back(species);
  model.rods.push_back({0, 15.0, 15.0, 0.0});
  return model;
}

}  // namespace rodsort::engine::testing
