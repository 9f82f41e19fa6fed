// Periodic boundaries in x and y.
//
// The paper's cell is periodic in the plane. Bullet knows nothing of periodicity, so we build it
// from three pieces:
//  1. Wrapping: before each step, a rod whose centre of mass has left [0, Lx) x [0, Ly) is moved
//     by a whole number of cells (world and interpolation transforms; the broadphase simply sees a
//     jump). The number of cells crossed is kept, so unwrapped positions are exact.
//  2. Images: a rod near an edge gets image collision objects that share its shape, sitting at
//     the rod's pose shifted by S in {(Lx,0), (0,Ly), (Lx,Ly), (Lx,-Ly)}. Only these four "forward"
//     shifts are used: for any pair of rods that touch across an edge, exactly one of them has the
//     image that meets the other, so no contact is counted twice. Images are in their own
//     collision group and meet only rods, and never their own rod.
//  3. Contact translation: to Bullet an image is a static object, so a contact with it would push
//     only the other rod. The solver subclass below rewrites every manifold that touches an image
//     before the contacts become constraints: the image is replaced by its real rod, and the
//     contact point on that side is moved back by -S. The solver then sees exactly the contact it
//     would see if the two rods met in the middle of the cell, and a collision across an edge or a
//     corner gives the same outcome as one in the interior (to round-off).
// Bullet's own islands must not split the solver's work: a rod touching another through an image
// could land in two islands and receive gravity twice. The engine groups rods into islands itself,
// linking each image with its real rod (solver_batches.cpp).
//
// Sweep order. The solver stops after a fixed number of sweeps (ten by default), before it has
// converged, and what it stops at depends on the order in which each sweep meets the contacts. For
// a rod lying on a plate, whose contacts run along it sphere by sphere, a fixed order is a fixed
// direction along the rod, and it biases the rod's motion: sweeping the contacts of rod A from one
// end or from the other gave D_r = 0.137 or 0.075 rad^2/s and v0 = 13.7 or 14.3 mm/s at dt = 1e-4
// s, 24 rods each (docs/model.md, "Contact order in the solver"). Each sweep therefore meets the
// contacts in a random order, drawn from a stream seeded by the scenario's seed and the step
// (StreamPurpose::kSolverOrder), so that the order carries no direction and a restored world draws
// the same orders; both end-to-end orders then give the same D_r and v0 within their errors.
//
// White noise. The white angular noise turns a rod by a random angle every step. Turned outside
// the solver, a rod held against a neighbour is turned into it, and in a pile the solver does not
// get it out before the next turn: thin ends went 0.24 mm into neighbours at D_r = 0.2 rad^2/s
// (docs/model.md, "Checks while a run goes"). With Model::full_turn_correction the turn is handed
// to the solver as a turn velocity of the rod's position correction (split impulse), which is then
// applied in full: the solver's position rows see
// it and push back where it would drive the rod into a body it already overlaps, and it moves the
// rod without giving it angular momentum. A free rod turns by exactly the angle drawn. A rod
// without any contact is turned by the caller, after the step, as before.
#include "engine/periodic_boundary.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/body_tag.hpp"

namespace rodsort::engine {

PeriodicCell::PeriodicCell(double box_x, double box_y, double reach)
    : box_x_(box_x),
      box_y_(box_y),
      reach_(reach),
      shifts_{btVector3(box_x, 0, 0), btVector3(0, box_y, 0), btVector3(box_x, box_y, 0),
              btVector3(box_x, -box_y, 0)} {}

bool PeriodicCell::image_needed(double x, double y, int index) const {
  const btVector3& s = shifts_[static_cast<std::size_t>(index)];
  const double image_x = x + s.x();
  const double image_y = y + s.y();
  return image_x > -reach_ && image_x < box_x_ + reach_ && image_y > -reach_ &&
         image_y < box_y_ + reach_;
}

std::array<std::int64_t, 2> PeriodicCell::wrap_count(double x, double y) const {
  return {static_cast<std::int64_t>(std::floor(x / box_x_)),
          static_cast<std::int64_t>(std::floor(y / box_y_))};
}

bool PeriodicOverlapFilter::needBroadphaseCollision(btBroadphaseProxy* proxy0,
                                                    btBroadphaseProxy* proxy1) const {
  const bool groups_meet = (proxy0->m_collisionFilterGroup & proxy1->m_collisionFilterMask) != 0 &&
                           (proxy1->m_collisionFilterGroup & proxy0->m_collisionFilterMask) != 0;
  if (!groups_meet) return false;
  const auto* a = static_cast<const btCollisionObject*>(proxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(proxy1->m_clientObject);
  const auto* tag_a = static_cast<const BodyTag*>(a->getUserPointer());
  const auto* tag_b = static_cast<const BodyTag*>(b->getUserPointer());
  const bool image_pair = tag_a->kind == BodyKind::kImage || tag_b->kind == BodyKind::kImage;
  return !(image_pair && tag_a->rod == tag_b->rod);
}

void PeriodicContactSolver::convertContacts(btPersistentManifold** manifolds, int manifold_count,
                                            const btContactSolverInfo& info) {
  translated_.clear();
  for (int i = 0; i < manifold_count; ++i) {
    btPersistentManifold* manifold = manifolds[i];
    const auto* tag0 = static_cast<const BodyTag*>(manifold->getBody0()->getUserPointer());
    const auto* tag1 = static_cast<const BodyTag*>(manifold->getBody1()->getUserPointer());
    const bool image0 = tag0->kind == BodyKind::kImage;
    const bool image1 = tag1->kind == BodyKind::kImage;
    if (!image0 && !image1) {
      convertContact(manifold, info);
      continue;
    }
    btPersistentManifold& copy = translated_.emplace_back(*manifold);
    const btCollisionObject* body0 =
        image0 ? rods_[static_cast<std::size_t>(tag0->rod)] : manifold->getBody0();
    const btCollisionObject* body1 =
        image1 ? rods_[static_cast<std::size_t>(tag1->rod)] : manifold->getBody1();
    copy.setBodies(body0, body1);
    for (int p = 0; p < copy.getNumContacts(); ++p) {
      btManifoldPoint& point = copy.getContactPoint(p);
      if (image0) point.m_positionWorldOnA -= cell_.shift(tag0->shift);
      if (image1) point.m_positionWorldOnB -= cell_.shift(tag1->shift);
    }
    convertContact(&copy, info);
  }
}

void PeriodicContactSolver::start_step(const RandomStream& stream) { sweep_stream_ = stream; }

btScalar PeriodicContactSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  const btScalar result =
      exact_ ? btMLCPSolver::solveGroupCacheFriendlySetup(bodies, body_count, manifolds,
                                                          manifold_count, constraints,
                                                          constraint_count, info, debug)
             : btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
                   bodies, body_count, manifolds, manifold_count, constraints, constraint_count,
                   info, debug);
  if (noise_rates_ == nullptr) return result;
  // Only rods with a contact are turned here, so that which rods the solver turns does not depend
  // on how the islands are grouped into batches (a batch without contacts is not set up).
  for (int m = 0; m < manifold_count; ++m) {
    if (manifolds[m]->getNumContacts() == 0) continue;
    for (const btCollisionObject* body : {manifolds[m]->getBody0(), manifolds[m]->getBody1()}) {
      const auto& tag = *static_cast<const BodyTag*>(body->getUserPointer());
      if (tag.kind != BodyKind::kRod && tag.kind != BodyKind::kImage) continue;
      const auto rod = static_cast<std::size_t>(tag.rod);
      const double rate = (*noise_rates_)[rod];
      if (rate == 0.0 || (*noise_turned_)[rod]) continue;
      const int solver_body = rods_[rod]->getCompanionId();
      if (solver_body < 0) continue;
      // Bullet applies a turn velocity scaled by m_splitImpulseTurnErp, which the engine sets to
      // 1.
      m_tmpSolverBodyPool[solver_body].m_turnVelocity += btVector3(0, 0, rate);
      (*noise_turned_)[rod] = 1;
    }
  }
  return result;
}

btScalar PeriodicContactSolver::solveGroupCacheFriendlyIterations(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  if (exact_) {
    return btMLCPSolver::solveGroupCacheFriendlyIterations(
        bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, debug);
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
      bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, debug);
}

btScalar PeriodicContactSolver::solveSingleIteration(
    int iteration, btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  // A fresh random order of the contacts for this sweep (Fisher-Yates), each contact's two
  // friction rows kept right after it, as the interleaved solver mode expects. Bullet's own
  // SOLVER_RANDMIZE_ORDER shuffles the friction rows independently of their contacts, which would
  // bound a friction row by another contact's normal impulse.
  if (!fixed_sweep_order_) {
    const int count = m_tmpSolverContactConstraintPool.size();
    for (int c = 0; c < count; ++c) m_orderTmpConstraintPool[c] = c;
    for (int c = count - 1; c > 0; --c) {
      const auto bound = static_cast<std::uint64_t>(c + 1);
      const int pick = static_cast<int>(((sweep_stream_.next() >> 32) * bound) >> 32);
      std::swap(m_orderTmpConstraintPool[c], m_orderTmpConstraintPool[pick]);
    }
    for (int c = 0; c < count; ++c) {
      const int friction =
          m_tmpSolverContactConstraintPool[m_orderTmpConstraintPool[c]].m_frictionIndex;
      m_orderFrictionConstraintPool[2 * c] = friction;
      m_orderFrictionConstraintPool[2 * c + 1] = friction + 1;
    }
  }
  return btSequentialImpulseConstraintSolver::solveSingleIteration(
      iteration, bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info,
      debug);
}

}  // namespace rodsort::engine
