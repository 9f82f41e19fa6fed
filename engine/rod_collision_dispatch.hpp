#pragma once
// Wires the rod collision algorithms into Bullet's dispatcher in place of its generic compound
// algorithms: rod-plate pairs get RodPlateCollision, rod-wall pairs RodWallCollision, rod-rod and
// rod-image pairs RodRodCollision. Every compound in a simulation is a rod, every box a plate or a
// wall.

#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>

#include <cstdint>

class btCollisionDispatcher;
struct btBroadphasePair;
struct btDispatcherInfo;

namespace rodsort::engine {

class RestoredContacts;

class RodCollisionDispatch {
 public:
  /// Construction info for the world's btDefaultCollisionConfiguration: its algorithm pool must
  /// hold the rod algorithms too.
  static btDefaultCollisionConstructionInfo configuration_info();

  /// Registers the algorithms with `dispatcher`; this object must outlive the dispatcher's use.
  /// A rod-plate or rod-wall algorithm, when it is created, takes its pair's manifolds from
  /// `restored` (null: none), which must outlive the dispatcher's use too. Rod-rod and rod-wall
  /// algorithms count the tests they skip in `*pairs_skipped` (null: not counted).
  RodCollisionDispatch(btCollisionDispatcher& dispatcher, const RestoredContacts* restored,
                       std::int64_t* pairs_skipped = nullptr);

  RodCollisionDispatch(const RodCollisionDispatch&) = delete;
  RodCollisionDispatch& operator=(const RodCollisionDispatch&) = delete;

 private:
  /// Bullet's default near callback, except that a pair of rods, or a rod and a wall, still apart
  /// (RodRodCollision::skips, RodWallCollision::skips) returns at once, before Bullet wraps the
  /// two objects and makes a result for them.
  static void near_callback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                            const btDispatcherInfo& info);

  /// A rod (compound) against a box: a plate or a wall, told apart by the box's BodyTag.
  struct RodBox : btCollisionAlgorithmCreateFunc {
    bool rod_is_body0 = true;
    const RestoredContacts* restored = nullptr;
    std::int64_t* skipped = nullptr;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
  };
  struct RodRod : btCollisionAlgorithmCreateFunc {
    std::int64_t* skipped = nullptr;
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
  };

  RodBox rod_box_, box_rod_;
  RodRod rod_rod_;
};

}  // namespace rodsort::engine
