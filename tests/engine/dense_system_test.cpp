// Many rods at the paper's density: the engine must keep them in the gap, apart and finite.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/random_stream.hpp"
#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

constexpr int kRods = 300;
constexpr int kColumns = 17;
constexpr int kRows = 18;

/// 300 rod A at the paper's area fraction (319 rods in an 86.85 mm cell), on a lattice, rows
/// heading alternately +x and -x with a little jitter, so that no two rods overlap at the start.
Model dense_model() {
  const double box = 86.85 * std::sqrt(static_cast<double>(kRods) / 319.0);
  Model model = testing::paper_model(box);  // the default dt
  model.seed = 3;
  model.species.push_back(testing::rod_species(preset_a_profile(), 0.01));
  RandomStream jitter(11, 0, StreamPurpose::kPlacement);
  for (int i = 0; i < kRods; ++i) {
    const int row = i / kColumns;
    const int column = i % kColumns;
    const double heading = (row % 2 == 0 ? 0.0 : rodsort::kPi) + 0.3 * (jitter.uniform() - 0.5);
    model.rods.push_back({0, (column + 0.5) * box / kColumns, (row + 0.5) * box / kRows, heading});
  }
  return model;
}

struct Overlaps {
  double rod_rod = 0.0;    ///< deepest sphere-sphere penetration between different rods [mm]
  double rod_plate = 0.0;  ///< deepest penetration of a sphere into the base or the lid [mm]
  bool finite = true;
};

Overlaps measure(const Simulation& sim) {
  const Model& model = sim.model();
  const Frame frame = sim.frame();
  const auto& spheres = model.species[0].shape.spheres;
  Overlaps overlaps;
  std::vector<std::vector<Eigen::Vector3d>> centres(frame.rods.size());
  for (std::size_t i = 0; i < frame.rods.size(); ++i) {
    const RodFrame& rod = frame.rods[i];
    overlaps.finite = overlaps.finite && rod.position.allFinite() && std::isfinite(rod.z) &&
                      rod.velocity.allFinite() && rod.angular_velocity.allFinite();
    const Eigen::Vector3d centre(rod.position.x(), rod.position.y(), rod.z);
    for (const Sphere& sphere : spheres) {
      const Eigen::Vector3d c = centre + sphere.axial * rod.axis;
      centres[i].push_back(c);
      overlaps.rod_plate = std::max(overlaps.rod_plate, sim.base_surface_z() - (c.z() - sphere.radius));
      overlaps.rod_plate = std::max(overlaps.rod_plate, c.z() + sphere.radius - sim.lid_surface_z());
    }
  }
  for (std::size_t i = 0; i < centres.size(); ++i) {
    for (std::size_t j = i + 1; j < centres.size(); ++j) {
      for (std::size_t a = 0; a < spheres.size(); ++a) {
        for (std::size_t b = 0; b < spheres.size(); ++b) {
          Eigen::Vector3d d = centres[i][a] - centres[j][b];
          d.x() -= model.box_x * std::round(d.x() / model.box_x);  // nearest periodic image
          d.y() -= model.box_y * std::round(d.y() / model.box_y);
          overlaps.rod_rod =
              std::max(overlaps.rod_rod, spheres[a].radius + spheres[b].radius - d.norm());
        }
      }
    }
  }
  return overlaps;
}

}  // namespace

TEST_CASE("300 rods for one second at the default dt: in the gap, no deep overlaps, no NaN",
          "[physics][dense]") {
  Simulation sim(dense_model());
  const double diameter = 2.0 * sim.model().species[0].shape.max_radius;
  Overlaps worst;
  for (int check = 0; check < 20; ++check) {
    sim.advance(500);
    const Overlaps now = measure(sim);
    worst.rod_rod = std::max(worst.rod_rod, now.rod_rod);
    worst.rod_plate = std::max(worst.rod_plate, now.rod_plate);
    worst.finite = worst.finite && now.finite;
  }
  CHECK(sim.time() == Approx(1.0));
  CHECK(worst.finite);
  // Rods barely overlap one another (at most 0.005 mm over seeds 1-4). A sphere meeting a plate
  // at up to ~120 mm/s sinks v dt = 0.012 mm in the step before the contact pushes it out: the
  // frames show 0.0116-0.0121 mm, and the engine's own record of every step's deepest contact
  // 0.0225-0.0227 mm, over seeds 1-4 (docs/model.md, "Checks while a run goes").
  CHECK(worst.rod_rod < 0.01 * diameter);
  CHECK(worst.rod_plate < 0.015);
  CHECK(sim.counters().deepest_overlap < 0.025);
  // None has left the gap: every centre of mass lies between the plates.
  for (const RodFrame& rod : sim.frame().rods) {
    CHECK(rod.z > sim.base_surface_z());
    CHECK(rod.z < sim.lid_surface_z());
  }
}

TEST_CASE("rod pairs skipped while apart change nothing: bit for bit the run that tests them all",
          "[determinism][dense]") {
  Simulation skipping(dense_model());
  Model every_pair_model = dense_model();
  every_pair_model.test_every_pair = true;
  Simulation every_pair(every_pair_model);
  // 0.2 s: rows running head-on into each other, across the periodic edges.
  for (int block = 0; block < 4; ++block) {
    skipping.advance(500);
    every_pair.advance(500);
    REQUIRE(hash_state(skipping.state()) == hash_state(every_pair.state()));
  }
  CHECK(every_pair.counters().pair_tests_skipped == 0);
  // The skips happened: 29,300 of them here (in a filled trap, ~70% of the pairs the broadphase
  // finds are skipped; docs/performance.md).
  CHECK(skipping.counters().pair_tests_skipped > 10000);
}
