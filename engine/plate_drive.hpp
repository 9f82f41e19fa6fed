#pragma once

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "engine/model.hpp"

namespace rodsort::engine {

/// Positions of the base plate and the lid: z_base(t) = A cos(2 pi f t), z_lid(t) = z_base(t) + w.
class PlateDrive {
 public:
  explicit PlateDrive(const Drive& drive) : drive_(drive) {}

  double base_surface_z(double time) const;  ///< top surface of the base [mm]
  double lid_surface_z(double time) const;   ///< bottom surface of the lid [mm]

  /// Places the kinematic plate bodies at `time`. `reset` also sets the interpolation transform,
  /// so that the velocity Bullet derives for the next step starts from this position.
  void place(btRigidBody& base, btRigidBody& lid, double time, bool reset) const;

  /// Half thickness of the plate boxes [mm].
  static constexpr double kPlateHalfThickness = 1.0;

 private:
  Drive drive_;
};

}  // namespace rodsort::engine
