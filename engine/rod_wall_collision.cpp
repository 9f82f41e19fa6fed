// Rod-wall contacts.
//
// A wall is a box standing across the gap at any angle. Its axis-aligned bounding box, which is
// all Bullet's generic compound algorithm tests before running GJK for each sphere, is large for
// a slanted trap arm (22 x 39 mm for a 45 mm arm at 60°): every rod in it paid nine GJK searches
// per step, and in the paper's trap system this was the largest single cost of a step.
//
// Here the rod is first bounded in the wall's own frame (its axis segment, thickened by its largest
// radius, against the box), and only rods that can touch go sphere by sphere. The contacts are the
// ones GJK finds: Bullet treats a box as its core (the half extents less the collision margin)
// rounded by the margin, and a sphere as its centre rounded by its radius, so the distance is that
// from the sphere's centre to the core box, less margin and radius; the normal points from the
// closest point of the core to the centre; a point is kept up to the manifold's contact-breaking
// distance (such speculative points are not used by the solver, whose contact processing threshold
// is 0 for rods). Each sphere keeps its own persistent manifold, as with Bullet's compound
// algorithm, refreshed and merged by Bullet's btManifoldResult; but a manifold exists only while
// its sphere is within that distance, where Bullet kept one, mostly empty, for every sphere inside
// the wall's bounding box (some 700 of them in the paper's system), so the solver meets the
// contacts in another order.
//
// A rod that is not straight is bounded by its axis segment thickened by its largest radius plus
// its spheres' largest offset from the axis, and each sphere's centre adds that offset.
//
// A rod with no sphere within the contact-breaking distance gives the gap by which it stays out of
// it, and the pair is not tested again until the rod has travelled that far (apart_pair.hpp; the
// wall does not move): a skipped test is one that would have made nothing, as for rod pairs
// (rod_rod_collision.cpp).
#include "engine/rod_wall_collision.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/body_tag.hpp"
#include "engine/rod_geometry.hpp"
#include "engine/surface_contacts.hpp"

namespace rodsort::engine {

RodWallCollision::RodWallCollision(const btCollisionAlgorithmConstructionInfo& info,
                                   const btCollisionObjectWrapper* rod,
                                   const btCollisionObjectWrapper* wall, bool rod_is_body0,
                                   std::span<const SurfaceContactState> restored,
                                   std::int64_t* skipped)
    : btCollisionAlgorithm(info),
      rod_is_body0_(rod_is_body0),
      // As new_manifold sets it.
      breaking_threshold_(
          std::min(rod->getCollisionObject()->getCollisionShape()->getContactBreakingThreshold(
                       kContactBreakingFactor),
                   wall->getCollisionObject()->getCollisionShape()->getContactBreakingThreshold(
                       kContactBreakingFactor))),
      manifolds_(RodGeometry::of(*rod->getCollisionShape()).axial.size(), nullptr),
      apart_(travel_of(*rod->getCollisionObject()), &kStill, skipped) {
  restore_sphere_manifolds(*m_dispatcher, rod->getCollisionObject(), wall->getCollisionObject(),
                           restored, manifolds_);
}

RodWallCollision::~RodWallCollision() {
  for (btPersistentManifold*& manifold : manifolds_) release(manifold);
}

void RodWallCollision::release(btPersistentManifold*& manifold) {
  if (!manifold) return;
  m_dispatcher->releaseManifold(manifold);
  manifold = nullptr;
}

void RodWallCollision::processCollision(const btCollisionObjectWrapper* body0,
                                        const btCollisionObjectWrapper* body1,
                                        const btDispatcherInfo& /*dispatch_info*/,
                                        btManifoldResult* result) {
  const btCollisionObjectWrapper* rod = rod_is_body0_ ? body0 : body1;
  const btCollisionObjectWrapper* wall = rod_is_body0_ ? body1 : body0;
  if (apart_.skips()) return;  // out of reach at the last test, and since
  const RodGeometry& geometry = RodGeometry::of(*rod->getCollisionShape());
  const btTransform& pose = rod->getWorldTransform();
  const btVector3 axis = pose.getBasis().getColumn(0);
  const auto* box = static_cast<const btBoxShape*>(wall->getCollisionShape());
  const btVector3 core = box->getHalfExtentsWithoutMargin();
  const double margin = box->getMargin();
  const btTransform& wall_pose = wall->getWorldTransform();

  // The rod's axis segment in the wall's frame, bounded by a box grown by the largest radius.
  const btVector3 end0 = wall_pose.invXform(axis * geometry.axial_min + pose.getOrigin());
  const btVector3 end1 = wall_pose.invXform(axis * geometry.axial_max + pose.getOrigin());
  const double reach = geometry.max_radius + geometry.max_lateral + margin + breaking_threshold_;
  // Apart along some axis of the wall's frame by `separation` > 0: every sphere's distance from
  // the wall exceeds the breaking distance by at least that.
  double separation = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    separation = std::max({separation, std::min(end0[k], end1[k]) - reach - core[k],
                           -core[k] - (std::max(end0[k], end1[k]) + reach)});
  }
  if (separation > 0.0) {
    for (btPersistentManifold*& manifold : manifolds_) release(manifold);
    apart_.tested(separation);
    return;
  }

  double gap = std::numeric_limits<double>::infinity();  // the least of depth - breaking distance
  const btVector3 side = pose.getBasis().getColumn(1);
  for (std::size_t i = 0; i < manifolds_.size(); ++i) {
    btVector3 in_world = axis * geometry.axial[i] + pose.getOrigin();
    if (!geometry.straight) in_world += side * geometry.lateral[i];
    const btVector3 center = wall_pose.invXform(in_world);
    btVector3 closest(std::clamp(center.x(), -core.x(), core.x()),
                      std::clamp(center.y(), -core.y(), core.y()),
                      std::clamp(center.z(), -core.z(), core.z()));
    btVector3 normal;  // in the wall's frame, out of the core toward the sphere's centre
    double centre_distance;
    const btVector3 offset = center - closest;
    const double length = offset.length();
    if (length > SIMD_EPSILON) {
      normal = offset / length;
      centre_distance = length;
    } else {
      // The centre is inside the core: push out through the nearest face.
      int face = 0;
      for (int k = 1; k < 3; ++k) {
        if (core[k] - std::abs(center[k]) < core[face] - std::abs(center[face])) face = k;
      }
      normal.setZero();
      normal[face] = center[face] < 0.0 ? -1.0 : 1.0;
      centre_distance = -(core[face] - std::abs(center[face]));
      closest[face] = normal[face] * core[face];
    }
    const double depth = centre_distance - margin - geometry.radius[i];
    btPersistentManifold*& manifold = manifolds_[i];
    gap = std::min(gap, depth - breaking_threshold_);
    if (depth > breaking_threshold_) {
      release(manifold);
      continue;
    }
    const btVector3 on_wall = wall_pose * (closest + normal * margin);
    add_sphere_contact(*m_dispatcher, manifold, rod->getCollisionObject(),
                       wall->getCollisionObject(), rod_is_body0_, static_cast<int>(i), *result,
                       wall_pose.getBasis() * normal, on_wall, depth);
  }
  apart_.tested(gap);  // positive only if every sphere was released
}

void RodWallCollision::getAllContactManifolds(btManifoldArray& manifolds) {
  for (btPersistentManifold* manifold : manifolds_) {
    if (manifold) manifolds.push_back(manifold);
  }
}

}  // namespace rodsort::engine
