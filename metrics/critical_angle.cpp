#include "metrics/critical_angle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/sample_statistics.hpp"

namespace rodsort::metrics {

CriticalAngle critical_angle(std::vector<SweepPoint> points, int plateau_points) {
  CriticalAngle result;
  const int plateau_size = std::max(1, plateau_points);
  const std::size_t needed = static_cast<std::size_t>(plateau_size) + 2;
  if (points.size() < needed) {
    result.reason = "a critical angle needs at least " + std::to_string(needed) + " angles (" +
                    std::to_string(plateau_size) +
                    " for the low-angle plateau and two to bracket the drop), got " +
                    std::to_string(points.size());
    return result;
  }
  std::sort(points.begin(), points.end(),
            [](const SweepPoint& a, const SweepPoint& b) { return a.angle < b.angle; });
  for (int i = 0; i < plateau_size; ++i) result.plateau += points[i].eta;
  result.plateau /= plateau_size;
  result.half = 0.5 * result.plateau;
  if (!(result.plateau >= kMinPlateauEta)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "eta at the smallest angles is %.3g, below %.2g: their traps have not filled "
                  "(are the runs long enough?), so there is no plateau to fall from",
                  result.plateau, kMinPlateauEta);
    result.reason = text;
    return result;
  }
  // The plateau is the mean over the second half of each run: if eta was still rising there,
  // the plateau is too low and theta_c may be too.
  for (int i = 0; i < plateau_size; ++i) {
    const SweepPoint& point = points[static_cast<std::size_t>(i)];
    if (std::isnan(point.duration)) continue;
    if (std::isnan(point.levelled_at) || point.levelled_at > 0.5 * point.duration) {
      char text[240];
      if (std::isnan(point.levelled_at)) {
        std::snprintf(text, sizeof text,
                      "at %g, eta never reached 90%% of its final level in the runs (%g s): the "
                      "plateau, and theta_c with it, may be too low; run longer",
                      point.angle, point.duration);
      } else {
        std::snprintf(text, sizeof text,
                      "at %g, eta was still rising in the second half of the runs (it reached "
                      "90%% of its final level at %.3g s of %g s): the plateau, and theta_c "
                      "with it, may be too low; run longer",
                      point.angle, point.levelled_at, point.duration);
      }
      result.caution = text;
      break;
    }
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const SweepPoint& a = points[i];
    const SweepPoint& b = points[i + 1];
    if (a.eta >= result.half && b.eta < result.half) {
      result.found = true;
      result.below = a.angle;
      result.above = b.angle;
      result.angle = a.angle + (a.eta - result.half) / (a.eta - b.eta) * (b.angle - a.angle);
      // A trap that fills again beyond the drop: within the runs' length, whether a wide trap
      // holds a pile is a matter of when one nucleates, and the drop is not where it seems.
      for (std::size_t k = i + 2; k < points.size(); ++k) {
        if (points[k].eta >= result.half) {
          char text[240];
          std::snprintf(text, sizeof text,
                        "at %g, beyond theta_c, eta is %.3g, above half the plateau again: "
                        "whether a wider trap fills within the runs depends on when a pile "
                        "nucleates; run longer, or more seeds",
                        points[k].angle, points[k].eta);
          result.caution += (result.caution.empty() ? "" : "; ") + std::string(text);
          break;
        }
      }
      return result;
    }
  }
  result.reason = "eta never falls below half its low-angle plateau (" +
                  std::to_string(result.half) + ") over the angles swept";
  return result;
}

SeedCriticalAngles critical_angle_per_seed(const std::vector<std::vector<SweepPoint>>& seeds,
                                           int plateau_points) {
  SeedCriticalAngles result;
  std::vector<double> angles;
  for (const std::vector<SweepPoint>& points : seeds) {
    result.per_seed.push_back(critical_angle(points, plateau_points));
    if (result.per_seed.back().found) angles.push_back(result.per_seed.back().angle);
  }
  result.found = static_cast<int>(angles.size());
  if (angles.empty()) return result;
  const SampleStatistics statistics = sample_statistics(angles);
  result.mean = statistics.mean;
  if (angles.size() < 2) return result;
  result.standard_deviation = statistics.deviation;
  result.standard_error = statistics.standard_error;
  return result;
}

}  // namespace rodsort::metrics
