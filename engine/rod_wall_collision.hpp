#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>

#include <cstdint>
#include <span>
#include <vector>

#include "engine/apart_pair.hpp"
#include "engine/state.hpp"

class btPersistentManifold;

namespace rodsort::engine {

/// Contacts of a rod (a compound of spheres) with a static wall (any box), sphere by sphere in
/// the box's frame; see rod_wall_collision.cpp.
class RodWallCollision : public btCollisionAlgorithm {
 public:
  /// `restored`: the manifolds this pair had when its State was saved (surface_contacts.hpp).
  /// Counts the steps it skips the pair on in `*skipped` (null: not counted).
  RodWallCollision(const btCollisionAlgorithmConstructionInfo& info,
                   const btCollisionObjectWrapper* rod, const btCollisionObjectWrapper* wall,
                   bool rod_is_body0, std::span<const SurfaceContactState> restored,
                   std::int64_t* skipped);
  ~RodWallCollision() override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

  /// Whether the pair is skipped at this step: at the last test no sphere of the rod was within
  /// the contact-breaking distance of the wall, and the rod has not travelled that gap since
  /// (its BodyTag::travel, kept here from construction; none kept, never skipped). Counts the skip.
  bool skips() { return apart_.skips(); }

 private:
  void release(btPersistentManifold*& manifold);

  bool rod_is_body0_;
  double breaking_threshold_;  ///< of the manifolds Bullet makes for this pair [mm]
  std::vector<btPersistentManifold*> manifolds_;  ///< one per sphere, null while it is far
  ApartPair apart_;                               ///< the rod against the still wall
};

}  // namespace rodsort::engine
