#pragma once

#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>

#include "engine/solver_batches.hpp"

namespace rodsort::engine {

/// Bullet's discrete dynamics world without the per-body passes this engine never needs; see
/// rod_world.cpp.
class RodWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

 protected:
  void predictUnconstraintMotion(btScalar time_step) override;
  void createPredictiveContacts(btScalar time_step) override;
  void calculateSimulationIslands() override;
  void solveConstraints(btContactSolverInfo& solver_info) override;
  void updateActivationState(btScalar time_step) override;

 public:
  void synchronizeMotionStates() override;

 private:
  SolverBatches batches_;
};

}  // namespace rodsort::engine
