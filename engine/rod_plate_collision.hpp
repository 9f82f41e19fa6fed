#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>

#include <span>
#include <vector>

#include "engine/state.hpp"

class btPersistentManifold;
class btTransform;

namespace rodsort::engine {
class PlateRoughness;
struct RodGeometry;
}  // namespace rodsort::engine

namespace rodsort::engine {

/// Contacts of a rod (a compound of spheres) with the base or the lid (horizontal slabs), computed
/// analytically; see rod_plate_collision.cpp.
class RodPlateCollision : public btCollisionAlgorithm {
 public:
  /// `restored`: the manifolds this pair had when its State was saved (surface_contacts.hpp).
  RodPlateCollision(const btCollisionAlgorithmConstructionInfo& info,
                    const btCollisionObjectWrapper* rod, const btCollisionObjectWrapper* plate,
                    bool rod_is_body0, std::span<const SurfaceContactState> restored);
  ~RodPlateCollision() override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

 private:
  void process_rough(const PlateRoughness& roughness, bool base, double box_surface,
                     const RodGeometry& geometry, const btTransform& pose,
                     const btCollisionObjectWrapper* rod, const btCollisionObjectWrapper* plate,
                     btManifoldResult* result);

  bool rod_is_body0_;
  std::vector<btPersistentManifold*> manifolds_;  ///< one per sphere, null while it is clear
  std::vector<char> clear_;  ///< rough plates: per sphere, clear of the plate at this step
};

}  // namespace rodsort::engine
