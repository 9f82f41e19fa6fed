// The persistent contacts of the rods with the plates and the walls.
//
// A rod's contacts with a plate or a wall persist from step to step in Bullet's manifolds (one per
// sphere: rod_plate_collision.cpp, rod_wall_collision.cpp), and the solver starts each step from
// the impulses they carry (warm starting); a point also remembers where on the rod it was made,
// which decides whether the next step's point replaces it or joins it. A State therefore holds
// every such manifold, point by point, and a rebuilt world hands each collision algorithm the
// manifolds it had, when it is created at the first step after a restore. Contacts between rods
// are made afresh at every step (rod_rod_collision.cpp) and carry nothing over.
#include "engine/surface_contacts.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <algorithm>
#include <utility>

#include "engine/body_tag.hpp"

namespace rodsort::engine {
namespace {

std::array<double, 3> from_bullet(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btVector3 to_bullet(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

ContactPointState save_point(const btManifoldPoint& point) {
  ContactPointState saved{};
  saved.local_a = from_bullet(point.m_localPointA);
  saved.local_b = from_bullet(point.m_localPointB);
  saved.world_a = from_bullet(point.m_positionWorldOnA);
  saved.world_b = from_bullet(point.m_positionWorldOnB);
  saved.normal = from_bullet(point.m_normalWorldOnB);
  saved.friction_dir1 = from_bullet(point.m_lateralFrictionDir1);
  saved.friction_dir2 = from_bullet(point.m_lateralFrictionDir2);
  saved.distance = point.m_distance1;
  saved.combined = {point.m_combinedFriction, point.m_combinedRollingFriction,
                    point.m_combinedSpinningFriction, point.m_combinedRestitution};
  saved.solver = {point.m_appliedImpulse,
                  point.m_prevRHS,
                  point.m_appliedImpulseLateral1,
                  point.m_appliedImpulseLateral2,
                  point.m_contactMotion1,
                  point.m_contactMotion2,
                  point.m_contactCFM,
                  point.m_contactERP,
                  point.m_frictionCFM};
  saved.ids = {point.m_partId0, point.m_partId1,           point.m_index0,
               point.m_index1,  point.m_contactPointFlags, point.m_lifeTime};
  return saved;
}

btManifoldPoint load_point(const ContactPointState& saved) {
  btManifoldPoint point(to_bullet(saved.local_a), to_bullet(saved.local_b), to_bullet(saved.normal),
                        saved.distance);
  point.m_positionWorldOnA = to_bullet(saved.world_a);
  point.m_positionWorldOnB = to_bullet(saved.world_b);
  point.m_lateralFrictionDir1 = to_bullet(saved.friction_dir1);
  point.m_lateralFrictionDir2 = to_bullet(saved.friction_dir2);
  point.m_combinedFriction = saved.combined[0];
  point.m_combinedRollingFriction = saved.combined[1];
  point.m_combinedSpinningFriction = saved.combined[2];
  point.m_combinedRestitution = saved.combined[3];
  point.m_appliedImpulse = saved.solver[0];
  point.m_prevRHS = saved.solver[1];
  point.m_appliedImpulseLateral1 = saved.solver[2];
  point.m_appliedImpulseLateral2 = saved.solver[3];
  point.m_contactMotion1 = saved.solver[4];
  point.m_contactMotion2 = saved.solver[5];
  point.m_contactCFM = saved.solver[6];
  point.m_contactERP = saved.solver[7];
  point.m_frictionCFM = saved.solver[8];
  point.m_partId0 = saved.ids[0];
  point.m_partId1 = saved.ids[1];
  point.m_index0 = saved.ids[2];
  point.m_index1 = saved.ids[3];
  point.m_contactPointFlags = saved.ids[4];
  point.m_lifeTime = saved.ids[5];
  return point;
}

}  // namespace

int surface_of(const BodyTag& tag) {
  switch (tag.kind) {
    case BodyKind::kBase:
      return 0;
    case BodyKind::kLid:
      return 1;
    case BodyKind::kWall:
      return 2 + tag.wall;
    default:
      return -1;
  }
}

std::vector<SurfaceContactState> save_surface_contacts(btDispatcher& dispatcher) {
  std::vector<SurfaceContactState> contacts;
  const int manifold_count = dispatcher.getNumManifolds();
  for (int m = 0; m < manifold_count; ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    if (manifold.getNumContacts() == 0) continue;
    // The rod algorithms make every plate and wall manifold with the rod as body 0.
    const auto& rod = *static_cast<const BodyTag*>(manifold.getBody0()->getUserPointer());
    const auto& other = *static_cast<const BodyTag*>(manifold.getBody1()->getUserPointer());
    const int surface = surface_of(other);
    if (rod.kind != BodyKind::kRod || surface < 0) continue;
    SurfaceContactState& contact = contacts.emplace_back();
    contact.rod = rod.rod;
    contact.surface = surface;
    // Every point of a sphere's manifold names the sphere as its index on body 0.
    contact.sphere = manifold.getContactPoint(0).m_index0;
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      contact.points.push_back(save_point(manifold.getContactPoint(p)));
    }
  }
  std::sort(contacts.begin(), contacts.end(), comes_before);
  return contacts;
}

void RestoredContacts::assign(std::vector<SurfaceContactState> contacts) {
  contacts_ = std::move(contacts);
  pending_ = true;
}

void RestoredContacts::clear() {
  if (!pending_) return;
  contacts_.clear();
  contacts_.shrink_to_fit();
  pending_ = false;
}

std::span<const SurfaceContactState> RestoredContacts::of(int rod, int surface) const {
  const std::pair<int, int> wanted(rod, surface);
  const auto first = std::lower_bound(
      contacts_.begin(), contacts_.end(), wanted,
      [](const SurfaceContactState& c, const auto& w) { return std::pair(c.rod, c.surface) < w; });
  const auto last = std::upper_bound(
      first, contacts_.end(), wanted,
      [](const auto& w, const SurfaceContactState& c) { return w < std::pair(c.rod, c.surface); });
  return {first, last};
}

void add_sphere_contact(btDispatcher& dispatcher, btPersistentManifold*& manifold,
                        const btCollisionObject* rod, const btCollisionObject* surface,
                        bool rod_is_body0, int sphere, btManifoldResult& result,
                        const btVector3& normal, const btVector3& point, double depth) {
  if (!manifold) manifold = new_manifold(dispatcher, rod, surface);
  if (rod_is_body0) {
    result.setShapeIdentifiersA(-1, sphere);
  } else {
    result.setShapeIdentifiersB(-1, sphere);
  }
  result.setPersistentManifold(manifold);
  result.refreshContactPoints();
  result.addContactPoint(normal, point, depth);
  result.refreshContactPoints();
}

void load_points(btPersistentManifold& manifold, const SurfaceContactState& saved) {
  // Appended in order: a manifold of at most four points keeps them where they were.
  for (const ContactPointState& point : saved.points) manifold.addManifoldPoint(load_point(point));
}

void restore_sphere_manifolds(btDispatcher& dispatcher, const btCollisionObject* rod,
                              const btCollisionObject* surface,
                              std::span<const SurfaceContactState> restored,
                              std::vector<btPersistentManifold*>& manifolds) {
  for (const SurfaceContactState& saved : restored) {
    btPersistentManifold*& manifold = manifolds.at(static_cast<std::size_t>(saved.sphere));
    manifold = new_manifold(dispatcher, rod, surface);
    load_points(*manifold, saved);
  }
}

}  // namespace rodsort::engine
