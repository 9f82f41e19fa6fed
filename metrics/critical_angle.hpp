#pragma once
// The critical opening angle theta_c from a sweep: eta (time-averaged over the plateau of each
// run) against the trap's angle stays near its low-angle plateau, then drops abruptly (the paper:
// at 125° in simulation). theta_c is where eta falls through half of that plateau.

#include <string>
#include <vector>

namespace rodsort::metrics {

struct SweepPoint {
  double angle;  ///< opening angle, in whatever unit the caller uses (degrees from a sweep)
  double eta;    ///< time-averaged trapping efficiency
};

struct CriticalAngle {
  bool found = false;
  std::string reason;    ///< why not, when not found
  double angle = 0.0;    ///< theta_c, linearly interpolated between the bracketing points
  double below = 0.0;    ///< largest swept angle before the drop (eta >= half)
  double above = 0.0;    ///< smallest swept angle after it (eta < half)
  double plateau = 0.0;  ///< mean eta of the plateau_points smallest angles
  double half = 0.0;     ///< plateau / 2
};

/// Sorts the points by angle; the plateau is the mean eta of the `plateau_points` smallest
/// angles; theta_c is the first downward crossing of plateau/2 going up in angle, interpolated
/// linearly in eta between the two bracketing points.
CriticalAngle critical_angle(std::vector<SweepPoint> points, int plateau_points = 3);

}  // namespace rodsort::metrics
