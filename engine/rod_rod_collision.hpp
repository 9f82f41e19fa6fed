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
  /// Counts the steps it skips a pair on in `*skipped` (null: not counted). `travel0` and
  /// `travel1`: the two rods' BodyTag::travel (travel_of), kept here so that the test whether to
  /// skip reads neither collision object; null for either, never skipped.
  RodRodCollision(const btCollisionAlgorithmConstructionInfo& info, std::int64_t* skipped,
                  const double* travel0, const double* travel1)
      : btCollisionAlgorithm(info), skipped_(skipped), travel0_(travel0), travel1_(travel1) {}
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
  bool skips() {
    if (!(travel() < skip_below_travel_)) return false;
    if (skipped_ != nullptr) ++*skipped_;
    return true;
  }

 private:
  void release_from(std::size_t first);
  /// The two rods' travel summed; NaN where either is not kept.
  double travel() const {
    return travel0_ != nullptr && travel1_ != nullptr ? *travel0_ + *travel1_
                                                      : std::numeric_limits<double>::quiet_NaN();
  }

  std::vector<btPersistentManifold*> manifolds_;  ///< filled four points each, cleared every step
  /// The pair is skipped while the two rods' BodyTag::travel sum stays below this [mm]: they were
  /// apart by more than that can close (NaN: test at the next step).
  double skip_below_travel_ = std::numeric_limits<double>::quiet_NaN();
  std::int64_t* skipped_;
  const double* travel0_;
  const double* travel1_;
};

}  // namespace rodsort::engine
