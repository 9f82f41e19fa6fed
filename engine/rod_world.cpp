// A btDiscreteDynamicsWorld that skips what the simulation never uses.
//
// Every step of Bullet's world makes about a dozen passes over all bodies, and with a few thousand
// rods each pass costs a trip to memory for every rod. Some of these passes do nothing here. What
// is skipped, and why it changes nothing:
//  - predictUnconstraintMotion: damps velocities (rods have no damping) and predicts each body's
//    transform at the end of the step into its interpolation transform. The prediction is only
//    used for continuous collision detection (off: DESIGN.md) and to widen the body's broadphase
//    box by its motion over the step, which matters only for fast bodies; the rods move by less
//    than a micrometre per step. The interpolation transform now holds the pose at the start of the
//    step, and the broadphase box is that of the pose.
//  - createPredictiveContacts: computes, for every body, the same prediction again, for
//    continuous collision detection only.
//  - calculateSimulationIslands, and the island building in solveConstraints: Bullet's simulation
//    islands serve deactivation (disabled for every body) and splitting the solver's work by
//    island, which Bullet cannot do right across periodic images (periodic_boundary.cpp). The
//    engine makes its own islands, which know the images, and hands them to the solver batch by
//    batch (solver_batches.cpp), with the same result as one call with everything when the sweep
//    order is fixed (tests/engine/solver_batches_test.cpp).
//  - updateActivationState and synchronizeMotionStates: deactivation is disabled for every body,
//    and no body has a motion state.
#include "engine/rod_world.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletDynamics/ConstraintSolver/btConstraintSolver.h>

namespace rodsort::engine {

void RodWorld::predictUnconstraintMotion(btScalar /*time_step*/) {}

void RodWorld::createPredictiveContacts(btScalar /*time_step*/) {}

void RodWorld::calculateSimulationIslands() {}

void RodWorld::solveConstraints(btContactSolverInfo& solver_info) {
  btDispatcher* dispatcher = getDispatcher();
  const int manifold_count = dispatcher->getNumManifolds();
  batches_.build(m_nonStaticRigidBodies,
                 manifold_count > 0 ? dispatcher->getInternalManifoldPointer() : nullptr,
                 manifold_count);
  m_constraintSolver->prepareSolve(getNumCollisionObjects(), manifold_count);
  for (int b = 0; b < batches_.size(); ++b) {
    m_constraintSolver->solveGroup(batches_.bodies(b), batches_.body_count(b),
                                   batches_.manifolds(b), batches_.manifold_count(b), nullptr, 0,
                                   solver_info, getDebugDrawer(), dispatcher);
  }
  m_constraintSolver->allSolved(solver_info, getDebugDrawer());
}

void RodWorld::updateActivationState(btScalar /*time_step*/) {}

void RodWorld::synchronizeMotionStates() {}

}  // namespace rodsort::engine
