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

  /// engine::Model::reverse_contact_order.
  void set_reverse_contact_order(bool reversed) { batches_.set_reversed(reversed); }
  /// engine::Model::single_solver_batch.
  void set_single_solver_batch(bool single) { batches_.set_single_batch(single); }

  /// The manifolds the last step solved, in the solver's canonical order (solver_batches.cpp).
  btPersistentManifold* const* solved_manifolds() const { return batches_.all_manifolds(); }
  int solved_manifold_count() const { return batches_.all_manifold_count(); }

 private:
  SolverBatches batches_;
};

}  // namespace rodsort::engine
