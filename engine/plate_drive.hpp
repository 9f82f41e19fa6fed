#pragma once

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "engine/model.hpp"

namespace rodsort::engine {

/// Positions of the base plate and the lid: z_base(t) = A cos(2 pi f t), z_lid(t) = z_base(t) + w.
class PlateDrive {
 public:
  /// `base_reach` and `lid_reach` are how far a rough plate's surface may stand out of its nominal
  /// surface (PlateRoughness::reach, 0 for a flat plate): the plate's box is moved out by as much,
  /// so that Bullet's broadphase meets a rod wherever the surface can touch it.
  explicit PlateDrive(const Drive& drive, double base_reach = 0.0, double lid_reach = 0.0)
      : drive_(drive), base_reach_(base_reach), lid_reach_(lid_reach) {}

  double base_surface_z(double time) const;  ///< top surface of the base [mm]
  double lid_surface_z(double time) const;   ///< bottom surface of the lid [mm]

  /// Places the kinematic plate bodies at `time`. `reset` also sets the interpolation transform,
  /// so that the velocity Bullet derives for the next step starts from this position.
  void place(btRigidBody& base, btRigidBody& lid, double time, bool reset) const;

  /// Half thickness of the plate boxes [mm].
  static constexpr double kPlateHalfThickness = 1.0;

 private:
  Drive drive_;
  double base_reach_, lid_reach_;
};

}  // namespace rodsort::engine
