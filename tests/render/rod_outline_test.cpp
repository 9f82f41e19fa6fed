#include "render/rod_outline.hpp"

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "engine/units.hpp"

using namespace rodsort;
using render::OutlineArc;
using render::OutlineLoop;

namespace {

Eigen::Vector2d point_on(const OutlineArc& arc, double angle) {
  return {arc.axial + arc.radius * std::cos(angle), arc.radius * std::sin(angle)};
}

/// Signed distance from a point to the union of the shape's discs (negative inside) [mm].
double distance_to_union(const engine::RodShape& shape, const Eigen::Vector2d& point) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const engine::Sphere& sphere : shape.spheres) {
    nearest =
        std::min(nearest, (point - Eigen::Vector2d(sphere.axial, 0.0)).norm() - sphere.radius);
  }
  return nearest;
}

/// Checks that every loop is closed, lies on the union's boundary and runs clockwise, and that
/// the loops together enclose the union's area (the engine's projected area, computed apart).
void check_outline(const engine::RodShape& shape, std::size_t expected_loops) {
  const std::vector<OutlineLoop> loops = render::rod_outline(shape);
  REQUIRE(loops.size() == expected_loops);
  double twice_area = 0.0;
  double farthest = 0.0;  // from the union's boundary, of a point of the outline [mm]
  for (const OutlineLoop& loop : loops) {
    REQUIRE(loop.size() >= 2);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const OutlineArc& arc = loop[k];
      const OutlineArc& next = loop[(k + 1) % loop.size()];
      CHECK(arc.to <= arc.from);
      CHECK((point_on(arc, arc.to) - point_on(next, next.from)).norm() < 1e-9);
      constexpr int kSamples = 400;
      for (int i = 0; i < kSamples; ++i) {
        const Eigen::Vector2d p = point_on(arc, arc.from + (arc.to - arc.from) * i / kSamples);
        const Eigen::Vector2d q =
            point_on(arc, arc.from + (arc.to - arc.from) * (i + 1) / kSamples);
        farthest = std::max(farthest, std::abs(distance_to_union(shape, p)));
        twice_area += p.x() * q.y() - q.x() * p.y();
      }
    }
  }
  CHECK(farthest < 1e-9);
  // Clockwise: the shoelace sum is negative.
  CHECK(-0.5 * twice_area == Approx(shape.projected_area).epsilon(1e-4));
}

}  // namespace

TEST_CASE("The outline of a rod is the boundary of its discs' union", "[render][rod_outline]") {
  check_outline(engine::make_rod_shape(engine::preset_rnt_profile(), kBrassDensity), 1);
  // Rod A's thin-tip sphere stands 0.025 mm clear of its neighbour: a second loop.
  check_outline(engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity), 2);
  check_outline(
      engine::make_rod_shape(engine::linear_taper_profile(4.5, 0.55, 0.2, 15), kBrassDensity), 1);
}

TEST_CASE("A disc hidden inside the others has no part in the outline", "[render][rod_outline]") {
  engine::RodProfile profile;
  profile.spheres = {{0.0, 0.5}, {0.3, 0.1}, {0.6, 0.5}};
  const engine::RodShape shape = engine::make_rod_shape(profile, kBrassDensity);
  check_outline(shape, 1);
  const std::vector<OutlineLoop> loops = render::rod_outline(shape);
  CHECK(loops[0].size() == 4);
  for (const OutlineArc& arc : loops[0]) CHECK(arc.radius == 0.5);
}

TEST_CASE("Separate spheres make separate loops, each a circle", "[render][rod_outline]") {
  engine::RodProfile profile;
  profile.spheres = {{0.0, 0.4}, {2.0, 0.3}};
  const engine::RodShape shape = engine::make_rod_shape(profile, kBrassDensity);
  check_outline(shape, 2);
  const std::vector<OutlineLoop> loops = render::rod_outline(shape);
  for (const OutlineLoop& loop : loops) {
    REQUIRE(loop.size() == 2);
    CHECK(loop[0].from == kPi);
    CHECK(loop[0].to == 0.0);
    CHECK(loop[1].from == 0.0);
    CHECK(loop[1].to == -kPi);
  }
  CHECK(loops[0][0].radius == 0.4);
  CHECK(loops[1][0].radius == 0.3);
}
