#include "engine/rod_collision_dispatch.hpp"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>

#include <algorithm>
#include <new>

#include "engine/body_tag.hpp"
#include "engine/rod_plate_collision.hpp"
#include "engine/rod_rod_collision.hpp"
#include "engine/rod_wall_collision.hpp"
#include "engine/surface_contacts.hpp"

namespace rodsort::engine {

btDefaultCollisionConstructionInfo RodCollisionDispatch::configuration_info() {
  btDefaultCollisionConstructionInfo info;
  // Bullet's pool hands out fixed-size elements and does not check the size asked for.
  info.m_customCollisionAlgorithmMaxElementSize = static_cast<int>(
      std::max({sizeof(RodPlateCollision), sizeof(RodRodCollision), sizeof(RodWallCollision)}));
  return info;
}

RodCollisionDispatch::RodCollisionDispatch(btCollisionDispatcher& dispatcher,
                                           const RestoredContacts* restored,
                                           std::int64_t* pairs_skipped) {
  rod_rod_.skipped = pairs_skipped;
  rod_box_.skipped = pairs_skipped;
  box_rod_.skipped = pairs_skipped;
  rod_box_.rod_is_body0 = true;
  box_rod_.rod_is_body0 = false;
  rod_box_.restored = restored;
  box_rod_.restored = restored;
  dispatcher.registerCollisionCreateFunc(COMPOUND_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, &rod_box_);
  dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, COMPOUND_SHAPE_PROXYTYPE, &box_rod_);
  dispatcher.registerCollisionCreateFunc(COMPOUND_SHAPE_PROXYTYPE, COMPOUND_SHAPE_PROXYTYPE,
                                         &rod_rod_);
  dispatcher.setNearCallback(&near_callback);
}

btCollisionAlgorithm* RodCollisionDispatch::RodBox::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
  const btCollisionObjectWrapper* rod = rod_is_body0 ? body0 : body1;
  const btCollisionObjectWrapper* box = rod_is_body0 ? body1 : body0;
  const auto* tag = static_cast<const BodyTag*>(box->getCollisionObject()->getUserPointer());
  const auto* rod_tag = static_cast<const BodyTag*>(rod->getCollisionObject()->getUserPointer());
  const std::span<const SurfaceContactState> saved =
      restored ? restored->of(rod_tag->rod, surface_of(*tag))
               : std::span<const SurfaceContactState>();
  if (tag->kind == BodyKind::kWall) {
    void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(RodWallCollision));
    return new (memory) RodWallCollision(info, rod, box, rod_is_body0, saved, skipped);
  }
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(RodPlateCollision));
  return new (memory) RodPlateCollision(info, rod, box, rod_is_body0, saved);
}

btCollisionAlgorithm* RodCollisionDispatch::RodRod::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(RodRodCollision));
  return new (memory) RodRodCollision(info, skipped, travel_of(*body0->getCollisionObject()),
                                      travel_of(*body1->getCollisionObject()));
}

void RodCollisionDispatch::near_callback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                                         const btDispatcherInfo& info) {
  // Told apart by the proxies' collision groups, without reading the collision objects: two rods
  // (or a rod and an image) have a RodRodCollision, a rod and a wall a RodWallCollision.
  if (pair.m_algorithm != nullptr) {
    constexpr int kRodLike = kGroupRod | kGroupImage;
    const int group0 = pair.m_pProxy0->m_collisionFilterGroup;
    const int group1 = pair.m_pProxy1->m_collisionFilterGroup;
    if ((group0 & kRodLike) != 0 && (group1 & kRodLike) != 0) {
      if (static_cast<RodRodCollision*>(pair.m_algorithm)->skips()) return;
    } else if ((group0 | group1) == (kGroupRod | kGroupWall)) {
      if (static_cast<RodWallCollision*>(pair.m_algorithm)->skips()) return;
    }
  }
  btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
}

}  // namespace rodsort::engine
