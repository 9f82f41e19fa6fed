#pragma once

#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "engine/random_stream.hpp"

class btRigidBody;

namespace rodsort::engine {

/// Geometry of the periodic cell [0, box_x) x [0, box_y) and of the image shifts.
class PeriodicCell {
 public:
  static constexpr int kShiftCount = 4;

  /// reach: how far beyond the cell edge an image must be kept so that it can touch a rod whose
  /// centre is inside the cell (twice the largest rod half-length plus a margin) [mm].
  PeriodicCell(double box_x, double box_y, double reach);

  double box_x() const { return box_x_; }
  double box_y() const { return box_y_; }
  btVector3 shift(int index) const { return shifts_[static_cast<std::size_t>(index)]; }

  /// Whether the image of a rod centred at (x, y) (wrapped) under shift `index` can touch a rod.
  bool image_needed(double x, double y, int index) const;
  /// False when a rod centred at (x, y) (wrapped) needs no image at all: it is farther than the
  /// reach from every edge.
  bool near_edge(double x, double y) const {
    return x < reach_ || x > box_x_ - reach_ || y < reach_ || y > box_y_ - reach_;
  }

  /// Number of cells to subtract along x and y to bring (x, y) into the cell.
  std::array<std::int64_t, 2> wrap_count(double x, double y) const;

 private:
  double box_x_, box_y_, reach_;
  std::array<btVector3, kShiftCount> shifts_;
};

/// Broadphase filter: the usual group/mask test, and a rod never meets its own image.
class PeriodicOverlapFilter : public btOverlapFilterCallback {
 public:
  bool needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const override;
};

/// Contact solver for periodic images: a contact with an image is handed to the solver as a
/// contact with the real rod, its contact point moved back by the image's shift.
/// It is Bullet's sequential-impulse solver unless set_exact(), which solves each batch's contacts
/// as one linear complementarity problem (Bullet's MLCP solver with its Dantzig algorithm); that
/// is a diagnostic (engine::Model::exact_contact_solver), not meant for piles.
class PeriodicContactSolver : public btMLCPSolver {
 public:
  PeriodicContactSolver(const PeriodicCell& cell, const std::vector<btRigidBody*>& rods)
      : btMLCPSolver(&dantzig_), cell_(cell), rods_(rods) {}

  /// engine::Model::exact_contact_solver.
  void set_exact(bool exact) { exact_ = exact; }
  /// Solves since construction that the exact solver gave up on and left to the sequential-impulse
  /// iterations (a singular or ill-conditioned problem).
  int exact_fallbacks() const { return getNumFallbacks(); }
  btConstraintSolverType getSolverType() const override {
    return exact_ ? BT_MLCP_SOLVER : BT_SEQUENTIAL_IMPULSE_SOLVER;
  }

  /// Each sweep meets the contacts in a random order drawn from `stream` (periodic_boundary.cpp,
  /// "Sweep order"); call before each step with a stream made from the seed and the step.
  void start_step(const RandomStream& stream);
  /// engine::Model::fixed_sweep_order.
  void set_fixed_sweep_order(bool fixed) { fixed_sweep_order_ = fixed; }
  /// The white noise's turn of each rod in the coming step, as a rate about the vertical
  /// [rad/s], given to the solver as part of its position correction (periodic_boundary.cpp,
  /// "White noise"); `turned` gets 1 for each rod the solver took it for, which the caller
  /// clears before the step. Both live as long as the solver.
  void set_noise_turns(const std::vector<double>* rates, std::vector<char>* turned) {
    noise_rates_ = rates;
    noise_turned_ = turned;
  }

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* debug) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int body_count,
                                             btPersistentManifold** manifolds, int manifold_count,
                                             btTypedConstraint** constraints, int constraint_count,
                                             const btContactSolverInfo& info,
                                             btIDebugDraw* debug) override;
  void convertContacts(btPersistentManifold** manifolds, int manifold_count,
                       const btContactSolverInfo& info) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int body_count,
                                btPersistentManifold** manifolds, int manifold_count,
                                btTypedConstraint** constraints, int constraint_count,
                                const btContactSolverInfo& info, btIDebugDraw* debug) override;

 private:
  const PeriodicCell& cell_;
  const std::vector<btRigidBody*>& rods_;
  std::deque<btPersistentManifold> translated_;  ///< live until the next step's conversion
  RandomStream sweep_stream_{0, 0, StreamPurpose::kSolverOrder};
  bool fixed_sweep_order_ = false;
  const std::vector<double>* noise_rates_ = nullptr;
  std::vector<char>* noise_turned_ = nullptr;
  btDantzigSolver dantzig_;
  bool exact_ = false;
};

}  // namespace rodsort::engine
