// Bullet combines the friction and restitution of a contact from the two bodies' own values
// through global function pointers (btManifoldResult.h); by default it multiplies them. The paper
// gives a value per pair of materials (rod-rod, rod-base, rod-lid, rod-trap), which no per-body
// value can reproduce. We replace the two functions with a lookup in the pair table, keyed by the
// materials in the bodies' tags, for every contact between two bodies of a simulation (both carry
// kBodyTagMark). The pointers are process-wide, so a contact between other bodies (another Bullet
// world in the same process) goes to the functions that were installed before, Bullet's own
// unless someone else replaced them, and never has its user pointer read as a BodyTag.
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include <mutex>

#include "engine/body_tag.hpp"

namespace rodsort::engine {
namespace {

CalculateCombinedCallback previous_friction = nullptr;
CalculateCombinedCallback previous_restitution = nullptr;

bool tagged(const btCollisionObject* object) { return object->getUserIndex3() == kBodyTagMark; }

const ContactCoefficients& pair_coefficients(const btCollisionObject* a, const btCollisionObject* b) {
  const auto* tag_a = static_cast<const BodyTag*>(a->getUserPointer());
  const auto* tag_b = static_cast<const BodyTag*>(b->getUserPointer());
  return tag_a->materials->get(tag_a->material, tag_b->material);
}

btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
  if (!tagged(a) || !tagged(b)) return previous_friction(a, b);
  return pair_coefficients(a, b).friction;
}

btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  if (!tagged(a) || !tagged(b)) return previous_restitution(a, b);
  return pair_coefficients(a, b).restitution;
}

}  // namespace

void install_material_table_callbacks() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    previous_friction = gCalculateCombinedFrictionCallback;
    previous_restitution = gCalculateCombinedRestitutionCallback;
    gCalculateCombinedFrictionCallback = &combined_friction;
    gCalculateCombinedRestitutionCallback = &combined_restitution;
  });
}

}  // namespace rodsort::engine
