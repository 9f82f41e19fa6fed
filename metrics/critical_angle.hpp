#pragma once
// The critical opening angle theta_c from a sweep: eta (time-averaged over the plateau of each
// run) against the trap's angle stays near its low-angle plateau, then drops abruptly (the paper:
// at 125° in simulation). theta_c is where eta falls through half of that plateau.
//
// Only where the data bear it: fewer than plateau_points + 2 angles cannot show both a plateau
// and a drop; a plateau below kMinPlateauEta is not a trap filling; and a theta_c comes with a
// caution when eta at the smallest angles was still rising in the second half of the runs, or when
// eta at a wider angle beyond the drop is above half the plateau again.

#include <limits>
#include <string>
#include <vector>

namespace rodsort::metrics {

/// Least plateau eta from which a drop is looked for: below it the smallest angles' traps have
/// not filled (runs too short, or no trapping at all), and half of it is within noise.
inline constexpr double kMinPlateauEta = 0.1;

struct SweepPoint {
  double angle;  ///< opening angle, in whatever unit the caller uses (degrees from a sweep)
  double eta;    ///< time-averaged trapping efficiency
  /// When eta reached 90% of its final level, the latest over the runs at this angle [s]; NaN
  /// when it never did, or is not known (then `duration` is NaN too).
  double levelled_at = std::numeric_limits<double>::quiet_NaN();
  /// Simulated length of the runs, the shortest over those at this angle [s]; NaN: not known.
  double duration = std::numeric_limits<double>::quiet_NaN();
};

struct CriticalAngle {
  bool found = false;
  std::string reason;    ///< why not, when not found
  double angle = 0.0;    ///< theta_c, linearly interpolated between the bracketing points
  double below = 0.0;    ///< largest swept angle before the drop (eta >= half)
  double above = 0.0;    ///< smallest swept angle after it (eta < half)
  double plateau = 0.0;  ///< mean eta of the plateau_points smallest angles
  double half = 0.0;     ///< plateau / 2
  /// When found: why it may not be reliable (empty when nothing is known against it).
  std::string caution;
};

/// Sorts the points by angle; the plateau is the mean eta of the `plateau_points` smallest
/// angles; theta_c is the first downward crossing of plateau/2 going up in angle, interpolated
/// linearly in eta between the two bracketing points. Not found, with the reason, for fewer than
/// plateau_points + 2 angles or a plateau below kMinPlateauEta.
CriticalAngle critical_angle(std::vector<SweepPoint> points, int plateau_points = 3);

/// theta_c of each seed of a sweep alone, and their spread: the error bar of theta_c.
struct SeedCriticalAngles {
  std::vector<CriticalAngle> per_seed;  ///< in the order of the seeds given
  int found = 0;                        ///< seeds with a theta_c
  /// Mean, standard deviation and standard error (sd / sqrt(found)) over the seeds with a
  /// theta_c; NaN for fewer than one (mean) or two (sd, standard error).
  double mean = std::numeric_limits<double>::quiet_NaN();
  double standard_deviation = std::numeric_limits<double>::quiet_NaN();
  double standard_error = std::numeric_limits<double>::quiet_NaN();
};

/// critical_angle of each seed's points on their own.
SeedCriticalAngles critical_angle_per_seed(const std::vector<std::vector<SweepPoint>>& seeds,
                                           int plateau_points = 3);

}  // namespace rodsort::metrics
