// The trap with real rods: Bullet walls built from VTrap::walls(), rods of the paper's type A with
// the paper's collision kick (eps = 0.01 /mm), drive and materials. The paper: a single rod stays
// trapped for theta <= 70° and escapes beyond; a few rods in a narrow trap jam at its apex.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/simulation.hpp"
#include "engine/units.hpp"
#include "trap/v_trap.hpp"

using namespace rodsort;

namespace {

constexpr double kWindow = 0.07;        // tau, the paper's frame interval [s]
constexpr int kWindowSteps = 700;       // tau / dt
constexpr double kPaperArm = 45.0;      // L = 10 rod lengths [mm]
constexpr double kWallThickness = 0.5;  // [mm]
/// metrics::kDefaultStationarySpeed (metrics/trapping.hpp), which this layer cannot include [mm/s].
constexpr double kStationarySpeed = 5.0;

engine::Model trap_model(double box, const trap::VTrap& trap, std::uint64_t seed) {
  engine::Model model;
  model.box_x = model.box_y = box;
  model.drive = engine::Drive::paper();
  model.dt = 1.0e-4;
  model.seed = seed;
  model.materials = engine::MaterialTable::paper();
  engine::Species a;
  a.name = "A";
  a.shape = engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity);
  a.noise.kick_eps = 0.01;
  model.species.push_back(a);
  model.walls = trap.walls();
  REQUIRE_FALSE(trap.fit_error(box, box, trap::required_margin({a.shape})));
  return model;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

TEST_CASE("rods released in a 40° trap pointing at its apex jam there, stationary",
          "[trap][physics]") {
  const double box = 60.0;
  const trap::VTrap trap =
      trap::centered_v_trap(box, box, degrees_to_radians(40.0), kPaperArm, kWallThickness);
  engine::Model model = trap_model(box, trap, 1);
  // Five rods along the bisector, 10 to 30 mm from the apex, pointing roughly at it.
  const Eigen::Vector2d along = trap.bisector();
  const Eigen::Vector2d across(-along.y(), along.x());
  const double offsets[5][2] = {{10, 0}, {15, 1.5}, {20, -1.5}, {25, 0.5}, {30, -2.0}};
  for (const auto& [distance, side] : offsets) {
    const Eigen::Vector2d p = trap.apex() + distance * along + side * across;
    model.rods.push_back({0, p.x(), p.y(), trap.bisector_angle() + kPi + 0.05 * side});
  }
  engine::Simulation sim(model);
  sim.advance(30000);  // 3 s: the farthest rod needs ~2.5 s at ~12 mm/s

  // Over the next second, every tau: each rod's speed over tau.
  std::vector<std::vector<double>> speeds(model.rods.size());
  engine::Frame earlier = sim.frame();
  for (int k = 0; k < 14; ++k) {
    sim.advance(kWindowSteps);
    const engine::Frame later = sim.frame();
    for (std::size_t i = 0; i < later.rods.size(); ++i) {
      speeds[i].push_back((later.rods[i].unwrapped - earlier.rods[i].unwrapped).norm() / kWindow);
    }
    earlier = later;
  }
  for (std::size_t i = 0; i < earlier.rods.size(); ++i) {
    INFO("rod " << i);
    const engine::RodFrame& rod = earlier.rods[i];
    CHECK(trap.contains(rod.position));
    // Five rods fill the wedge up to ~10 mm from the apex.
    CHECK((rod.position - trap.apex()).norm() < 15.0);
    // Pointing into the trap, thin end first.
    CHECK(rod.axis.head<2>().normalized().dot(-along) > 0.5);
    // Stationary most of the time: a trapped rod rattles, a free one moves at 10-15 mm/s.
    CHECK(median(speeds[i]) < kStationarySpeed);
  }
}

TEST_CASE("a single rod escapes a 160° trap", "[trap][physics]") {
  const double box = 100.0;
  const trap::VTrap trap =
      trap::centered_v_trap(box, box, degrees_to_radians(160.0), kPaperArm, kWallThickness);
  for (const std::uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    engine::Model model = trap_model(box, trap, seed);
    // 4 mm in front of the apex, pointing at it, slightly turned.
    const Eigen::Vector2d p = trap.apex() + 4.0 * trap.bisector();
    model.rods.push_back({0, p.x(), p.y(), trap.bisector_angle() + kPi + 0.2});
    engine::Simulation sim(model);
    bool escaped = false;
    // Up to 5 s: the rod slides along an arm (45 mm) at ~12 mm/s and leaves.
    for (int k = 0; k < 50 && !escaped; ++k) {
      sim.advance(1000);
      const engine::RodFrame rod = sim.frame().rods[0];
      escaped = !trap.contains(rod.position) && (rod.position - trap.apex()).norm() > 20.0;
    }
    CHECK(escaped);
  }
}
