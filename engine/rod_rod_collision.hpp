#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>

#include <cstdint>
#include <vector>

#include "engine/apart_pair.hpp"

class btPersistentManifold;

namespace rodsort::engine {

/// Contacts between two rods (or a rod and a periodic image), sphere against sphere behind a
/// bounding-capsule test; see rod_rod_collision.cpp.
class RodRodCollision : public btCollisionAlgorithm {
 public:
  /// Counts the steps it skips a pair on in `*skipped` (null: not counted). `travel0` and
  /// `travel1`: the two rods' BodyTag::travel (travel_of), kept here so that the test whether to
  /// skip reads neither collision object; null for either, never skipped.
  RodRodCollision(const btCollisionAlgorithmConstructionInfo& info, std::int64_t* skipped,
                  const Travel* travel0, const Travel* travel1)
      : btCollisionAlgorithm(info), apart_(travel0, travel1, skipped) {}
  ~RodRodCollision() override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

  /// Whether the pair is skipped at this step: its rods were apart at the last test by more than
  /// they have travelled since. Counts the skip.
  bool skips() { return apart_.skips(); }

 private:
  void release_from(std::size_t first);

  std::vector<btPersistentManifold*> manifolds_;  ///< filled four points each, cleared every step
  ApartPair apart_;
};

}  // namespace rodsort::engine
