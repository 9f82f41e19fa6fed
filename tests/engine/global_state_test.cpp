// A Simulation leaves Bullet's process-wide state as other code expects it: another Bullet world
// in the same process keeps Bullet's own contact rules and breaking distance, and Simulations can
// be built on several threads at once.
#include <btBulletDynamicsCommon.h>

#include <catch2/catch.hpp>
#include <thread>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

Model small_model(std::uint64_t seed) {
  Model model = testing::paper_model(20.0);
  model.seed = seed;
  model.species.push_back(testing::rod_species(preset_a_profile(), 0.01, 0.1));
  for (int i = 0; i < 8; ++i)
    model.rods.push_back({0, 2.5 + 5.0 * (i % 4), 4.0 + 8.0 * (i / 4), 0.7 * i});
  return model;
}

/// A ball dropped on a box in a world of Bullet's own, its bodies' user pointers pointing at
/// something that is not a BodyTag. Returns the combined friction of its last contact point.
double plain_world_friction() {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, 0, -9.81));
  int foreign = 42;  // what another program might keep in its user pointers

  btBoxShape floor_shape(btVector3(5, 5, 0.5));
  btRigidBody floor(btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, &floor_shape));
  floor.setFriction(0.4);
  floor.setUserPointer(&foreign);
  world.addRigidBody(&floor);

  btSphereShape ball_shape(0.5);
  btVector3 inertia;
  ball_shape.calculateLocalInertia(1.0, inertia);
  btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(1.0, nullptr, &ball_shape, inertia));
  ball.setFriction(0.5);
  ball.setUserPointer(&foreign);
  ball.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 1.2)));
  world.addRigidBody(&ball);

  double friction = -1.0;
  for (int step = 0; step < 120; ++step) {
    world.stepSimulation(1.0 / 60.0, 0);
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      if (manifold->getNumContacts() > 0) {
        friction = manifold->getContactPoint(0).m_combinedFriction;
      }
    }
  }
  world.removeRigidBody(&ball);
  world.removeRigidBody(&floor);
  return friction;
}

}  // namespace

TEST_CASE("a plain Bullet world runs beside a Simulation with Bullet's own rules",
          "[engine][global]") {
  const double breaking_before = gContactBreakingThreshold;
  Simulation simulation(small_model(3));
  simulation.advance(200);
  // Bullet's rule for bodies that are not a simulation's: the product of their frictions.
  CHECK(plain_world_friction() == Approx(0.4 * 0.5).epsilon(1e-12));
  CHECK(gContactBreakingThreshold == breaking_before);
  // And the Simulation steps on exactly as one that never saw the other world.
  Simulation twin(small_model(3));
  twin.advance(200);
  simulation.advance(300);
  twin.advance(300);
  CHECK(hash_state(simulation.state()) == hash_state(twin.state()));
}

TEST_CASE("Simulations built and run on two threads at once agree with one built alone",
          "[engine][global]") {
  Simulation alone(small_model(5));
  alone.advance(400);
  std::uint64_t hashes[2] = {0, 0};
  std::thread threads[2];
  for (int t = 0; t < 2; ++t) {
    threads[t] = std::thread([t, &hashes] {
      Simulation simulation(small_model(5));
      simulation.advance(400);
      hashes[t] = hash_state(simulation.state());
    });
  }
  for (std::thread& thread : threads) thread.join();
  CHECK(hashes[0] == hash_state(alone.state()));
  CHECK(hashes[1] == hash_state(alone.state()));
}
