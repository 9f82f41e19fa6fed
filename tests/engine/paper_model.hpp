#pragma once
// Models for engine tests, built by hand (the engine knows no YAML): the paper's drive, materials
// and rod A, in a periodic cell of a given size.

#include <cmath>
#include <vector>

#include "engine/model.hpp"
#include "engine/random_stream.hpp"
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

/// 300 rod A with the paper's kick at the paper's area fraction (319 rods in an 86.85 mm cell), on
/// a lattice of 17 x 18, rows heading alternately +x and -x with a little jitter, so that no two
/// rods overlap at the start and the rows run head-on into each other across the periodic edges.
inline Model dense_paper_model() {
  constexpr int kRods = 300, kColumns = 17, kRows = 18;
  const double box = 86.85 * std::sqrt(static_cast<double>(kRods) / 319.0);
  Model model = paper_model(box);  // the default dt
  model.seed = 3;
  model.species.push_back(rod_species(preset_a_profile(), 0.01));
  RandomStream jitter(11, 0, StreamPurpose::kPlacement);
  for (int i = 0; i < kRods; ++i) {
    const int row = i / kColumns;
    const int column = i % kColumns;
    const double heading = (row % 2 == 0 ? 0.0 : kPi) + 0.3 * (jitter.uniform() - 0.5);
    model.rods.push_back({0, (column + 0.5) * box / kColumns, (row + 0.5) * box / kRows, heading});
  }
  return model;
}

}  // namespace rodsort::engine::testing
