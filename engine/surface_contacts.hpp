#pragma once
// The persistent contacts of the rods with the plates and the walls, between a State and Bullet's
// manifolds; see surface_contacts.cpp.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/state.hpp"

class btCollisionObject;
class btDispatcher;
class btManifoldResult;
class btPersistentManifold;
class btVector3;

namespace rodsort::engine {

struct BodyTag;

/// The surface number of a State's contacts for a plate or a wall: 0 the base, 1 the lid, 2 + w
/// wall w; -1 for a rod or an image.
int surface_of(const BodyTag& tag);

/// The manifolds of `dispatcher` between a rod and a plate or a wall that hold points, as a
/// State's contacts, sorted.
std::vector<SurfaceContactState> save_surface_contacts(btDispatcher& dispatcher);

/// A State's contacts, held until the collision algorithms of a rebuilt world ask for theirs.
class RestoredContacts {
 public:
  /// `contacts` sorted (check_state).
  void assign(std::vector<SurfaceContactState> contacts);
  void clear();
  /// Assigned and not yet cleared: the world has not stepped since it was rebuilt.
  bool pending() const { return pending_; }
  const std::vector<SurfaceContactState>& all() const { return contacts_; }
  /// The manifolds of `rod` with `surface`, by sphere; empty when there are none.
  std::span<const SurfaceContactState> of(int rod, int surface) const;

 private:
  std::vector<SurfaceContactState> contacts_;
  bool pending_ = false;
};

/// Fills an empty manifold with a saved manifold's points, every field as it was.
void load_points(btPersistentManifold& manifold, const SurfaceContactState& saved);

/// Remakes the saved manifolds of `rod` with a plate or wall `surface`, each in the slot of its
/// sphere in `manifolds` (one per sphere, null where none): what a rod-plate or rod-wall algorithm
/// does when a restored world first creates it.
void restore_sphere_manifolds(btDispatcher& dispatcher, const btCollisionObject* rod,
                              const btCollisionObject* surface,
                              std::span<const SurfaceContactState> restored,
                              std::vector<btPersistentManifold*>& manifolds);

/// Adds the contact of sphere `sphere` of `rod` with a plate or wall `surface` to the sphere's own
/// persistent manifold (made on its first contact), refreshed and merged by Bullet's
/// btManifoldResult as Bullet's compound algorithm does. `normal` on the surface, toward the rod;
/// `point` on the surface; `depth` negative when penetrating [mm].
void add_sphere_contact(btDispatcher& dispatcher, btPersistentManifold*& manifold,
                        const btCollisionObject* rod, const btCollisionObject* surface,
                        bool rod_is_body0, int sphere, btManifoldResult& result,
                        const btVector3& normal, const btVector3& point, double depth);

}  // namespace rodsort::engine
