#include "metrics/critical_angle.hpp"

#include <algorithm>

namespace rodsort::metrics {

CriticalAngle critical_angle(std::vector<SweepPoint> points, int plateau_points) {
  CriticalAngle result;
  if (points.size() < 2) {
    result.reason =
        "a critical angle needs at least two angles, got " + std::to_string(points.size());
    return result;
  }
  std::sort(points.begin(), points.end(),
            [](const SweepPoint& a, const SweepPoint& b) { return a.angle < b.angle; });
  const int used = std::clamp(plateau_points, 1, static_cast<int>(points.size()));
  for (int i = 0; i < used; ++i) result.plateau += points[i].eta;
  result.plateau /= used;
  result.half = 0.5 * result.plateau;
  if (!(result.plateau > 0.0)) {
    result.reason =
        "eta at the smallest angles is not positive: nothing is trapped, so there is "
        "no plateau to fall from";
    return result;
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const SweepPoint& a = points[i];
    const SweepPoint& b = points[i + 1];
    if (a.eta >= result.half && b.eta < result.half) {
      result.found = true;
      result.below = a.angle;
      result.above = b.angle;
      result.angle = a.angle + (a.eta - result.half) / (a.eta - b.eta) * (b.angle - a.angle);
      return result;
    }
  }
  result.reason = "eta never falls below half its low-angle plateau (" +
                  std::to_string(result.half) + ") over the angles swept";
  return result;
}

}  // namespace rodsort::metrics
