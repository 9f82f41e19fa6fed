#pragma once
// Every Bullet collision object of a simulation carries a BodyTag in its user pointer: what it is,
// its material, and for a rod or a periodic image the rod it stands for. Contact materials, the
// periodic solver and the collision kick all read it.

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <algorithm>

#include "engine/apart_pair.hpp"
#include "engine/materials.hpp"
#include "engine/plate_roughness.hpp"

namespace rodsort::engine {

enum class BodyKind { kRod, kImage, kBase, kLid, kWall };

/// Collision groups: images meet only rods; plates and walls meet only rods.
enum CollisionGroup : int { kGroupRod = 1, kGroupPlate = 2, kGroupWall = 4, kGroupImage = 8 };

struct BodyTag {
  BodyKind kind;
  int material;                  ///< index into *materials
  const MaterialTable* materials;
  int rod = -1;                  ///< rod index for kRod and kImage
  int shift = -1;                ///< periodic shift index for kImage
  int wall = -1;                 ///< wall index for kWall
  const PlateRoughness* roughness = nullptr;  ///< kBase and kLid: the surface, null when flat
  /// kRod and kImage: a bound on how far any sphere centre of the rod has moved since the world
  /// was built (apart_pair.hpp); null where nobody keeps it. The rod-rod and rod-wall algorithms
  /// skip a pair whose gap the rods cannot yet have closed.
  const Travel* travel = nullptr;
};

/// Every collision object of a simulation carries this mark in its user index 3 beside its tag, so
/// that Bullet's process-wide material callbacks (contact_materials.cpp) know a simulation's bodies
/// from those of any other Bullet world in the process.
constexpr int kBodyTagMark = 0x726f6473;

inline void attach_tag(btCollisionObject& object, BodyTag& tag) {
  object.setUserPointer(&tag);
  object.setUserIndex3(kBodyTagMark);
}

/// Where BodyTag::travel of a rod or an image is kept; null where it is not (nothing is skipped).
inline const Travel* travel_of(const btCollisionObject& object) {
  if (object.getUserIndex3() != kBodyTagMark) return nullptr;
  return static_cast<const BodyTag*>(object.getUserPointer())->travel;
}

/// Makes Bullet combine friction and restitution of two tagged bodies by looking the pair up in
/// their material table instead of multiplying per-body values; contacts of bodies without the
/// mark are combined as before. Safe to call from any thread, any number of times.
void install_material_table_callbacks();

/// Contact-breaking distance factor. Bullet multiplies it by a shape's bounding radius (~2.4 mm for
/// rod A), giving ~0.1 mm, well above 2 v dt for the speeds met at dt <= 1e-4 s. Set on every
/// manifold the rod algorithms make, not through Bullet's global gContactBreakingThreshold, which
/// other Bullet worlds in the process share.
constexpr double kContactBreakingFactor = 0.04;

/// A new manifold between `a` and `b`, with the contact-breaking distance Bullet's dispatcher
/// would give it with kContactBreakingFactor as its global factor.
inline btPersistentManifold* new_manifold(btDispatcher& dispatcher, const btCollisionObject* a,
                                          const btCollisionObject* b) {
  btPersistentManifold* manifold = dispatcher.getNewManifold(a, b);
  manifold->setContactBreakingThreshold(
      std::min(a->getCollisionShape()->getContactBreakingThreshold(kContactBreakingFactor),
               b->getCollisionShape()->getContactBreakingThreshold(kContactBreakingFactor)));
  return manifold;
}

}  // namespace rodsort::engine
