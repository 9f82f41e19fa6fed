#pragma once

#include <array>
#include <vector>

#include <LinearMath/btVector3.h>

#include "engine/random_stream.hpp"

class btPersistentManifold;
class btRigidBody;

namespace rodsort::engine {

/// The paper's angular noise: at each collision of a rod with the base or the lid,
/// omega_z += s * eps * v_rel, with s = +-1 at random and v_rel the normal relative velocity of the
/// contact points at impact.
class CollisionKick {
 public:
  /// Per-rod memory: whether the rod touched the base [0] and the lid [1] after the last step.
  using Touching = std::array<bool, 2>;

  /// Call before the Bullet step: remembers the rods' velocities before the impact.
  void save_velocities(const std::vector<btRigidBody*>& rods);

  /// Call after the Bullet step, with the manifolds the step solved in the solver's canonical
  /// order (SolverBatches). Detects new contacts with the plates, applies the kicks of the rods
  /// whose eps is non-zero, updates `touching`. Returns the number of collision events.
  int apply(btPersistentManifold* const* manifolds, int manifold_count,
            const std::vector<btRigidBody*>& rods, const std::vector<double>& kick_eps,
            std::vector<Touching>& touching, std::vector<RandomStream>& streams);

 private:
  struct Impact {
    double impulse = 0.0;  ///< largest applied impulse among the contact points [g mm/s]
    double normal_speed = 0.0;  ///< |v_rel . n| at that point, from the saved velocities [mm/s]
  };

  std::vector<btVector3> position_before_, velocity_before_, angular_velocity_before_;
  std::vector<std::array<Impact, 2>> impacts_;
};

}  // namespace rodsort::engine
