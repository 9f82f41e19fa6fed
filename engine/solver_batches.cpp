// Solving the contacts batch by batch.
//
// Bullet's sequential-impulse solver sweeps all contact constraints ten times per step (plus ten
// sweeps for split impulses), and each constraint row reads the solver bodies of its two bodies.
// With all rods in one call, as the periodic images require (periodic_boundary.cpp), a sweep
// streams through a few kilobytes per rod: a few hundred rods stay in the processor's cache from
// one sweep to the next, a few thousand do not, and every sweep then waits on memory. This was
// most of the growth of the cost per rod from 319 to 5,104 rods.
//
// A contact island is a set of rods linked by rod-rod contacts (a contact with a periodic image
// links the image's rod); plates and walls, which do not move in response, link nothing. Islands
// do not interact inside the solver: every row changes only the velocities of its own two bodies,
// and those of the plates and walls not at all (infinite mass). Solving island after island, each
// with all its sweeps, therefore gives exactly the result of solving them all at once, as long as
// each island's constraints keep their relative order, which they do here (the dispatcher's
// order). Small islands, most of them single rods, are grouped into batches of about kTargetRods
// rods so that each call to the solver does enough work; a batch holds whole islands only, so a
// rod's contacts, and gravity, are applied in exactly one batch.
#include "engine/solver_batches.hpp"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cassert>

#include "engine/body_tag.hpp"

namespace rodsort::engine {
namespace {

/// The rod a collision object stands for (a rod or its periodic image), or -1.
int rod_of(const btCollisionObject* object) {
  const auto* tag = static_cast<const BodyTag*>(object->getUserPointer());
  return tag->kind == BodyKind::kRod || tag->kind == BodyKind::kImage ? tag->rod : -1;
}

}  // namespace

int SolverBatches::root(int rod) {
  while (parent_[rod] != rod) {
    parent_[rod] = parent_[parent_[rod]];
    rod = parent_[rod];
  }
  return rod;
}

void SolverBatches::build(const btAlignedObjectArray<btRigidBody*>& rods,
                          btPersistentManifold** manifolds, int manifold_count) {
  const int rod_count = rods.size();
  parent_.resize(rod_count);
  for (int r = 0; r < rod_count; ++r) parent_[r] = r;
  manifold_batch_.resize(manifold_count);
  for (int m = 0; m < manifold_count; ++m) {
    const int rod0 = rod_of(manifolds[m]->getBody0());
    const int rod1 = rod_of(manifolds[m]->getBody1());
    // The manifold's island is known only once all unions are made; remember which rod to ask.
    manifold_batch_[m] = manifolds[m]->getNumContacts() > 0 ? (rod0 >= 0 ? rod0 : rod1) : -1;
    if (rod0 >= 0 && rod1 >= 0) {
      const int a = root(rod0), b = root(rod1);
      if (a != b) parent_[a < b ? b : a] = a < b ? a : b;
    }
  }

  // Number the islands by their first rod, and cut them into batches in that order.
  island_of_root_.resize(0);
  island_of_root_.resize(rod_count, -1);
  island_size_.resize(0);
  for (int r = 0; r < rod_count; ++r) {
    int& island = island_of_root_[root(r)];
    if (island < 0) {
      island = island_size_.size();
      island_size_.push_back(0);
    }
    ++island_size_[island];
  }
  batch_of_island_.resize(island_size_.size());
  body_starts_.resize(0);
  body_starts_.push_back(0);
  int in_batch = 0;
  for (int i = 0; i < island_size_.size(); ++i) {
    if (in_batch >= kTargetRods) {
      body_starts_.push_back(body_starts_[body_starts_.size() - 1] + in_batch);
      in_batch = 0;
    }
    batch_of_island_[i] = body_starts_.size() - 1;
    in_batch += island_size_[i];
  }
  body_starts_.push_back(body_starts_[body_starts_.size() - 1] + in_batch);
  const int batch_count = body_starts_.size() - 1;

  // Bodies by batch, in rod order within a batch.
  btAlignedObjectArray<int>& fill = island_size_;  // reused as each batch's next free slot
  fill.resize(batch_count);
  for (int b = 0; b < batch_count; ++b) fill[b] = body_starts_[b];
  bodies_.resize(rod_count);
  for (int r = 0; r < rod_count; ++r) {
    assert(rod_of(rods[r]) == r);
    bodies_[fill[batch_of_island_[island_of_root_[root(r)]]]++] = rods[r];
  }

  // Manifolds by batch, in the dispatcher's order within a batch.
  manifold_starts_.resize(0);
  manifold_starts_.resize(batch_count + 1, 0);
  for (int m = 0; m < manifold_count; ++m) {
    if (manifold_batch_[m] < 0) continue;
    manifold_batch_[m] = batch_of_island_[island_of_root_[root(manifold_batch_[m])]];
    ++manifold_starts_[manifold_batch_[m] + 1];
  }
  for (int b = 0; b < batch_count; ++b) manifold_starts_[b + 1] += manifold_starts_[b];
  for (int b = 0; b < batch_count; ++b) fill[b] = manifold_starts_[b];
  manifolds_.resize(manifold_starts_[batch_count]);
  for (int m = 0; m < manifold_count; ++m) {
    if (manifold_batch_[m] >= 0) manifolds_[fill[manifold_batch_[m]]++] = manifolds[m];
  }
}

}  // namespace rodsort::engine
