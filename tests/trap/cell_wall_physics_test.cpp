// A bounded cell's wall with real bodies: a sphere thrown at it comes back with the configured
// rod-wall restitution, on an edge of the wall's polygon and on a corner where two boxes meet, and
// without friction keeps its speed along the wall.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/paper_model.hpp"
#include "engine/simulation.hpp"
#include "trap/cell_wall.hpp"

using namespace rodsort;

namespace {

constexpr double kImpactSpeed = 150.0;  // [mm/s]
constexpr double kDiameter = 20.0;      // [mm]
constexpr double kBox = 30.0;           // [mm]

/// A still world (no drive, a wide gap) closed by a circular wall, with rod-wall coefficients.
engine::Model walled_model(const trap::CellWall& cell, double friction, double restitution) {
  engine::Model model = engine::testing::paper_model(kBox);
  model.drive.amplitude = 0.0;
  model.drive.gap = 10.0;
  model.species.push_back(
      engine::testing::rod_species(engine::RodProfile{{{0.0, 0.5}}}));  // one sphere
  model.walls = cell.walls();
  model.rods.push_back({0, kBox / 2.0, kBox / 2.0, 0.0});  // placed by throw_at_wall
  model.materials.set(engine::MaterialTable::kFirstRod, engine::MaterialTable::kWall,
                      {friction, restitution});
  return model;
}

struct Bounce {
  double normal_ratio;      ///< outgoing over incoming speed along the wall's normal
  double tangential_ratio;  ///< outgoing over incoming speed along the wall
};

/// Throws the sphere from 1.5 mm inside the wall along `direction` (unit), at the point of the
/// wall in direction `toward` from the centre, and measures its velocity once it moves away.
Bounce throw_at_wall(const engine::Model& model, const Eigen::Vector2d& toward,
                     const Eigen::Vector2d& direction) {
  const Eigen::Vector2d centre(kBox / 2.0, kBox / 2.0);
  const trap::CellWall cell = trap::CellWall::circle(centre, kDiameter, 1.0);
  const Eigen::Vector2d hit = centre + cell.distance_to_wall(centre) * toward;
  const Eigen::Vector2d start = hit - (1.5 + 0.5) * direction / direction.dot(toward);
  engine::Simulation sim(model);
  engine::State state = sim.state();
  state.rods[0].position = {start.x(), start.y(), 5.0};  // mid-gap
  state.rods[0].velocity = {kImpactSpeed * direction.x(), kImpactSpeed * direction.y(), 0.0};
  sim.restore(state);
  const Eigen::Vector2d tangent(-toward.y(), toward.x());
  const double normal_in = kImpactSpeed * direction.dot(toward);
  const double tangential_in = kImpactSpeed * direction.dot(tangent);
  for (int step = 0; step < 2000; ++step) {
    sim.step();
    const Eigen::Vector3d v = sim.frame().rods[0].velocity;
    const Eigen::Vector2d planar(v.x(), v.y());
    if (planar.dot(toward) < 0.0) {
      return {-planar.dot(toward) / normal_in,
              tangential_in == 0.0 ? 0.0 : planar.dot(tangent) / tangential_in};
    }
  }
  FAIL("the sphere never came back from the wall");
  return {};
}

}  // namespace

TEST_CASE("a sphere thrown at a circular cell's wall rebounds with the rod-wall restitution",
          "[trap][physics]") {
  const Eigen::Vector2d centre(kBox / 2.0, kBox / 2.0);
  const trap::CellWall cell = trap::CellWall::circle(centre, kDiameter, 1.0);
  const auto corners = cell.outline();
  // Toward a corner of the polygon (two boxes meet there) and toward the middle of an edge.
  const Eigen::Vector2d at_corner = (corners[3] - centre).normalized();
  const Eigen::Vector2d at_edge = (0.5 * (corners[7] + corners[8]) - centre).normalized();
  for (const double e : {0.3, 0.65}) {
    const engine::Model model = walled_model(cell, 0.03, e);
    for (const Eigen::Vector2d& toward : {at_corner, at_edge}) {
      INFO("e = " << e << ", toward (" << toward.x() << ", " << toward.y() << ")");
      CHECK(throw_at_wall(model, toward, toward).normal_ratio == Approx(e).epsilon(0.05));
    }
  }
}

TEST_CASE("a sphere glancing off a frictionless cell wall keeps its speed along the wall",
          "[trap][physics]") {
  const Eigen::Vector2d centre(kBox / 2.0, kBox / 2.0);
  const trap::CellWall cell = trap::CellWall::circle(centre, kDiameter, 1.0);
  const engine::Model model = walled_model(cell, 0.0, 0.65);
  // At the middle of an edge, whose normal is `toward`; the sphere touches 0.4 mm from it.
  const auto corners = cell.outline();
  const Eigen::Vector2d toward = (0.5 * (corners[5] + corners[6]) - centre).normalized();
  const Eigen::Vector2d tangent(-toward.y(), toward.x());
  const Eigen::Vector2d direction = (toward + 0.8 * tangent).normalized();  // 39° from the normal
  const Bounce bounce = throw_at_wall(model, toward, direction);
  CHECK(bounce.normal_ratio == Approx(0.65).epsilon(0.05));
  CHECK(bounce.tangential_ratio == Approx(1.0).epsilon(0.02));
}
