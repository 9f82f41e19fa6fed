// Rod-plate contacts, the bulk of all collision work: every rod meets the base and usually the lid
// at every step.
//
// Bullet's generic path for a compound of spheres against a box runs, for each of the rod's
// spheres, a transform product, two AABB computations and, for a sphere touching the plate, a GJK
// closest-point search. Against a horizontal slab all of it reduces to one number per sphere: the
// height of its lowest (base) or highest (lid) point above or below the plate's surface.
//
// The contacts are those Bullet's compound algorithm makes, so the physics does not change: a
// sphere has a contact exactly when it reaches the plate's surface (where its AABB starts to
// overlap the plate's), the point lies on the surface under the sphere's centre, the normal is
// vertical, and each touching sphere keeps its own persistent manifold, refreshed and merged by
// Bullet's own btManifoldResult, so that contacts persist and warm-start as before. A manifold
// holds at most four points and a rod lying on its side touches with all of its spheres (their
// envelope is a cone, tangent to the plate along a line), hence one manifold per sphere rather than
// one per rod.
//
// A sphere off the rod's axis (a rod that is not straight, rod_shape.hpp) adds its offset along the
// body y axis to its centre; a straight rod's algorithm leaves that term out.
//
// A rough plate (plate_roughness.hpp) is met through its tangent plane under each sphere's centre:
// the normal is that of the surface h(x, y) at the centre's (x, y), and the depth is the sphere's
// distance to that plane. For the slopes allowed (at most 0.3 rad) and spheres small against the
// wavelength this is the exact contact up to terms of order radius x slope x curvature.
#include "engine/rod_plate_collision.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>

#include <cmath>

#include "engine/body_tag.hpp"
#include "engine/plate_roughness.hpp"
#include "engine/rod_geometry.hpp"
#include "engine/surface_contacts.hpp"

namespace rodsort::engine {

RodPlateCollision::RodPlateCollision(const btCollisionAlgorithmConstructionInfo& info,
                                     const btCollisionObjectWrapper* rod,
                                     const btCollisionObjectWrapper* plate, bool rod_is_body0,
                                     std::span<const SurfaceContactState> restored)
    : btCollisionAlgorithm(info),
      rod_is_body0_(rod_is_body0),
      manifolds_(RodGeometry::of(*rod->getCollisionShape()).axial.size(), nullptr),
      clear_(manifolds_.size(), 0) {
  restore_sphere_manifolds(*m_dispatcher, rod->getCollisionObject(), plate->getCollisionObject(),
                           restored, manifolds_);
}

RodPlateCollision::~RodPlateCollision() {
  for (btPersistentManifold* manifold : manifolds_) {
    if (manifold) m_dispatcher->releaseManifold(manifold);
  }
}

void RodPlateCollision::processCollision(const btCollisionObjectWrapper* body0,
                                         const btCollisionObjectWrapper* body1,
                                         const btDispatcherInfo& /*dispatch_info*/,
                                         btManifoldResult* result) {
  const btCollisionObjectWrapper* rod = rod_is_body0_ ? body0 : body1;
  const btCollisionObjectWrapper* plate = rod_is_body0_ ? body1 : body0;
  const RodGeometry& geometry = RodGeometry::of(*rod->getCollisionShape());
  const btTransform& pose = rod->getWorldTransform();
  const btVector3 axis = pose.getBasis().getColumn(0);

  const auto* tag = static_cast<const BodyTag*>(plate->getCollisionObject()->getUserPointer());
  const bool base = tag->kind == BodyKind::kBase;
  const double half_thickness =
      static_cast<const btBoxShape*>(plate->getCollisionShape())->getHalfExtentsWithMargin().z();
  const double plate_z = plate->getWorldTransform().getOrigin().z();
  const double surface = base ? plate_z + half_thickness : plate_z - half_thickness;
  const btVector3& origin = pose.getOrigin();
  if (tag->roughness != nullptr) {
    process_rough(*tag->roughness, base, surface, geometry, pose, rod, plate, result);
    return;
  }
  // The normal on the plate (body B of every manifold here), pointing toward the rod.
  const btVector3 normal(0.0, 0.0, base ? 1.0 : -1.0);

  int kept = 0;  // manifolds that exist and may need releasing below
  const btVector3 body_y = pose.getBasis().getColumn(1);
  const auto height_of = [&](std::size_t i) {
    // The height of pose * (axial, lateral, 0), written out; the rest of the centre only on
    // contact.
    const double center_z = axis.z() * geometry.axial[i] + origin.z();
    return geometry.straight ? center_z : center_z + body_y.z() * geometry.lateral[i];
  };
  for (std::size_t i = 0; i < manifolds_.size(); ++i) {
    const double center_z = height_of(i);
    const double r = geometry.radius[i];
    const double depth = base ? (center_z - r) - surface : surface - (center_z + r);
    btPersistentManifold*& manifold = manifolds_[i];
    if (depth > 0.0) {
      kept += manifold != nullptr;
      continue;
    }
    double center_x = axis.x() * geometry.axial[i] + origin.x();
    double center_y = axis.y() * geometry.axial[i] + origin.y();
    if (!geometry.straight) {
      center_x += body_y.x() * geometry.lateral[i];
      center_y += body_y.y() * geometry.lateral[i];
    }
    add_sphere_contact(*m_dispatcher, manifold, rod->getCollisionObject(),
                       plate->getCollisionObject(), rod_is_body0_, static_cast<int>(i), *result,
                       normal, btVector3(center_x, center_y, surface), depth);
  }
  // Manifolds of spheres that left the plate go only after the new ones were made, as with
  // Bullet's compound algorithm: the dispatcher's list, and so the order in which the solver meets
  // the contacts, stays the same. It matters: with ten solver iterations the contacts of a rod
  // landing on several spheres at once are not converged, and releasing first (which reorders the
  // list) moved a single rod's mean speed by 8% at dt = 1e-4 s.
  for (std::size_t i = 0; kept > 0 && i < manifolds_.size(); ++i) {
    btPersistentManifold*& manifold = manifolds_[i];
    if (!manifold) continue;
    const double center_z = height_of(i);
    const double r = geometry.radius[i];
    const double depth = base ? (center_z - r) - surface : surface - (center_z + r);
    if (depth > 0.0) {
      m_dispatcher->releaseManifold(manifold);
      manifold = nullptr;
      --kept;
    }
  }
}

void RodPlateCollision::process_rough(const PlateRoughness& roughness, bool base,
                                      double box_surface, const RodGeometry& geometry,
                                      const btTransform& pose, const btCollisionObjectWrapper* rod,
                                      const btCollisionObjectWrapper* plate,
                                      btManifoldResult* result) {
  // The plate's box stands out by the roughness's reach (plate_drive.hpp).
  const double surface = base ? box_surface - roughness.reach() : box_surface + roughness.reach();
  const double side = base ? 1.0 : -1.0;
  const btVector3 axis = pose.getBasis().getColumn(0);
  const btVector3 body_y = pose.getBasis().getColumn(1);
  const btVector3& origin = pose.getOrigin();
  struct Contact {
    btVector3 normal, point;
    double depth;
  };
  const auto center_of = [&](std::size_t i) {
    const btVector3 center = origin + axis * geometry.axial[i];
    return geometry.straight ? center : center + body_y * geometry.lateral[i];
  };
  const auto contact_of = [&](std::size_t i) {
    const btVector3 center = center_of(i);
    const PlateRoughness::Surface local = roughness.at(center.x(), center.y());
    // Normal on the plate toward the rod: the surface's upward normal, turned down for the lid.
    const btVector3 normal = btVector3(-local.slope_x, -local.slope_y, 1.0).normalized() * side;
    const btVector3 on_surface(center.x(), center.y(), surface + local.height);
    const double depth = normal.dot(center - on_surface) - geometry.radius[i];
    return Contact{normal, center - normal * (geometry.radius[i] + depth), depth};
  };
  // The depth is n_z (z_centre - surface - h) - r with h <= reach and n_z >= 1 / sqrt(1 + g^2),
  // g the steepest slope: a sphere whose gap to the nominal surface exceeds
  // reach + r (sqrt(1 + g^2) - 1) is clear without evaluating the field.
  const double tilt_excess = std::sqrt(1.0 + roughness.max_slope() * roughness.max_slope()) - 1.0;
  int kept = 0;
  for (std::size_t i = 0; i < manifolds_.size(); ++i) {
    btPersistentManifold*& manifold = manifolds_[i];
    const double center_z = center_of(i).z();
    const double gap = side * (center_z - surface) - geometry.radius[i];
    if (gap > roughness.reach() + tilt_excess * geometry.radius[i]) {
      clear_[i] = 1;
      kept += manifold != nullptr;
      continue;
    }
    const Contact contact = contact_of(i);
    clear_[i] = contact.depth > 0.0 ? 1 : 0;
    if (clear_[i]) {
      kept += manifold != nullptr;
      continue;
    }
    add_sphere_contact(*m_dispatcher, manifold, rod->getCollisionObject(),
                       plate->getCollisionObject(), rod_is_body0_, static_cast<int>(i), *result,
                       contact.normal, contact.point, contact.depth);
  }
  // Released after the new ones were made, as on a flat plate (below).
  for (std::size_t i = 0; kept > 0 && i < manifolds_.size(); ++i) {
    btPersistentManifold*& manifold = manifolds_[i];
    if (manifold && clear_[i]) {
      m_dispatcher->releaseManifold(manifold);
      manifold = nullptr;
      --kept;
    }
  }
}

void RodPlateCollision::getAllContactManifolds(btManifoldArray& manifolds) {
  for (btPersistentManifold* manifold : manifolds_) {
    if (manifold) manifolds.push_back(manifold);
  }
}

}  // namespace rodsort::engine
