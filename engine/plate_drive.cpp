// The plate drive. The base and the lid are kinematic boxes: Bullet gives them no dynamics but
// derives their velocity from the change of their transform over a step
// (btRigidBody::saveKinematicState). We move them to their position at t + dt before each step
// and let Bullet take exactly one internal step of dt per call, so the velocity the contact solver
// sees is the mean plate velocity over that step, (z(t+dt) - z(t)) / dt, and the plates are where
// the drive says at every step boundary. Thin boxes are much cheaper than btStaticPlaneShape,
// which keeps one manifold per sphere.
#include "engine/plate_drive.hpp"

#include <cmath>

#include "engine/units.hpp"

namespace rodsort::engine {

double PlateDrive::base_surface_z(double time) const {
  return drive_.amplitude * std::cos(2.0 * kPi * drive_.frequency * time);
}

double PlateDrive::lid_surface_z(double time) const { return base_surface_z(time) + drive_.gap; }

void PlateDrive::place(btRigidBody& base, btRigidBody& lid, double time, bool reset) const {
  btTransform base_transform = base.getWorldTransform();
  base_transform.getOrigin().setZ(base_surface_z(time) + base_reach_ - kPlateHalfThickness);
  btTransform lid_transform = lid.getWorldTransform();
  lid_transform.getOrigin().setZ(lid_surface_z(time) - lid_reach_ + kPlateHalfThickness);
  base.setWorldTransform(base_transform);
  lid.setWorldTransform(lid_transform);
  if (reset) {
    base.setInterpolationWorldTransform(base_transform);
    lid.setInterpolationWorldTransform(lid_transform);
    base.setLinearVelocity(btVector3(0, 0, 0));
    lid.setLinearVelocity(btVector3(0, 0, 0));
    base.setInterpolationLinearVelocity(btVector3(0, 0, 0));
    lid.setInterpolationLinearVelocity(btVector3(0, 0, 0));
  }
}

}  // namespace rodsort::engine
