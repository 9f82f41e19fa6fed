#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>

#include <vector>

class btPersistentManifold;

namespace rodsort::engine {

/// Contacts between two rods (or a rod and a periodic image), sphere against sphere behind a
/// bounding-capsule test; see rod_rod_collision.cpp.
class RodRodCollision : public btCollisionAlgorithm {
 public:
  explicit RodRodCollision(const btCollisionAlgorithmConstructionInfo& info)
      : btCollisionAlgorithm(info) {}
  ~RodRodCollision() override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

 private:
  void release_from(std::size_t first);

  std::vector<btPersistentManifold*> manifolds_;  ///< filled four points each, cleared every step
};

}  // namespace rodsort::engine
