// Restitution must come out as configured. Bullet's defaults lose it (speculative contacts slow a
// body before it touches; see the comment at the top of engine/simulation.cpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

constexpr double kImpactSpeed = 150.0;  // [mm/s]
constexpr double kTolerance = 0.05;     // relative

/// A still world (no drive) with a wide gap, so nothing touches the lid; rod-base and rod-rod
/// restitution set to e.
Model still_model(const Species& species, double dt, double e) {
  Model model = testing::paper_model(30.0, dt);
  model.drive.amplitude = 0.0;
  model.drive.gap = 10.0;
  model.species.push_back(species);
  model.rods.push_back({0, 15.0, 15.0, 0.0});
  model.materials.set(MaterialTable::kFirstRod, MaterialTable::kBase, {0.03, e});
  model.materials.set(MaterialTable::kFirstRod, MaterialTable::kFirstRod, {0.05, e});
  return model;
}

Species single_sphere(double radius) { return testing::rod_species(RodProfile{{{0.0, radius}}}); }

/// Drops the model's rod at kImpactSpeed onto the base and returns the ratio of the normal
/// velocity of its body point `arm` (from the centre of mass, in the rod's initial frame) after
/// and before the impact. The impact velocity includes the g dt that gravity adds during the
/// impact step before the solver acts.
double drop_on_base(const Model& model, const Eigen::Vector3d& arm) {
  Simulation sim(model);
  State state = sim.state();
  state.rods[0].position[2] = 3.0;
  state.rods[0].velocity = {0.0, 0.0, -kImpactSpeed};
  sim.restore(state);
  double before = -kImpactSpeed;
  for (int step = 0; step < 100000; ++step) {
    sim.step();
    const RodFrame rod = sim.frame().rods[0];
    const double after = rod.velocity.z() + rod.angular_velocity.cross(arm).z();
    if (after > 0.0) return after / (-before + rodsort::kGravity * model.dt);
    before = after;
  }
  return 0.0;
}

}  // namespace

TEST_CASE("a sphere dropped on the base rebounds with the configured restitution",
          "[restitution]") {
  for (const double dt : {1.0e-4, 2.5e-5}) {
    for (const double e : {0.1, 0.3, 0.65}) {
      INFO("dt = " << dt << ", e = " << e);
      const double measured = drop_on_base(still_model(single_sphere(0.5), dt, e), {0, 0, -0.5});
      CHECK(measured == Approx(e).epsilon(kTolerance));
    }
  }
}

TEST_CASE("a rod dropped flat on the base rebounds with the configured restitution",
          "[restitution]") {
  const Species rod = testing::rod_species(preset_a_profile());
  // Lying flat, rod A first touches with the bottom of its thick end sphere.
  const Sphere& thick = rod.shape.spheres.front();
  const Eigen::Vector3d contact_arm(thick.axial, 0.0, -thick.radius);
  for (const double dt : {1.0e-4, 2.5e-5}) {
    for (const double e : {0.1, 0.3, 0.65}) {
      INFO("dt = " << dt << ", e = " << e);
      CHECK(drop_on_base(still_model(rod, dt, e), contact_arm) == Approx(e).epsilon(kTolerance));
    }
  }
}

TEST_CASE("two spheres colliding head on separate with the configured restitution",
          "[restitution]") {
  for (const double dt : {1.0e-4, 2.5e-5}) {
    for (const double e : {0.1, 0.3, 0.65}) {
      INFO("dt = " << dt << ", e = " << e);
      Model model = still_model(single_sphere(0.5), dt, e);
      model.rods.push_back({0, 16.3, 15.0, 0.0});
      Simulation sim(model);
      State state = sim.state();
      for (RodState& rod : state.rods) rod.position[2] = 5.0;  // mid-gap, far from both plates
      state.rods[0].velocity = {kImpactSpeed / 2, 0.0, 0.0};
      state.rods[1].velocity = {-kImpactSpeed / 2, 0.0, 0.0};
      sim.restore(state);
      double approach = 0.0;
      for (int step = 0; step < 100000; ++step) {
        const Frame frame = sim.frame();
        const double relative = frame.rods[1].velocity.x() - frame.rods[0].velocity.x();
        if (relative > 0.0) {
          approach = kImpactSpeed;
          CHECK(relative / approach == Approx(e).epsilon(kTolerance));
          break;
        }
        sim.step();
      }
      CHECK(approach > 0.0);
    }
  }
}
