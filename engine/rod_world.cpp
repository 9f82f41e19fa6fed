// A btDiscreteDynamicsWorld that skips what the simulation never uses.
//
// Every step of Bullet's world makes about a dozen passes over all bodies. With a few thousand rods
// the bodies no longer fit in the processor's caches, and each pass costs a trip to memory for
// every rod: some of these passes do nothing here, and skipping them is most of what keeps the cost
// per rod flat as the system grows. What is skipped, and why it changes nothing:
//  - predictUnconstraintMotion: damps velocities (rods have no damping) and predicts each body's
//    transform at the end of the step into its interpolation transform. The prediction is only
//    used for continuous collision detection (off: DESIGN.md) and to widen the body's broadphase
//    box by its motion over the step, which matters only for fast bodies; the rods move by less
//    than a micrometre per step. The interpolation transform now holds the pose at the start of the
//    step, and the broadphase box is that of the pose.
//  - createPredictiveContacts: computes, for every body, the same prediction again, for
//    continuous collision detection only.
//  - calculateSimulationIslands, and the island building in solveConstraints: simulation islands
//    serve deactivation (disabled for every body) and splitting the solver's work by island (the
//    engine solves everything as one island: see periodic_boundary.cpp). The solver gets what
//    Bullet hands it without split islands: every collision object, every manifold, in Bullet's
//    order.
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
  btCollisionObjectArray& objects = getCollisionObjectArray();
  btDispatcher* dispatcher = getDispatcher();
  const int manifold_count = dispatcher->getNumManifolds();
  m_constraintSolver->prepareSolve(objects.size(), manifold_count);
  m_constraintSolver->solveGroup(
      objects.size() > 0 ? &objects[0] : nullptr, objects.size(),
      manifold_count > 0 ? dispatcher->getInternalManifoldPointer() : nullptr, manifold_count,
      nullptr, 0, solver_info, getDebugDrawer(), dispatcher);
  m_constraintSolver->allSolved(solver_info, getDebugDrawer());
}

void RodWorld::updateActivationState(btScalar /*time_step*/) {}

void RodWorld::synchronizeMotionStates() {}

}  // namespace rodsort::engine
