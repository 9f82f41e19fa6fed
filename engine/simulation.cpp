// The simulation: a Bullet world of tapered rods between a vibrating base and lid.
//
// One step of dt:
//  1. rods whose centre left the periodic cell are wrapped, and their images refreshed
//     (periodic_boundary.cpp);
//  2. the plates are moved to their position at t + dt (plate_drive.cpp);
//  3. the rods' velocities are saved for the collision kick;
//  4. Bullet takes exactly one internal step of dt;
//  5. collision kicks are applied to rods that have just hit a plate (collision_kick.cpp);
//  6. white angular noise turns each rod, with its velocities, about the vertical through its
//     centre of mass by sqrt(2 D_r dt) xi, a Brownian rotation that the contacts then resolve.
//     Turning the velocities too matters: a rod turned while its velocity is not slides sideways,
//     and friction at its thick end swings it back toward its velocity like a weathervane, which
//     cut the measured D_r by ~10% at lag 0.07 s and ~25% at 1.4 s.
//
// Restitution. Bullet loses restitution with its default settings: speculative contacts (points
// within the contact-breaking distance that have not yet touched) slow a body before impact, and
// the split-impulse threshold mixes position correction into the velocity. We process only
// penetrating points (contact processing threshold 0 on every rod), always use split impulse
// (penetration threshold 0) and lower the restitution velocity threshold to a few g dt, below
// which Bullet drops restitution. With these the measured coefficient equals the configured one
// (tests/engine/restitution_test.cpp).
#include "engine/simulation.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/body_tag.hpp"
#include "engine/collision_kick.hpp"
#include "engine/periodic_boundary.hpp"
#include "engine/plate_drive.hpp"
#include "engine/random_stream.hpp"
#include "engine/rod_collision_dispatch.hpp"
#include "engine/rod_geometry.hpp"
#include "engine/rod_world.hpp"
#include "engine/surface_contacts.hpp"
#include "engine/units.hpp"

namespace rodsort::engine {
namespace {

/// Extra margin for images and plates beyond the reach of the largest rod [mm].
constexpr double kReachMargin = 1.0;

// The state keeps Bullet's rotation matrix, not a quaternion, so that saving and restoring a
// world is exact to the bit.
btMatrix3x3 to_bullet(const std::array<double, 9>& m) {
  return {m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]};
}
std::array<double, 9> from_bullet(const btMatrix3x3& m) {
  return {m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
}
btVector3 to_bullet(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }
std::array<double, 3> from_bullet(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

double largest_rod_reach(const Model& model) {
  double reach = 0.0;
  for (const Species& species : model.species) {
    for (const Sphere& sphere : species.shape.spheres) {
      reach = std::max(reach, std::hypot(sphere.axial, sphere.lateral) + sphere.radius);
    }
  }
  return reach;
}

std::unique_ptr<PlateRoughness> make_roughness(const Model& model, int plate) {
  const double slope = plate == 0 ? model.roughness.base_slope : model.roughness.lid_slope;
  if (slope == 0.0) return nullptr;
  return std::make_unique<PlateRoughness>(slope, model.roughness.wavelength, model.box_x,
                                          model.box_y, model.seed, plate);
}

double reach_of(const std::unique_ptr<PlateRoughness>& roughness) {
  return roughness ? roughness->reach() : 0.0;
}

}  // namespace

struct Simulation::Impl {
  Model model;
  std::unique_ptr<PlateRoughness> base_roughness, lid_roughness;  ///< null for a flat plate
  PlateDrive drive;
  PeriodicCell cell;

  // Shapes outlive the world; one compound per species.
  std::vector<std::unique_ptr<btSphereShape>> sphere_shapes;
  std::vector<std::unique_ptr<btCompoundShape>> rod_shapes;
  std::vector<std::unique_ptr<RodGeometry>> rod_geometries;  ///< user pointers of rod_shapes
  std::unique_ptr<btBoxShape> plate_shape;
  std::vector<std::unique_ptr<btBoxShape>> wall_shapes;

  // The world; rebuilt on restore.
  std::unique_ptr<btDefaultCollisionConfiguration> configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<RodCollisionDispatch> rod_collision;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<PeriodicOverlapFilter> overlap_filter;
  std::unique_ptr<PeriodicContactSolver> solver;
  std::unique_ptr<RodWorld> world;
  RestoredContacts restored_contacts;  ///< from the State, until the first step takes them

  std::unique_ptr<btRigidBody> base, lid;
  std::vector<std::unique_ptr<btRigidBody>> walls;
  std::vector<std::unique_ptr<btRigidBody>> rod_bodies;
  std::vector<btRigidBody*> rods;  ///< views of rod_bodies, for the solver and the kick
  std::vector<std::unique_ptr<btCollisionObject>> images;  ///< rod * kShiftCount + shift
  std::vector<char> image_in_world;
  std::vector<BodyTag> rod_tags, image_tags, wall_tags;
  BodyTag base_tag{}, lid_tag{};

  // Everything of the State that is not in the Bullet bodies.
  double time = 0.0;
  std::int64_t step = 0;
  std::vector<std::array<std::int64_t, 2>> image_count;
  std::vector<CollisionKick::Touching> touching;
  std::vector<RandomStream> kick_streams, noise_streams;

  std::vector<double> kick_eps, white_noise_step;  ///< per rod
  std::vector<double> noise_angle, noise_rate;     ///< per rod, the white noise of this step
  std::vector<char> noise_turned;                  ///< per rod: the solver applied noise_rate
  /// Per rod: BodyTag::travel, the pose it was last brought up to date at, and the farthest sphere
  /// centre's distance from the centre of mass along the axis and across it [mm].
  std::vector<Travel> travel;
  std::vector<btTransform> travel_pose;
  std::vector<double> axial_reach;
  std::vector<double> lateral_reach;
  double thinnest_radius = 0.0;  ///< of any rod's spheres [mm]
  /// No contact shallower than this can be too deep: the thinnest radius and the thinnest
  /// sphere's, wall's or plate's reach [mm].
  double shallowest_limit = 0.0;
  CollisionKick kick;
  SimulationCounters counters;

  explicit Impl(Model m)
      : model(std::move(m)),
        base_roughness(make_roughness(model, 0)),
        lid_roughness(make_roughness(model, 1)),
        drive(model.drive, reach_of(base_roughness), reach_of(lid_roughness)),
        cell(model.box_x, model.box_y, 2.0 * largest_rod_reach(model) + kReachMargin) {
    install_material_table_callbacks();
    build_shapes();
    thinnest_radius = std::numeric_limits<double>::infinity();
    for (const Species& species : model.species) {
      for (const Sphere& sphere : species.shape.spheres) {
        thinnest_radius = std::min(thinnest_radius, sphere.radius);
      }
    }
    double thinnest_other = std::min(thinnest_radius, PlateDrive::kPlateHalfThickness);
    for (const Wall& wall : model.walls) {
      thinnest_other = std::min(thinnest_other, wall.half_thickness);
    }
    shallowest_limit = thinnest_radius + thinnest_other;
    for (const RodInit& init : model.rods) {
      const Species& species = model.species.at(static_cast<std::size_t>(init.species));
      kick_eps.push_back(species.noise.kick_eps);
      white_noise_step.push_back(std::sqrt(2.0 * species.noise.white_Dr * model.dt));
    }
    noise_angle.assign(model.rods.size(), 0.0);
    noise_rate.assign(model.rods.size(), 0.0);
    noise_turned.assign(model.rods.size(), 0);
    build_world(initial_state());
  }

  ~Impl() { destroy_world(); }

  void build_shapes() {
    for (const Species& species : model.species) {
      auto compound =
          std::make_unique<btCompoundShape>(false, static_cast<int>(species.shape.spheres.size()));
      for (const Sphere& sphere : species.shape.spheres) {
        auto& child = sphere_shapes.emplace_back(std::make_unique<btSphereShape>(sphere.radius));
        btTransform offset;
        offset.setIdentity();
        offset.setOrigin(btVector3(sphere.axial, sphere.lateral, 0));
        compound->addChildShape(offset, child.get());
      }
      compound->setUserPointer(
          rod_geometries.emplace_back(std::make_unique<RodGeometry>(species.shape)).get());
      rod_shapes.push_back(std::move(compound));
    }
    const double overhang = 2.0 * largest_rod_reach(model) + kReachMargin;
    plate_shape = std::make_unique<btBoxShape>(btVector3(
        model.box_x / 2 + overhang, model.box_y / 2 + overhang, PlateDrive::kPlateHalfThickness));
    // Walls reach through both plates at their extreme positions.
    const double wall_half_height = model.drive.gap + 2.0 * model.drive.amplitude + 1.0;
    for (const Wall& wall : model.walls) {
      wall_shapes.push_back(std::make_unique<btBoxShape>(
          btVector3(wall.half_length, wall.half_thickness, wall_half_height)));
    }
  }

  std::vector<int> sphere_counts() const {
    std::vector<int> counts;
    for (const RodInit& init : model.rods) {
      counts.push_back(static_cast<int>(
          model.species.at(static_cast<std::size_t>(init.species)).shape.spheres.size()));
    }
    return counts;
  }

  State initial_state() const {
    State state;
    const double rest_height = drive.base_surface_z(0.0) + reach_of(base_roughness) + 0.01;
    for (std::size_t i = 0; i < model.rods.size(); ++i) {
      const RodInit& init = model.rods[i];
      const Species& species = model.species.at(static_cast<std::size_t>(init.species));
      RodState rod{};
      rod.position = {init.x, init.y, rest_height + species.shape.max_radius};
      btQuaternion orientation(btVector3(0, 0, 1), init.heading);
      if (init.roll != 0.0) orientation *= btQuaternion(btVector3(1, 0, 0), init.roll);
      rod.basis = from_bullet(btMatrix3x3(orientation));
      rod.velocity = {0, 0, 0};
      rod.angular_velocity = {0, 0, 0};
      rod.image = {0, 0};
      rod.touching = {false, false};
      rod.kick_rng = RandomStream(model.seed, i, StreamPurpose::kCollisionKick).state();
      rod.noise_rng = RandomStream(model.seed, i, StreamPurpose::kWhiteNoise).state();
      state.rods.push_back(rod);
    }
    return state;
  }

  std::unique_ptr<btRigidBody> make_kinematic_plate(BodyTag& tag) {
    btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, plate_shape.get());
    auto body = std::make_unique<btRigidBody>(info);
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    body->setActivationState(DISABLE_DEACTIVATION);
    attach_tag(*body, tag);
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(btVector3(model.box_x / 2, model.box_y / 2, 0));
    body->setWorldTransform(transform);
    world->addRigidBody(body.get(), kGroupPlate, kGroupRod);
    return body;
  }

  /// `state` has been checked (check_state) or built from the model.
  void build_world(const State& state) {
    configuration = std::make_unique<btDefaultCollisionConfiguration>(
        RodCollisionDispatch::configuration_info());
    dispatcher = std::make_unique<btCollisionDispatcher>(configuration.get());
    restored_contacts.assign(state.contacts);
    rod_collision = std::make_unique<RodCollisionDispatch>(*dispatcher, &restored_contacts,
                                                           &counters.pair_tests_skipped);
    broadphase = std::make_unique<btDbvtBroadphase>();
    overlap_filter = std::make_unique<PeriodicOverlapFilter>();
    broadphase->getOverlappingPairCache()->setOverlapFilterCallback(overlap_filter.get());
    solver = std::make_unique<PeriodicContactSolver>(cell, rods);
    solver->set_fixed_sweep_order(model.fixed_sweep_order);
    solver->set_exact(model.exact_contact_solver);
    if (model.full_turn_correction) solver->set_noise_turns(&noise_rate, &noise_turned);
    world = std::make_unique<RodWorld>(dispatcher.get(), broadphase.get(), solver.get(),
                                       configuration.get());
    world->setGravity(btVector3(0, 0, -kGravity));
    world->set_reverse_contact_order(model.reverse_contact_order);
    world->set_single_solver_batch(model.single_solver_batch);
    // No continuous collision detection (DESIGN.md): this also keeps Bullet from widening each
    // rod's broadphase box by its predicted motion (see rod_world.cpp).
    world->getDispatchInfo().m_useContinuous = false;
    // Bullet recomputes every body's broadphase box each step unless told to skip the inactive
    // ones: only the walls are inactive (asleep), and a bounded cell has hundreds of them.
    world->setForceUpdateAllAabbs(false);
    btContactSolverInfo& info = world->getSolverInfo();
    info.m_numIterations = model.solver_iterations;
    info.m_globalCfm = model.constraint_force_mixing;
    // Two friction directions per contact: with Bullet's default single direction (along the
    // current sliding velocity) a rod on the vibrated plate spins up by itself, turning ~25 rad in
    // 5 s without any noise. Warm starting stays on: it is also what makes Bullet write the
    // applied impulse back to the contact points, which the collision kick reads.
    // Friction interleaved with its contact: each contact's friction is solved right after its
    // normal impulse, so its Coulomb bound already holds the landing's impulse within the same
    // sweep. Solving all normals first and all frictions after (Bullet's default) left the spin
    // that follows a kick unconverged at dt = 1e-4 s: a rod's rotational diffusion came out 15-20%
    // above its small-dt value. Interleaved, it agrees with dt = 2.5e-5 s within 3%, and v0 with
    // every dt from 1e-4 to 1.25e-5 s within 3%, at the same cost (docs/performance.md).
    info.m_solverMode = SOLVER_USE_WARMSTARTING | SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_SIMD |
                        SOLVER_INTERLEAVE_CONTACT_AND_FRICTION_CONSTRAINTS;
    info.m_splitImpulse = 1;
    info.m_splitImpulsePenetrationThreshold = 0.0;
    // The split impulse's position correction is solved for turn velocities applied in full;
    // Bullet applies a tenth of them by default. In full (Model::full_turn_correction) rod A's v0
    // depends less on dt and the white noise's overlaps shrink, but the RnT rod changes its gait
    // at the default dt (docs/model.md, "Checks while a run goes").
    // Bullet's default is the float 0.1f, which is not the double 0.1.
    info.m_splitImpulseTurnErp = model.full_turn_correction ? 1.0 : static_cast<double>(0.1f);
    info.m_restitutionVelocityThreshold = 2.5 * kGravity * model.dt;

    base_tag = {BodyKind::kBase, MaterialTable::kBase, &model.materials};
    base_tag.roughness = base_roughness.get();
    lid_tag = {BodyKind::kLid, MaterialTable::kLid, &model.materials};
    lid_tag.roughness = lid_roughness.get();
    base = make_kinematic_plate(base_tag);
    lid = make_kinematic_plate(lid_tag);
    drive.place(*base, *lid, state.time, true);

    wall_tags.clear();
    wall_tags.reserve(model.walls.size());
    for (std::size_t w = 0; w < model.walls.size(); ++w) {
      const Wall& wall = model.walls[w];
      wall_tags.push_back({BodyKind::kWall, wall.material, &model.materials});
      wall_tags.back().wall = static_cast<int>(w);
      btRigidBody::btRigidBodyConstructionInfo info_wall(0.0, nullptr, wall_shapes[w].get());
      auto body = std::make_unique<btRigidBody>(info_wall);
      btTransform transform(btQuaternion(btVector3(0, 0, 1), wall.yaw),
                            btVector3(wall.center_x, wall.center_y, model.drive.gap / 2));
      body->setWorldTransform(transform);
      attach_tag(*body, wall_tags.back());
      world->addRigidBody(body.get(), kGroupWall, kGroupRod);
      // A wall never moves: asleep, its broadphase box is never recomputed (see below).
      body->setActivationState(ISLAND_SLEEPING);
      walls.push_back(std::move(body));
    }

    const std::size_t rod_count = model.rods.size();
    rod_tags.clear();
    rod_tags.reserve(rod_count);
    rods.clear();
    travel.assign(rod_count, 0);  // never resized while the world stands: tags point into it
    travel_pose.clear();
    axial_reach.clear();
    lateral_reach.clear();
    for (std::size_t i = 0; i < rod_count; ++i) {
      const RodState& rs = state.rods[i];
      const Species& species = model.species[static_cast<std::size_t>(model.rods[i].species)];
      rod_tags.push_back({BodyKind::kRod, species.material, &model.materials, static_cast<int>(i)});
      if (!model.test_every_pair) rod_tags.back().travel = &travel[i];
      double reach = 0.0;
      for (const Sphere& sphere : species.shape.spheres) {
        reach = std::max(reach, std::abs(sphere.axial));
      }
      axial_reach.push_back(reach);
      lateral_reach.push_back(species.shape.max_lateral);
      btCompoundShape* shape = rod_shapes[static_cast<std::size_t>(model.rods[i].species)].get();
      btRigidBody::btRigidBodyConstructionInfo info_rod(species.shape.mass, nullptr, shape);
      auto body = std::make_unique<btRigidBody>(info_rod);
      // Bullet's compound inertia is a bounding-box estimate; use the union's exact values.
      body->setMassProps(species.shape.mass,
                         btVector3(species.shape.inertia_axial, species.shape.inertia_transverse,
                                   species.shape.inertia_normal));
      body->updateInertiaTensor();
      body->setActivationState(DISABLE_DEACTIVATION);
      body->setContactProcessingThreshold(0.0);
      attach_tag(*body, rod_tags.back());
      const btTransform transform(to_bullet(rs.basis), to_bullet(rs.position));
      body->setWorldTransform(transform);
      body->setInterpolationWorldTransform(transform);
      travel_pose.push_back(transform);
      body->setLinearVelocity(to_bullet(rs.velocity));
      body->setAngularVelocity(to_bullet(rs.angular_velocity));
      body->setInterpolationLinearVelocity(to_bullet(rs.velocity));
      body->setInterpolationAngularVelocity(to_bullet(rs.angular_velocity));
      world->addRigidBody(body.get(), kGroupRod,
                          kGroupRod | kGroupPlate | kGroupWall | kGroupImage);
      body->updateInertiaTensor();
      rods.push_back(body.get());
      rod_bodies.push_back(std::move(body));
    }

    image_tags.clear();
    image_tags.reserve(rod_count * PeriodicCell::kShiftCount);
    for (std::size_t i = 0; i < rod_count; ++i) {
      for (int s = 0; s < PeriodicCell::kShiftCount; ++s) {
        image_tags.push_back(
            {BodyKind::kImage, rod_tags[i].material, &model.materials, static_cast<int>(i), s});
        image_tags.back().travel = rod_tags[i].travel;
        auto image = std::make_unique<btCollisionObject>();
        image->setCollisionShape(rods[i]->getCollisionShape());
        attach_tag(*image, image_tags.back());
        image->setActivationState(DISABLE_DEACTIVATION);
        image->setContactProcessingThreshold(0.0);
        images.push_back(std::move(image));
      }
    }
    image_in_world.assign(images.size(), 0);

    time = state.time;
    step = state.step;
    image_count.clear();
    touching.clear();
    kick_streams.clear();
    noise_streams.clear();
    for (const RodState& rs : state.rods) {
      image_count.push_back(rs.image);
      touching.push_back(rs.touching);
      kick_streams.emplace_back(rs.kick_rng);
      noise_streams.emplace_back(rs.noise_rng);
    }
  }

  void destroy_world() {
    if (!world) return;
    for (std::size_t k = 0; k < images.size(); ++k) {
      if (image_in_world[k]) world->removeCollisionObject(images[k].get());
    }
    for (auto& body : rod_bodies) world->removeRigidBody(body.get());
    for (auto& body : walls) world->removeRigidBody(body.get());
    world->removeRigidBody(base.get());
    world->removeRigidBody(lid.get());
    images.clear();
    image_in_world.clear();
    rod_bodies.clear();
    rods.clear();
    walls.clear();
    base.reset();
    lid.reset();
    world.reset();
    solver.reset();
    broadphase.reset();
    overlap_filter.reset();
    dispatcher.reset();
    rod_collision.reset();
    configuration.reset();
  }

  /// A rod whose centre is no longer between base and lid (by more than a gap's margin), or not
  /// finite, means the model broke down (validation bounds what moves a rod per step, so this
  /// should not happen); stopping says so instead of running on with nonsense.
  [[noreturn]] void stop_escaped_rod(std::size_t rod, const btVector3& where) const {
    std::ostringstream message;
    message << "rod " << rod << " left the space between base and lid at step " << step
            << ", t = " << time << " s (its centre at x = " << where.x() << ", y = " << where.y()
            << ", z = " << where.z() << " mm; base at z = " << drive.base_surface_z(time)
            << " mm, lid at z = " << drive.lid_surface_z(time)
            << " mm): the simulation broke down and was stopped";
    throw std::runtime_error(message.str());
  }

  void wrap_and_refresh_images() {
    const double margin = model.drive.gap;
    const double lowest = drive.base_surface_z(time) - margin;
    const double highest = drive.lid_surface_z(time) + margin;
    for (std::size_t i = 0; i < rods.size(); ++i) {
      btRigidBody& body = *rods[i];
      btTransform transform = body.getWorldTransform();
      const btVector3& centre = transform.getOrigin();
      if (!(centre.z() > lowest && centre.z() < highest) || !std::isfinite(centre.x()) ||
          !std::isfinite(centre.y())) {
        stop_escaped_rod(i, centre);
      }
      const auto crossed = cell.wrap_count(transform.getOrigin().x(), transform.getOrigin().y());
      if (crossed[0] != 0 || crossed[1] != 0) {
        const btVector3 jump(static_cast<double>(crossed[0]) * cell.box_x(),
                             static_cast<double>(crossed[1]) * cell.box_y(), 0.0);
        transform.getOrigin() -= jump;
        body.setWorldTransform(transform);
        btTransform interpolation = body.getInterpolationWorldTransform();
        interpolation.getOrigin() -= jump;
        body.setInterpolationWorldTransform(interpolation);
        image_count[i][0] += crossed[0];
        image_count[i][1] += crossed[1];
      }
      // A sphere centre at (a, l) on the body's x and y axes moves by the centre's move plus a
      // times the x axis's plus l times the y axis's: the sum bounds every sphere's, and an
      // image's (a wrap moves it with its rod).
      const btTransform& last = travel_pose[i];
      double move = (transform.getOrigin() - last.getOrigin()).length() +
                    (transform.getBasis().getColumn(0) - last.getBasis().getColumn(0)).length() *
                        axial_reach[i];
      if (lateral_reach[i] > 0.0) {
        move += (transform.getBasis().getColumn(1) - last.getBasis().getColumn(1)).length() *
                lateral_reach[i];
      }
      travel[i] += travel_of_move(move);
      travel_pose[i] = transform;
      const bool near_edge = cell.near_edge(transform.getOrigin().x(), transform.getOrigin().y());
      for (int s = 0; s < PeriodicCell::kShiftCount; ++s) {
        const std::size_t k = i * PeriodicCell::kShiftCount + static_cast<std::size_t>(s);
        const bool needed =
            near_edge && cell.image_needed(transform.getOrigin().x(), transform.getOrigin().y(), s);
        btCollisionObject& image = *images[k];
        if (needed) {
          btTransform shifted = transform;
          shifted.getOrigin() += cell.shift(s);
          image.setWorldTransform(shifted);
          if (!image_in_world[k]) {
            world->addCollisionObject(&image, kGroupImage, kGroupRod);
            image_in_world[k] = 1;
          }
        } else if (image_in_world[k]) {
          world->removeCollisionObject(&image);
          image_in_world[k] = 0;
        }
      }
    }
  }

  /// Tracks the deepest contact of the step just solved, and stops the run at a contact as deep as
  /// the two bodies' reach there: a rod's sphere radius, a wall's or a plate's half-thickness. That
  /// deep, the centres of two spheres meet, or a sphere's centre reaches a box's mid-plane, and
  /// the contact can no longer push the bodies apart: beyond, it pushes them through each other.
  /// Bullet refreshed every point's depth when the step began.
  void check_overlaps() {
    btPersistentManifold* const* manifolds = world->solved_manifolds();
    const int count = world->solved_manifold_count();
    double deepest = 0.0;
    for (int m = 0; m < count; ++m) {
      const btPersistentManifold& manifold = *manifolds[m];
      for (int p = 0; p < manifold.getNumContacts(); ++p) {
        const btManifoldPoint& point = manifold.getContactPoint(p);
        const double depth = -point.getDistance();
        deepest = std::max(deepest, depth);
        if (depth >= shallowest_limit) {
          const double limit = reach(*manifold.getBody0(), point.m_index0) +
                               reach(*manifold.getBody1(), point.m_index1);
          if (depth >= limit) stop_deep_overlap(manifold, depth, limit);
        }
      }
    }
    counters.deepest_overlap = std::max(counters.deepest_overlap, deepest);
  }

  /// How deep another body may reach into `body` at its part `index` before the contact turns
  /// over: the radius of a rod's sphere, the half-thickness of a wall or a plate.
  double reach(const btCollisionObject& body, int index) const {
    const auto& tag = *static_cast<const BodyTag*>(body.getUserPointer());
    switch (tag.kind) {
      case BodyKind::kRod:
      case BodyKind::kImage: {
        const RodInit& rod = model.rods[static_cast<std::size_t>(tag.rod)];
        const auto& spheres = model.species[static_cast<std::size_t>(rod.species)].shape.spheres;
        return index >= 0 && static_cast<std::size_t>(index) < spheres.size()
                   ? spheres[static_cast<std::size_t>(index)].radius
                   : thinnest_radius;
      }
      case BodyKind::kWall:
        return model.walls[static_cast<std::size_t>(tag.wall)].half_thickness;
      case BodyKind::kBase:
      case BodyKind::kLid:
        return PlateDrive::kPlateHalfThickness;
    }
    return 0.0;
  }

  static std::string describe_body(const btCollisionObject& body) {
    const auto& tag = *static_cast<const BodyTag*>(body.getUserPointer());
    switch (tag.kind) {
      case BodyKind::kRod:
        return "rod " + std::to_string(tag.rod);
      case BodyKind::kImage:
        return "a periodic image of rod " + std::to_string(tag.rod);
      case BodyKind::kBase:
        return "the base";
      case BodyKind::kLid:
        return "the lid";
      case BodyKind::kWall:
        return "wall " + std::to_string(tag.wall);
    }
    return "a body";
  }

  [[noreturn]] void stop_deep_overlap(const btPersistentManifold& manifold, double depth,
                                      double limit) const {
    const btCollisionObject* first = manifold.getBody0();
    const btCollisionObject* second = manifold.getBody1();
    if (static_cast<const BodyTag*>(first->getUserPointer())->kind != BodyKind::kRod) {
      std::swap(first, second);
    }
    std::ostringstream message;
    message << describe_body(*first) << " went " << depth << " mm deep into "
            << describe_body(*second) << " at step " << step << ", t = " << time
            << " s, as deep as the two bodies' reach there (" << limit
            << " mm: two spheres' radii, or a sphere's radius and a wall's or plate's "
               "half-thickness), where the contact no longer pushes them apart: the simulation "
               "broke down and was stopped";
    throw std::runtime_error(message.str());
  }

  /// Draws each noisy rod's turn for the coming step; with Model::full_turn_correction the solver
  /// applies it (periodic_boundary.cpp, "White noise").
  void draw_white_noise() {
    for (std::size_t i = 0; i < rods.size(); ++i) {
      noise_turned[i] = 0;
      noise_angle[i] =
          white_noise_step[i] == 0.0 ? 0.0 : white_noise_step[i] * noise_streams[i].normal();
      noise_rate[i] = noise_angle[i] / model.dt;
    }
  }

  /// Turns the velocities of each noisy rod with it, and the rod itself where the solver did not
  /// (always, unless Model::full_turn_correction; then only rods without contacts).
  void apply_white_noise() {
    for (std::size_t i = 0; i < rods.size(); ++i) {
      if (white_noise_step[i] == 0.0) continue;
      const double angle = noise_angle[i];
      btRigidBody& body = *rods[i];
      const btMatrix3x3 turn(btQuaternion(btVector3(0, 0, 1), angle));
      if (!noise_turned[i]) {
        btTransform transform = body.getWorldTransform();
        transform.setBasis(turn * transform.getBasis());
        body.setWorldTransform(transform);
        body.setInterpolationWorldTransform(transform);
      }
      body.setLinearVelocity(turn * body.getLinearVelocity());
      body.setAngularVelocity(turn * body.getAngularVelocity());
      // The inertia tensor in the world's frame turns with the rod, as a restored rod's does.
      body.updateInertiaTensor();
    }
  }

  void do_step() {
    wrap_and_refresh_images();
    // At (step + 1) dt, the time a restored world computes for that step, not time + dt, which
    // differs from it by rounding.
    drive.place(*base, *lid, static_cast<double>(step + 1) * model.dt, false);
    kick.save_velocities(rods);
    solver->start_step(
        RandomStream(model.seed, static_cast<std::uint64_t>(step), StreamPurpose::kSolverOrder));
    draw_white_noise();
    world->stepSimulation(model.dt, 0, model.dt);
    // The collision algorithms were created, and took their restored contacts, in this step.
    restored_contacts.clear();
    check_overlaps();
    counters.kicks += kick.apply(world->solved_manifolds(), world->solved_manifold_count(), rods,
                                 kick_eps, touching, kick_streams);
    apply_white_noise();
    ++step;
    time = static_cast<double>(step) * model.dt;
  }

  State current_state() const {
    State state;
    state.time = time;
    state.step = step;
    state.rods.reserve(rods.size());
    for (std::size_t i = 0; i < rods.size(); ++i) {
      const btRigidBody& body = *rods[i];
      RodState rs{};
      rs.position = from_bullet(body.getWorldTransform().getOrigin());
      rs.basis = from_bullet(body.getWorldTransform().getBasis());
      rs.velocity = from_bullet(body.getLinearVelocity());
      rs.angular_velocity = from_bullet(body.getAngularVelocity());
      rs.image = image_count[i];
      rs.touching = touching[i];
      rs.kick_rng = kick_streams[i].state();
      rs.noise_rng = noise_streams[i].state();
      state.rods.push_back(rs);
    }
    // Before its first step a rebuilt world's contacts are still those it was given.
    state.contacts =
        restored_contacts.pending() ? restored_contacts.all() : save_surface_contacts(*dispatcher);
    return state;
  }
};

Simulation::Simulation(Model model) : impl_(std::make_unique<Impl>(std::move(model))) {}
Simulation::~Simulation() = default;

void Simulation::step() { impl_->do_step(); }

void Simulation::advance(std::int64_t steps) {
  for (std::int64_t i = 0; i < steps; ++i) impl_->do_step();
}

double Simulation::time() const { return impl_->time; }
std::int64_t Simulation::step_count() const { return impl_->step; }
const Model& Simulation::model() const { return impl_->model; }
SimulationCounters Simulation::counters() const {
  SimulationCounters counters = impl_->counters;
  counters.exact_solver_fallbacks = impl_->solver->exact_fallbacks();
  return counters;
}
void Simulation::reset_counters() { impl_->counters = {}; }

Frame Simulation::frame() const {
  Frame frame;
  frame.time = impl_->time;
  frame.rods.reserve(impl_->rods.size());
  for (std::size_t i = 0; i < impl_->rods.size(); ++i) {
    const btRigidBody& body = *impl_->rods[i];
    const btTransform& transform = body.getWorldTransform();
    const btVector3 axis = transform.getBasis().getColumn(0);
    RodFrame rod;
    rod.species = impl_->model.rods[i].species;
    rod.position = {transform.getOrigin().x(), transform.getOrigin().y()};
    rod.unwrapped =
        rod.position +
        Eigen::Vector2d(static_cast<double>(impl_->image_count[i][0]) * impl_->model.box_x,
                        static_cast<double>(impl_->image_count[i][1]) * impl_->model.box_y);
    rod.z = transform.getOrigin().z();
    rod.axis = {axis.x(), axis.y(), axis.z()};
    const btVector3& v = body.getLinearVelocity();
    const btVector3& w = body.getAngularVelocity();
    rod.velocity = {v.x(), v.y(), v.z()};
    rod.angular_velocity = {w.x(), w.y(), w.z()};
    frame.rods.push_back(rod);
  }
  return frame;
}

State Simulation::state() const { return impl_->current_state(); }

void Simulation::restore(const State& state) {
  // Checked before the world is torn down.
  check_state(state, impl_->model.rods.size(), 2 + static_cast<int>(impl_->model.walls.size()),
              impl_->sphere_counts());
  impl_->destroy_world();
  impl_->build_world(state);
}

double Simulation::base_surface_z() const { return impl_->drive.base_surface_z(impl_->time); }
double Simulation::lid_surface_z() const { return impl_->drive.lid_surface_z(impl_->time); }

double Simulation::base_velocity_z() const { return impl_->base->getLinearVelocity().z(); }

void Simulation::write_bullet_snapshot(const std::filesystem::path& path) const {
  btDefaultSerializer serializer;
  serializer.setSerializationFlags(BT_SERIALIZE_CONTACT_MANIFOLDS);
  impl_->world->serialize(&serializer);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(serializer.getBufferPointer()),
            serializer.getCurrentBufferSize());
  if (!out) throw std::runtime_error("cannot write Bullet snapshot " + path.string());
}

}  // namespace rodsort::engine
