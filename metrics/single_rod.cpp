#include "metrics/single_rod.hpp"

#include <cassert>
#include <numeric>

#include "metrics/kinematics.hpp"
#include "metrics/sample_statistics.hpp"

namespace rodsort::metrics {

double mean_axial_speed(const std::vector<engine::Frame>& frames, const std::vector<int>& rods,
                        int lag) {
  assert(lag > 0);
  double sum = 0.0;
  long samples = 0;
  for (std::size_t k = 0; k + lag < frames.size(); ++k) {
    const engine::Frame& earlier = frames[k];
    const engine::Frame& later = frames[k + lag];
    const double window = later.time - earlier.time;
    for (const int rod : rods) {
      const engine::RodFrame& a = earlier.rods.at(rod);
      const engine::RodFrame& b = later.rods.at(rod);
      const Eigen::Vector2d axis_sum =
          a.axis.head<2>().normalized() + b.axis.head<2>().normalized();
      if (axis_sum.norm() == 0.0) continue;  // reversed exactly: no axis to project on
      sum += (b.unwrapped - a.unwrapped).dot(axis_sum.normalized()) / window;
      ++samples;
    }
  }
  return samples > 0 ? sum / samples : 0.0;
}

RotationalDiffusion rotational_diffusion(const std::vector<engine::Frame>& frames,
                                         const std::vector<int>& rods, int min_lag, int max_lag) {
  assert(min_lag > 0 && max_lag >= min_lag);
  assert(frames.size() > static_cast<std::size_t>(max_lag));
  // Unwrapped heading of each listed rod in each frame.
  std::vector<std::vector<double>> phi(rods.size(), std::vector<double>(frames.size()));
  for (std::size_t r = 0; r < rods.size(); ++r) {
    phi[r][0] = heading(frames[0].rods.at(rods[r]));
    for (std::size_t k = 1; k < frames.size(); ++k) {
      phi[r][k] = phi[r][k - 1] + wrap_angle(heading(frames[k].rods.at(rods[r])) -
                                             heading(frames[k - 1].rods.at(rods[r])));
    }
  }
  RotationalDiffusion result;
  for (int lag = min_lag; lag <= max_lag; ++lag) {
    double square_sum = 0.0, time_sum = 0.0;
    long samples = 0;
    for (std::size_t k = 0; k + lag < frames.size(); ++k) {
      time_sum += frames[k + lag].time - frames[k].time;
      for (std::size_t r = 0; r < rods.size(); ++r) {
        const double change = phi[r][k + lag] - phi[r][k];
        square_sum += change * change;
        ++samples;
      }
    }
    result.lag_times.push_back(time_sum / static_cast<double>(frames.size() - lag));
    result.mean_square.push_back(samples > 0 ? square_sum / samples : 0.0);
  }
  // Least-squares line through (lag time, mean square); with a single lag, the ratio of the sums.
  const LineFit line = fit_line(result.lag_times, result.mean_square);
  const double slope =
      line.determined
          ? line.slope
          : 2.0 * std::accumulate(result.mean_square.begin(), result.mean_square.end(), 0.0) /
                std::accumulate(result.lag_times.begin(), result.lag_times.end(), 0.0);
  result.coefficient = slope / 2.0;
  result.intercept = line.intercept;
  return result;
}

}  // namespace rodsort::metrics
