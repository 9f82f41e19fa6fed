#pragma once

#include <LinearMath/btAlignedObjectArray.h>

#include <cstdint>

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
  /// the dispatcher's, in any order: the batches hold them in the canonical order.
  void build(const btAlignedObjectArray<btRigidBody*>& rods, btPersistentManifold** manifolds,
             int manifold_count);

  /// A diagnostic: each rod's manifolds in the reverse of the canonical order, to check that
  /// results do not depend on the order (engine::Model::reverse_contact_order).
  void set_reversed(bool reversed) { reversed_ = reversed; }
  /// A diagnostic: all islands in one batch, to check that batching changes nothing
  /// (engine::Model::single_solver_batch).
  void set_single_batch(bool single) { single_batch_ = single; }

  int size() const { return body_starts_.size() - 1; }
  btCollisionObject** bodies(int batch) { return &bodies_[body_starts_[batch]]; }
  int body_count(int batch) const { return body_starts_[batch + 1] - body_starts_[batch]; }
  btPersistentManifold** manifolds(int batch) {
    return manifold_count(batch) > 0 ? &manifolds_[manifold_starts_[batch]] : nullptr;
  }
  int manifold_count(int batch) const {
    return manifold_starts_[batch + 1] - manifold_starts_[batch];
  }
  /// Every manifold with points, batch after batch, each in the canonical order.
  btPersistentManifold* const* all_manifolds() const {
    return manifolds_.size() > 0 ? &manifolds_[0] : nullptr;
  }
  int all_manifold_count() const { return manifolds_.size(); }

 private:
  /// A manifold's place among those of its lower rod.
  struct Key {
    std::uint64_t body0, body1;  ///< ranks of the two bodies
    int index0, index1;          ///< spheres of the first point
    bool operator<(const Key& other) const;
  };

  int root(int rod);
  /// Fills sorted_ with the manifolds that hold points, in the canonical order.
  void sort_canonically(btPersistentManifold** manifolds, int manifold_count, int rod_count);

  bool reversed_ = false;
  bool single_batch_ = false;
  btAlignedObjectArray<int> owner_;         ///< per dispatcher manifold: its lower rod, or -1
  btAlignedObjectArray<int> owner_starts_;  ///< rod_count + 1 offsets into sorted_
  btAlignedObjectArray<btPersistentManifold*> sorted_;
  btAlignedObjectArray<Key> keys_;            ///< of sorted_
  btAlignedObjectArray<int> fill_;            ///< next free slot, per rod or per batch
  btAlignedObjectArray<int> parent_;          ///< union-find over rods
  btAlignedObjectArray<int> island_of_root_;  ///< by root rod, -1 until numbered
  btAlignedObjectArray<int> batch_of_island_;
  btAlignedObjectArray<int> island_size_;
  btAlignedObjectArray<int> manifold_batch_;  ///< per sorted manifold
  btAlignedObjectArray<btCollisionObject*> bodies_;
  btAlignedObjectArray<btPersistentManifold*> manifolds_;
  btAlignedObjectArray<int> body_starts_, manifold_starts_;  ///< size() + 1 offsets each
};

}  // namespace rodsort::engine
