#pragma once

#include <LinearMath/btAlignedObjectArray.h>

class btCollisionObject;
class btPersistentManifold;
class btRigidBody;

namespace rodsort::engine {

/// The rods and their contact manifolds cut into batches of whole contact islands, for the solver
/// to take one at a time; see solver_batches.cpp.
class SolverBatches {
 public:
  /// Rods per batch, roughly: a batch's solver data must stay in the processor's cache over all
  /// the solver's iterations (about 2 kB per rod).
  static constexpr int kTargetRods = 128;

  /// `rods` are the world's dynamic bodies (each carries a BodyTag of kind kRod); `manifolds` are
  /// the dispatcher's, in its order.
  void build(const btAlignedObjectArray<btRigidBody*>& rods, btPersistentManifold** manifolds,
             int manifold_count);

  int size() const { return body_starts_.size() - 1; }
  btCollisionObject** bodies(int batch) { return &bodies_[body_starts_[batch]]; }
  int body_count(int batch) const { return body_starts_[batch + 1] - body_starts_[batch]; }
  btPersistentManifold** manifolds(int batch) {
    return manifold_count(batch) > 0 ? &manifolds_[manifold_starts_[batch]] : nullptr;
  }
  int manifold_count(int batch) const {
    return manifold_starts_[batch + 1] - manifold_starts_[batch];
  }

 private:
  int root(int rod);

  btAlignedObjectArray<int> parent_;          ///< union-find over rods
  btAlignedObjectArray<int> island_of_root_;  ///< by root rod, -1 until numbered
  btAlignedObjectArray<int> batch_of_island_;
  btAlignedObjectArray<int> island_size_;
  btAlignedObjectArray<int> manifold_batch_;  ///< per dispatcher manifold, -1 to skip
  btAlignedObjectArray<btCollisionObject*> bodies_;
  btAlignedObjectArray<btPersistentManifold*> manifolds_;
  btAlignedObjectArray<int> body_starts_, manifold_starts_;  ///< size() + 1 offsets each
};

}  // namespace rodsort::engine
