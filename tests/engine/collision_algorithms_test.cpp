// The rod collision algorithms (engine/rod_*_collision.cpp) against Bullet's generic path, which
// they replace: for thousands of random poses of two rods, a rod and a plate, a rod and a slanted
// wall, both dispatchers compute the contacts of the pair, and every penetrating point of one must
// be a point of the other (position, normal, depth). Speculative points (not yet touching) are
// left out: the solver never uses them, and the generic path keeps them by other rules. Each runs
// with rod A and with an RnT whose thin part lies off its axis (far more than a real one's would,
// so that a wrong offset cannot hide in the tolerance).
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <memory>
#include <random>
#include <vector>

#include "engine/body_tag.hpp"
#include "engine/rod_collision_dispatch.hpp"
#include "engine/rod_geometry.hpp"
#include "engine/rod_shape.hpp"
#include "engine/units.hpp"

using namespace rodsort::engine;

namespace {

struct Point {
  btVector3 on_b, normal;
  double depth;
};

/// A dispatcher, generic (Bullet's algorithms) or with the rod algorithms registered.
struct Dispatch {
  explicit Dispatch(bool rods)
      : configuration(RodCollisionDispatch::configuration_info()), dispatcher(&configuration) {
    if (rods) rod_collision = std::make_unique<RodCollisionDispatch>(dispatcher, nullptr);
  }
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher;
  std::unique_ptr<RodCollisionDispatch> rod_collision;

  /// The penetrating points of `a` and `b` in their current poses, in the frame where the normal
  /// points from `b` toward `a`.
  std::vector<Point> contacts(btCollisionObject& a, btCollisionObject& b) {
    btCollisionObjectWrapper wrap_a(nullptr, a.getCollisionShape(), &a, a.getWorldTransform(), -1,
                                    -1);
    btCollisionObjectWrapper wrap_b(nullptr, b.getCollisionShape(), &b, b.getWorldTransform(), -1,
                                    -1);
    btCollisionAlgorithm* algorithm =
        dispatcher.findAlgorithm(&wrap_a, &wrap_b, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    REQUIRE(algorithm != nullptr);
    btManifoldResult result(&wrap_a, &wrap_b);
    btDispatcherInfo info;
    algorithm->processCollision(&wrap_a, &wrap_b, info, &result);
    // Every manifold of the dispatcher is this algorithm's (Bullet's compound-compound algorithm
    // does not list those of the fallback it takes for compounds without AABB trees).
    std::vector<Point> points;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
      const bool a_is_body0 = manifold.getBody0() == &a;
      for (int p = 0; p < manifold.getNumContacts(); ++p) {
        const btManifoldPoint& point = manifold.getContactPoint(p);
        if (point.getDistance() > 0.0) continue;
        // The normal points from body 1 toward body 0; turn it to point from b toward a.
        const btVector3 normal = a_is_body0 ? point.m_normalWorldOnB : -point.m_normalWorldOnB;
        const btVector3 on_b =
            a_is_body0 ? point.getPositionWorldOnB() : point.getPositionWorldOnA();
        points.push_back({on_b, normal, point.getDistance()});
      }
    }
    algorithm->~btCollisionAlgorithm();
    dispatcher.freeCollisionAlgorithm(algorithm);
    return points;
  }
};

/// An RnT whose thin part lies 0.2 mm off the thick part's axis.
RodProfile off_axis_rnt() {
  return preset_rnt_profile(kRntThinRadius, kRntLength / 2, kRntThickRadius, 0.2);
}

/// A rod as a simulation builds it: a compound of spheres with its RodGeometry attached.
struct Rod {
  explicit Rod(const RodProfile& profile)
      : shape(make_rod_shape(profile, rodsort::kBrassDensity)), geometry(shape) {
    for (const Sphere& sphere : shape.spheres) {
      spheres.push_back(std::make_unique<btSphereShape>(sphere.radius));
      btTransform offset;
      offset.setIdentity();
      offset.setOrigin(btVector3(sphere.axial, sphere.lateral, 0));
      compound.addChildShape(offset, spheres.back().get());
    }
    compound.setUserPointer(&geometry);
  }
  RodShape shape;
  RodGeometry geometry;
  std::vector<std::unique_ptr<btSphereShape>> spheres;
  btCompoundShape compound{false};
};

/// Every point of `got` matches one of `expected`, and the counts agree.
void check_same(const std::vector<Point>& expected, const std::vector<Point>& got,
                double tolerance) {
  REQUIRE(got.size() == expected.size());
  for (const Point& point : got) {
    const auto match = std::find_if(expected.begin(), expected.end(), [&](const Point& e) {
      return (e.on_b - point.on_b).length() <= tolerance &&
             (e.normal - point.normal).length() <= tolerance &&
             std::abs(e.depth - point.depth) <= tolerance;
    });
    INFO("point on b (" << point.on_b.x() << ", " << point.on_b.y() << ", " << point.on_b.z()
                        << "), normal (" << point.normal.x() << ", " << point.normal.y() << ", "
                        << point.normal.z() << "), depth " << point.depth);
    CHECK(match != expected.end());
  }
}

btTransform random_rod_pose(std::mt19937_64& random, const btVector3& around, double spread) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const btQuaternion yaw(btVector3(0, 0, 1), 3.2 * unit(random));
  const btQuaternion tilt(btVector3(1, 0, 0).rotate(btVector3(0, 0, 1), 3.2 * unit(random)),
                          0.4 * unit(random));
  const btVector3 at = around + spread * btVector3(unit(random), unit(random), 0.3 * unit(random));
  return btTransform(tilt * yaw, at);
}

}  // namespace

TEST_CASE("rod-rod contacts are those of Bullet's compound algorithms", "[engine][collision]") {
  install_material_table_callbacks();
  MaterialTable materials = MaterialTable::paper();
  // Two A rods, two off-axis RnT rods, one of each.
  const int pair = GENERATE(0, 1, 2);
  Rod rod_a(pair == 1 ? off_axis_rnt() : preset_a_profile());
  Rod rod_b(pair == 0 ? preset_a_profile() : off_axis_rnt());
  BodyTag tag_a{BodyKind::kRod, MaterialTable::kFirstRod, &materials, 0};
  BodyTag tag_b{BodyKind::kRod, MaterialTable::kFirstRod, &materials, 1};
  btCollisionObject a, b;
  a.setCollisionShape(&rod_a.compound);
  b.setCollisionShape(&rod_b.compound);
  attach_tag(a, tag_a);
  attach_tag(b, tag_b);
  Dispatch generic(false), ours(true);
  std::mt19937_64 random(17);
  int touching = 0;
  for (int pose = 0; pose < 3000; ++pose) {
    a.setWorldTransform(random_rod_pose(random, btVector3(0, 0, 0), 0.2));
    b.setWorldTransform(random_rod_pose(random, btVector3(0, 0, 0), 3.0));
    const std::vector<Point> expected = generic.contacts(a, b);
    touching += !expected.empty();
    INFO("rods " << pair << ", pose " << pose);
    check_same(expected, ours.contacts(a, b), 1e-12);
  }
  CHECK(touching > 500);  // the poses test contacts, not only misses
}

TEST_CASE("rod-plate contacts are those of Bullet's compound algorithms", "[engine][collision]") {
  install_material_table_callbacks();
  MaterialTable materials = MaterialTable::paper();
  const bool off_axis = GENERATE(false, true);
  Rod rod(off_axis ? off_axis_rnt() : preset_a_profile());
  btBoxShape plate_shape(btVector3(20, 20, 1));
  BodyTag rod_tag{BodyKind::kRod, MaterialTable::kFirstRod, &materials, 0};
  Dispatch generic(false), ours(true);
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const BodyKind kind : {BodyKind::kBase, BodyKind::kLid}) {
    BodyTag plate_tag{kind, kind == BodyKind::kBase ? MaterialTable::kBase : MaterialTable::kLid,
                      &materials};
    btCollisionObject rod_object, plate;
    rod_object.setCollisionShape(&rod.compound);
    plate.setCollisionShape(&plate_shape);
    attach_tag(rod_object, rod_tag);
    attach_tag(plate, plate_tag);
    // The plate's surface at z = 0, the rod above the base or below the lid, touching or nearly.
    const double side = kind == BodyKind::kBase ? 1.0 : -1.0;
    plate.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, -side)));
    int touching = 0;
    for (int pose = 0; pose < 2000; ++pose) {
      // Any tilt and place, moved up or down so that the sphere nearest the plate reaches into it
      // by up to 0.1 mm or stays up to 0.1 mm clear (a step's penetration is far less).
      btTransform pose_now = random_rod_pose(random, btVector3(0, 0, 0), 0.5);
      double gap = 1e9;
      for (const Sphere& sphere : rod.shape.spheres) {
        const double z = (pose_now * btVector3(sphere.axial, sphere.lateral, 0)).z();
        gap = std::min(gap, side * z - sphere.radius);
      }
      const double wanted = 0.05 * (1.0 + 2.0 * unit(random)) - 0.05;
      pose_now.getOrigin() += btVector3(0, 0, side * (wanted - gap));
      rod_object.setWorldTransform(pose_now);
      const std::vector<Point> expected = generic.contacts(rod_object, plate);
      touching += !expected.empty();
      INFO((off_axis ? "off-axis RnT" : "rod A")
           << ", pose " << pose << (kind == BodyKind::kBase ? " on the base" : " under the lid"));
      check_same(expected, ours.contacts(rod_object, plate), 1e-12);
    }
    CHECK(touching > 500);
  }
}

TEST_CASE("rod-wall contacts are those Bullet's GJK finds", "[engine][collision]") {
  install_material_table_callbacks();
  MaterialTable materials = MaterialTable::paper();
  const bool off_axis = GENERATE(false, true);
  Rod rod(off_axis ? off_axis_rnt() : preset_a_profile());
  btBoxShape wall_shape(btVector3(10, 0.3, 3));
  BodyTag rod_tag{BodyKind::kRod, MaterialTable::kFirstRod, &materials, 0};
  BodyTag wall_tag{BodyKind::kWall, MaterialTable::kWall, &materials};
  wall_tag.wall = 0;
  btCollisionObject rod_object, wall;
  rod_object.setCollisionShape(&rod.compound);
  wall.setCollisionShape(&wall_shape);
  attach_tag(rod_object, rod_tag);
  attach_tag(wall, wall_tag);
  Dispatch generic(false), ours(true);
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int touching = 0;
  for (int pose = 0; pose < 2000; ++pose) {
    const double yaw = 3.2 * unit(random);
    wall.setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), yaw), btVector3(0, 0, 0)));
    // Beside the wall's long face, at a distance around the rod's radius.
    const btVector3 across = btVector3(0, 1, 0).rotate(btVector3(0, 0, 1), yaw);
    const btVector3 near = across * (0.3 + rod.shape.max_radius * (0.5 + unit(random))) +
                           btVector3(1, 0, 0).rotate(btVector3(0, 0, 1), yaw) * 8.0 * unit(random);
    rod_object.setWorldTransform(random_rod_pose(random, near, 0.3));
    const std::vector<Point> expected = generic.contacts(rod_object, wall);
    touching += !expected.empty();
    INFO((off_axis ? "off-axis RnT" : "rod A") << ", pose " << pose);
    // GJK and EPA converge to a tolerance; the closed form here is exact.
    check_same(expected, ours.contacts(rod_object, wall), 1e-6);
  }
  CHECK(touching > 500);
}

TEST_CASE("the spheres near a point of the axis are those std::lower_bound and upper_bound find",
          "[engine][collision]") {
  // Rod A's spheres are evenly spaced, RnT's are not (two halves, two spacings).
  for (const RodProfile& profile : {preset_a_profile(), preset_rnt_profile()}) {
    const RodGeometry geometry(make_rod_shape(profile, rodsort::kBrassDensity));
    REQUIRE(geometry.ascending);
    const auto& axial = geometry.axial;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> along(geometry.axial_min - 1.0,
                                                 geometry.axial_max + 1.0);
    std::vector<double> points(axial.begin(), axial.end());  // the centres themselves, exactly
    for (int k = 0; k < 2000; ++k) points.push_back(along(random));
    for (const double x : points) {
      INFO("x = " << x);
      CHECK(geometry.first_at_or_beyond(x) ==
            static_cast<std::size_t>(std::lower_bound(axial.begin(), axial.end(), x) -
                                     axial.begin()));
      CHECK(geometry.first_beyond(x) ==
            static_cast<std::size_t>(std::upper_bound(axial.begin(), axial.end(), x) -
                                     axial.begin()));
    }
  }
}
