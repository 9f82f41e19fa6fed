// Rod-rod contacts.
//
// Bullet's generic path for two compounds without AABB trees runs a compound algorithm for every
// sphere of one rod against the other rod, and in it a sphere-sphere algorithm for every pair whose
// AABBs overlap, with a transform product and AABB computations per child: 81 child pairs for two
// rods of 9 spheres whose bounding boxes touch, which is most of the time not a contact at all.
//
// Here a pair of rods is first tested as two bounding spheres, then as two capsules (each rod's
// axis segment, thickened by its largest radius), then each sphere of one rod against the other
// rod's axis; only spheres that pass are compared exactly. The contacts are those Bullet makes, bit
// for bit: one point for each pair of overlapping spheres, on the surface of the first body's
// sphere along the line of centres, with no persistence (Bullet's sphere-sphere algorithm clears
// its manifold every step, so rod-rod contacts never warm-start). Points are therefore written
// straight into manifolds emptied at each step, four to a manifold, without Bullet's merging of
// nearby points, which applies within one manifold and which Bullet's one manifold per sphere pair
// never triggers either. What differs is the order in which the solver meets the points (one
// manifold per rod pair instead of one per sphere pair, created and released at other moments),
// which changes results at the level of the solver's convergence, not the contacts.
//
// A rod that is not straight (rod_shape.hpp) has spheres off its axis, each within max_lateral of
// it: the bounding capsule and the cheap bounds below are widened by that, and the exact test adds
// each centre's offset along the body y axis.
//
// Pairs apart stay apart for a while. In a pile a rod has some five neighbours within its bounding
// box and touches few of them; most pairs the broadphase hands over make no point, step after step.
// Each test that makes no point also gives the gap between the two rods (a lower bound: exact for
// sphere pairs within a skin of touching, the bounding spheres' or capsules' gap otherwise, at
// most the skin), and the pair is not tested again until the two rods together have travelled
// that far (apart_pair.hpp; the simulation adds each step's move of the centre plus the axis's
// times the farthest sphere centre). No sphere pair can touch before then, so a skipped test is
// one that would have made no point: the contacts are the same, bit for bit.
#include "engine/rod_rod_collision.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <algorithm>
#include <cmath>

#include "engine/body_tag.hpp"
#include "engine/rod_geometry.hpp"
#include "engine/segment_distance.hpp"

namespace rodsort::engine {
namespace {

/// The cheap bounds below skip a sphere pair only when it is apart by more than rounding: beyond
/// this factor times the squared contact distance, plus this area [mm^2].
constexpr double kClearlyApart = 1.0 + 1e-9;
constexpr double kRoundingArea = 1e-12;

/// Sphere pairs nearer than this to touching are measured exactly for the gap; farther ones
/// count as this far [mm]. A pure matter of cost: a wider skin measures more pairs and skips
/// longer. The filled paper system takes the fewest instructions from 0.05 to 0.2 mm (callgrind,
/// docs/performance.md), 4% more at 0.02.
constexpr double kSkin = 0.1;

}  // namespace

RodRodCollision::~RodRodCollision() { release_from(0); }

void RodRodCollision::release_from(std::size_t first) {
  for (std::size_t m = first; m < manifolds_.size(); ++m)
    m_dispatcher->releaseManifold(manifolds_[m]);
  manifolds_.resize(std::min(first, manifolds_.size()));
}

void RodRodCollision::processCollision(const btCollisionObjectWrapper* body0,
                                       const btCollisionObjectWrapper* body1,
                                       const btDispatcherInfo& /*dispatch_info*/,
                                       btManifoldResult* /*result*/) {
  if (apart_.skips()) return;  // apart at the last test, no point since: none now

  const RodGeometry& geometry0 = RodGeometry::of(*body0->getCollisionShape());
  const RodGeometry& geometry1 = RodGeometry::of(*body1->getCollisionShape());
  const btTransform& pose0 = body0->getWorldTransform();
  const btTransform& pose1 = body1->getWorldTransform();
  const btVector3 axis0 = pose0.getBasis().getColumn(0);
  const btVector3 axis1 = pose1.getBasis().getColumn(0);

  for (btPersistentManifold* manifold : manifolds_) manifold->clearManifold();
  // Cheap rejections first: bounding spheres, then capsules.
  const double spheres_reach = geometry0.bounding_radius + geometry1.bounding_radius;
  const btVector3 between = (axis0 * geometry0.axial_center + pose0.getOrigin()) -
                            (axis1 * geometry1.axial_center + pose1.getOrigin());
  if (between.length2() > spheres_reach * spheres_reach) {
    release_from(0);
    apart_.tested(between.length() - spheres_reach);
    return;
  }
  const double capsule_reach =
      geometry0.max_radius + geometry0.max_lateral + geometry1.max_radius + geometry1.max_lateral;
  const double capsules = segment_distance_squared(axis0 * geometry0.axial_min + pose0.getOrigin(),
                                                   axis0 * geometry0.axial_max + pose0.getOrigin(),
                                                   axis1 * geometry1.axial_min + pose1.getOrigin(),
                                                   axis1 * geometry1.axial_max + pose1.getOrigin());
  if (capsules > capsule_reach * capsule_reach) {
    release_from(0);
    apart_.tested(std::sqrt(capsules) - capsule_reach);
    return;
  }

  // The points are those of Bullet's nested compound algorithms, bit for bit: for sphere i of
  // body 0 and sphere j of body 1, btSphereSphereCollisionAlgorithm runs with sphere j first, so
  // its manifold has body 1 as its A side and the normal points from sphere i toward sphere j.
  const btCollisionObject* object0 = body0->getCollisionObject();
  const btCollisionObject* object1 = body1->getCollisionObject();
  double friction = 0.0, restitution = 0.0, rolling_friction = 0.0, spinning_friction = 0.0;
  std::size_t points = 0;
  double gap = kSkin;  // the least of the sphere pairs' gaps, or the skin
  const btVector3 side0 = pose0.getBasis().getColumn(1);
  const btVector3 side1 = pose1.getBasis().getColumn(1);
  for (std::size_t i = 0; i < geometry0.axial.size(); ++i) {
    // pose * (axial, lateral, 0), written out.
    btVector3 center0 = axis0 * geometry0.axial[i] + pose0.getOrigin();
    if (!geometry0.straight) center0 += side0 * geometry0.lateral[i];
    const double radius0 = geometry0.radius[i];
    // Sphere j of body 1 is at a distance sqrt(across^2 + (axial_j - along)^2) from this centre,
    // measured along and across body 1's axis, less at most its offset from that axis: a cheap
    // bound before the exact test.
    const btVector3 from_origin1 = center0 - pose1.getOrigin();
    const double along = from_origin1.dot(axis1);
    const double across2 = from_origin1.length2() - along * along;
    // Bounds widened by the skin: a sphere pair they skip is apart by more than the skin.
    const double farthest = radius0 + geometry1.max_radius + geometry1.max_lateral + kSkin;
    const double bound = kClearlyApart * farthest * farthest + kRoundingArea;
    if (across2 > bound) continue;
    // Spheres of body 1 farther along its axis than `reach` from `along` fail the bound below for
    // any radius; with ascending centres they are left out (in a pile, most of the nine). `reach`
    // is the bound's, widened by a rounding area, so that the spheres left out are only ones the
    // test would skip.
    std::size_t j_begin = 0, j_end = geometry1.axial.size();
    if (geometry1.ascending) {
      const double reach = std::sqrt(bound - across2 + kRoundingArea);
      j_begin = geometry1.first_at_or_beyond(along - reach);
      j_end = geometry1.first_beyond(along + reach);
    }
    for (std::size_t j = j_begin; j < j_end; ++j) {
      const double radius1 = geometry1.radius[j];
      const double touching = radius0 + radius1;
      const double offset = geometry1.axial[j] - along;
      const double near = touching + kSkin + geometry1.max_lateral;
      if (across2 + offset * offset > kClearlyApart * near * near + kRoundingArea) continue;
      // The exact test, as btSphereSphereCollisionAlgorithm makes it.
      btVector3 center1 = axis1 * geometry1.axial[j] + pose1.getOrigin();
      if (!geometry1.straight) center1 += side1 * geometry1.lateral[j];
      const btVector3 difference = center1 - center0;
      const double length = difference.length();
      if (length > touching) {  // a point only for spheres that touch
        gap = std::min(gap, length - touching);
        continue;
      }
      const double distance = length - (radius0 + radius1);
      const btVector3 normal = length > SIMD_EPSILON ? difference / length : btVector3(1, 0, 0);
      const btVector3 on_0 = center0 + radius0 * normal;
      const btVector3 on_1 = on_0 + normal * distance;

      if (points == 0) {
        friction = gCalculateCombinedFrictionCallback(object0, object1);
        restitution = gCalculateCombinedRestitutionCallback(object0, object1);
        rolling_friction = gCalculateCombinedRollingFrictionCallback(object0, object1);
        spinning_friction = gCalculateCombinedSpinningFrictionCallback(object0, object1);
      }
      if (points % MANIFOLD_CACHE_SIZE == 0 && points / MANIFOLD_CACHE_SIZE == manifolds_.size()) {
        manifolds_.push_back(new_manifold(*m_dispatcher, object1, object0));
      }
      btPersistentManifold& manifold = *manifolds_[points / MANIFOLD_CACHE_SIZE];
      btManifoldPoint point(object1->getWorldTransform().invXform(on_1),
                            object0->getWorldTransform().invXform(on_0), normal, distance);
      point.m_positionWorldOnA = on_1;
      point.m_positionWorldOnB = on_0;
      point.m_combinedFriction = friction;
      point.m_combinedRestitution = restitution;
      point.m_combinedRollingFriction = rolling_friction;
      point.m_combinedSpinningFriction = spinning_friction;
      btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1,
                    point.m_lateralFrictionDir2);
      point.m_index0 = static_cast<int>(j);
      point.m_index1 = static_cast<int>(i);
      manifold.addManifoldPoint(point);
      ++points;
    }
  }
  release_from((points + MANIFOLD_CACHE_SIZE - 1) / MANIFOLD_CACHE_SIZE);
  apart_.tested(points == 0 ? gap : 0.0);
}

void RodRodCollision::getAllContactManifolds(btManifoldArray& manifolds) {
  for (btPersistentManifold* manifold : manifolds_) manifolds.push_back(manifold);
}

}  // namespace rodsort::engine
