// The collision kick.
//
// The paper: "a random angular velocity omega_z = eps v_rel, eps = +-0.01 mm^-1 with equal
// probability, whenever a rod collides with the base or the lid with relative velocity v_rel of
// contact points normal to the contact plane". We add it to omega_z.
//
// What is "a collision" in a time-stepped rigid-body engine? Bullet's callbacks run before the
// solver and see speculative points, and the rod-plate manifolds persist across steps, so neither
// "a callback fired" nor "a manifold exists" counts impacts in a way that is independent of dt.
// We use the solver's verdict instead: after a step, a rod touches a plate if any point of their
// manifolds carries a non-zero normal impulse. An event is the transition from not touching (after
// the previous step) to touching (after this one), so a rod resting or sliding on the base is
// kicked once when it lands, not every step. v_rel is taken from the velocities saved before the
// step (the approach velocity, not the rebound), at the contact point that carried the largest
// impulse, relative to the plate's velocity over the step.
#include "engine/collision_kick.hpp"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cmath>

#include "engine/body_tag.hpp"

namespace rodsort::engine {

void CollisionKick::save_velocities(const std::vector<btRigidBody*>& rods) {
  position_before_.resize(rods.size());
  velocity_before_.resize(rods.size());
  angular_velocity_before_.resize(rods.size());
  for (std::size_t i = 0; i < rods.size(); ++i) {
    position_before_[i] = rods[i]->getWorldTransform().getOrigin();
    velocity_before_[i] = rods[i]->getLinearVelocity();
    angular_velocity_before_[i] = rods[i]->getAngularVelocity();
  }
}

int CollisionKick::apply(btPersistentManifold* const* manifolds, int manifold_count,
                         const std::vector<btRigidBody*>& rods, const std::vector<double>& kick_eps,
                         std::vector<Touching>& touching, std::vector<RandomStream>& streams) {
  impacts_.assign(rods.size(), {});
  for (int m = 0; m < manifold_count; ++m) {
    const btPersistentManifold* manifold = manifolds[m];
    const auto* tag0 = static_cast<const BodyTag*>(manifold->getBody0()->getUserPointer());
    const auto* tag1 = static_cast<const BodyTag*>(manifold->getBody1()->getUserPointer());
    const bool rod_first = tag0->kind == BodyKind::kRod;
    const BodyTag* rod_tag = rod_first ? tag0 : tag1;
    const BodyTag* plate_tag = rod_first ? tag1 : tag0;
    if (rod_tag->kind != BodyKind::kRod) continue;
    if (plate_tag->kind != BodyKind::kBase && plate_tag->kind != BodyKind::kLid) continue;
    const auto rod = static_cast<std::size_t>(rod_tag->rod);
    const int plate = plate_tag->kind == BodyKind::kBase ? 0 : 1;
    const auto* plate_body =
        static_cast<const btRigidBody*>(rod_first ? manifold->getBody1() : manifold->getBody0());
    Impact& impact = impacts_[rod][static_cast<std::size_t>(plate)];
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getAppliedImpulse() <= impact.impulse) continue;
      const btVector3& on_rod = rod_first ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
      const btVector3 arm = on_rod - position_before_[rod];
      const btVector3 rod_point_velocity =
          velocity_before_[rod] + angular_velocity_before_[rod].cross(arm);
      const btVector3 relative = rod_point_velocity - plate_body->getLinearVelocity();
      impact.impulse = point.getAppliedImpulse();
      impact.normal_speed = std::abs(relative.dot(point.m_normalWorldOnB));
    }
  }

  int events = 0;
  for (std::size_t rod = 0; rod < rods.size(); ++rod) {
    for (std::size_t plate = 0; plate < 2; ++plate) {
      const bool now = impacts_[rod][plate].impulse > 0.0;
      if (now && !touching[rod][plate]) {
        ++events;
        if (kick_eps[rod] != 0.0) {
          const double kick = streams[rod].sign() * kick_eps[rod] * impacts_[rod][plate].normal_speed;
          btVector3 omega = rods[rod]->getAngularVelocity();
          omega.setZ(omega.z() + kick);
          rods[rod]->setAngularVelocity(omega);
        }
      }
      touching[rod][plate] = now;
    }
  }
  return events;
}

}  // namespace rodsort::engine
