#pragma once

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>

#include <cstdint>
#include <limits>
#include <vector>

class btPersistentManifold;

namespace rodsort::engine {

/// Contacts between two rods (or a rod and a periodic image), sphere against sphere behind a
/// bounding-capsule test; see rod_rod_collision.cpp.
class RodRodCollision : public btCollisionAlgorithm {
 public:
  /// Counts the steps it skips a pair on in `*skipped` (null: not counted).
  RodRodCollision(const btCollisionAlgorithmConstructionInfo& info, std::int64_t* skipped)
      : btCollisionAlgorithm(info), skipped_(skipped) {}
  ~RodRodCollision() override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1.0;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

  /// Whether the pair of `a` and `b` (this algorithm's two rods) is skipped at this step: they
  /// were apart at the last test by more than they have travelled since. Counts the skip.
  bool skips(const btCollisionObject& a, const btCollisionObject& b);

 private:
  void release_from(std::size_t first);

  std::vector<btPersistentManifold*> manifolds_;  ///< filled four points each, cleared every step
  /// The pair is skipped while the two rods' BodyTag::travel sum stays below this [mm]: they were
  /// apart by more than that can close (NaN: test at the next step).
  double skip_below_travel_ = std::numeric_limits<double>::quiet_NaN();
  std::int64_t* skipped_;
};

}  // namespace rodsort::engine
