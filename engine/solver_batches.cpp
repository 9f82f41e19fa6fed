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
// each island's constraints meet in the same order in every sweep; with the random sweep order
// (periodic_boundary.cpp) the orders drawn depend on how islands are grouped into batches, so the
// grouping is part of the deterministic method, not of the physics. Small islands, most of them
// single rods, are grouped into batches of about kTargetRods rods so that each call to the solver
// does enough work; a batch holds whole islands only, so a rod's contacts, and gravity, are
// applied in exactly one batch.
//
// The order of the contacts. A sequential-impulse solver stopped after ten sweeps depends on the
// order in which it meets the constraints, and the dispatcher's list of manifolds is in an order
// that only the world's history decides (manifolds are appended as pairs are processed, in the
// broadphase's order, and a released one is replaced by the last). A world rebuilt from a State
// would meet its contacts in another order and drift away from the original. The manifolds are
// therefore put in a canonical order first: by their lower rod, then by the two bodies (plates,
// walls, rods, images) and the spheres of their first point. With that order and the persistent
// contacts in the State (surface_contacts.cpp), a restored world steps exactly as the original.
#include "engine/solver_batches.hpp"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <tuple>

#include "engine/body_tag.hpp"
#include "engine/surface_contacts.hpp"

namespace rodsort::engine {
namespace {

const BodyTag& tag_of(const btCollisionObject* object) {
  return *static_cast<const BodyTag*>(object->getUserPointer());
}

/// The rod a collision object stands for (a rod or its periodic image), or -1.
int rod_of(const btCollisionObject* object) {
  const BodyTag& tag = tag_of(object);
  return tag.kind == BodyKind::kRod || tag.kind == BodyKind::kImage ? tag.rod : -1;
}

/// Where a collision object comes in the canonical order of bodies: the base, the lid, the walls,
/// then each rod followed by its images.
std::uint64_t body_rank(const BodyTag& tag) {
  if (tag.kind != BodyKind::kRod && tag.kind != BodyKind::kImage) {
    return static_cast<std::uint64_t>(surface_of(tag));  // the base, the lid, the walls
  }
  const std::uint64_t rod = (std::uint64_t{1} << 40) + static_cast<std::uint64_t>(tag.rod) * 16;
  return tag.kind == BodyKind::kRod ? rod : rod + 1 + static_cast<std::uint64_t>(tag.shift);
}

}  // namespace

bool SolverBatches::Key::operator<(const Key& other) const {
  return std::tie(body0, body1, index0, index1) <
         std::tie(other.body0, other.body1, other.index0, other.index1);
}

int SolverBatches::root(int rod) {
  while (parent_[rod] != rod) {
    parent_[rod] = parent_[parent_[rod]];
    rod = parent_[rod];
  }
  return rod;
}

void SolverBatches::sort_canonically(btPersistentManifold** manifolds, int manifold_count,
                                     int rod_count) {
  // Counting sort by lower rod (stable), then insertion sort of each rod's few manifolds by key.
  owner_.resize(manifold_count);
  owner_starts_.resize(0);
  owner_starts_.resize(rod_count + 1, 0);
  for (int m = 0; m < manifold_count; ++m) {
    const btPersistentManifold& manifold = *manifolds[m];
    if (manifold.getNumContacts() == 0) {
      owner_[m] = -1;  // nothing to solve
      continue;
    }
    const int rod0 = rod_of(manifold.getBody0());
    const int rod1 = rod_of(manifold.getBody1());
    owner_[m] = rod0 < 0 ? rod1 : (rod1 < 0 ? rod0 : std::min(rod0, rod1));
    ++owner_starts_[owner_[m] + 1];
  }
  for (int r = 0; r < rod_count; ++r) owner_starts_[r + 1] += owner_starts_[r];
  sorted_.resize(owner_starts_[rod_count]);
  keys_.resize(sorted_.size());
  fill_.resize(rod_count);
  for (int r = 0; r < rod_count; ++r) fill_[r] = owner_starts_[r];
  for (int m = 0; m < manifold_count; ++m) {
    if (owner_[m] < 0) continue;
    const btPersistentManifold& manifold = *manifolds[m];
    const btManifoldPoint& first = manifold.getContactPoint(0);
    const int slot = fill_[owner_[m]]++;
    sorted_[slot] = manifolds[m];
    keys_[slot] = {body_rank(tag_of(manifold.getBody0())), body_rank(tag_of(manifold.getBody1())),
                   first.m_index0, first.m_index1};
  }
  for (int r = 0; r < rod_count; ++r) {
    for (int i = owner_starts_[r] + 1; i < owner_starts_[r + 1]; ++i) {
      const Key key = keys_[i];
      btPersistentManifold* manifold = sorted_[i];
      int j = i;
      for (; j > owner_starts_[r] && (reversed_ ? keys_[j - 1] < key : key < keys_[j - 1]); --j) {
        keys_[j] = keys_[j - 1];
        sorted_[j] = sorted_[j - 1];
      }
      keys_[j] = key;
      sorted_[j] = manifold;
    }
  }
}

void SolverBatches::build(const btAlignedObjectArray<btRigidBody*>& rods,
                          btPersistentManifold** manifolds, int manifold_count) {
  const int rod_count = rods.size();
  sort_canonically(manifolds, manifold_count, rod_count);
  const int sorted_count = sorted_.size();
  parent_.resize(rod_count);
  for (int r = 0; r < rod_count; ++r) parent_[r] = r;
  for (int m = 0; m < sorted_count; ++m) {
    const int rod0 = rod_of(sorted_[m]->getBody0());
    const int rod1 = rod_of(sorted_[m]->getBody1());
    if (rod0 >= 0 && rod1 >= 0) {
      // Each set's root is its lowest rod, whatever the order of the unions.
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
    if (in_batch >= kTargetRods && !single_batch_) {
      body_starts_.push_back(body_starts_[body_starts_.size() - 1] + in_batch);
      in_batch = 0;
    }
    batch_of_island_[i] = body_starts_.size() - 1;
    in_batch += island_size_[i];
  }
  body_starts_.push_back(body_starts_[body_starts_.size() - 1] + in_batch);
  const int batch_count = body_starts_.size() - 1;

  // Bodies by batch, in rod order within a batch.
  fill_.resize(batch_count);
  for (int b = 0; b < batch_count; ++b) fill_[b] = body_starts_[b];
  bodies_.resize(rod_count);
  for (int r = 0; r < rod_count; ++r) {
    assert(rod_of(rods[r]) == r);
    bodies_[fill_[batch_of_island_[island_of_root_[root(r)]]]++] = rods[r];
  }

  // Manifolds by batch, in the canonical order within a batch.
  manifold_batch_.resize(sorted_count);
  manifold_starts_.resize(0);
  manifold_starts_.resize(batch_count + 1, 0);
  for (int m = 0; m < sorted_count; ++m) {
    const int rod0 = rod_of(sorted_[m]->getBody0());
    const int rod = rod0 >= 0 ? rod0 : rod_of(sorted_[m]->getBody1());
    manifold_batch_[m] = batch_of_island_[island_of_root_[root(rod)]];
    ++manifold_starts_[manifold_batch_[m] + 1];
  }
  for (int b = 0; b < batch_count; ++b) manifold_starts_[b + 1] += manifold_starts_[b];
  for (int b = 0; b < batch_count; ++b) fill_[b] = manifold_starts_[b];
  manifolds_.resize(sorted_count);
  for (int m = 0; m < sorted_count; ++m) manifolds_[fill_[manifold_batch_[m]]++] = sorted_[m];
}

}  // namespace rodsort::engine
