// Bullet combines the friction and restitution of a contact from the two bodies' own values
// through global function pointers (btManifoldResult.h); by default it multiplies them. The paper
// gives a value per pair of materials (rod-rod, rod-base, rod-lid, rod-trap), which no per-body
// value can reproduce. We replace the two functions with a lookup in the pair table, keyed by the
// materials in the bodies' tags; this is applied to every contact point Bullet creates.
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include "engine/body_tag.hpp"

namespace rodsort::engine {
namespace {

const ContactCoefficients& pair_coefficients(const btCollisionObject* a, const btCollisionObject* b) {
  const auto* tag_a = static_cast<const BodyTag*>(a->getUserPointer());
  const auto* tag_b = static_cast<const BodyTag*>(b->getUserPointer());
  return tag_a->materials->get(tag_a->material, tag_b->material);
}

btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
  return pair_coefficients(a, b).friction;
}

btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  return pair_coefficients(a, b).restitution;
}

}  // namespace

void install_material_table_callbacks() {
  gCalculateCombinedFrictionCallback = &combined_friction;
  gCalculateCombinedRestitutionCallback = &combined_restitution;
}

}  // namespace rodsort::engine
