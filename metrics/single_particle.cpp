#include "metrics/single_particle.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "metrics/kinematics.hpp"
#include "metrics/sample_statistics.hpp"

namespace rodsort::metrics {

namespace {

/// Appends an angle to a series kept continuous: the step from the last angle taken the shorter
/// way round.
void append_unwrapped(std::vector<double>& series, double angle) {
  series.push_back(series.empty() ? angle : series.back() + wrap_angle(angle - series.back()));
}

}  // namespace

Track track_of(const std::vector<engine::Frame>& frames, int rod) {
  Track track;
  for (const engine::Frame& frame : frames) {
    const engine::RodFrame& r = frame.rods.at(static_cast<std::size_t>(rod));
    const double phi = heading(r);
    track.time.push_back(frame.time);
    track.position.push_back(r.unwrapped);
    track.tilt.push_back(r.axis.z());
    append_unwrapped(track.heading, phi);
  }
  return track;
}

double roll_angle(const std::array<double, 9>& basis) {
  const Eigen::Vector3d axis(basis[0], basis[3], basis[6]);
  const Eigen::Vector3d body_y(basis[1], basis[4], basis[7]);
  // Left of the axis in the horizontal plane, and the direction normal to the axis nearest the
  // vertical; for an upright rod (no left) the body x-z plane stands in.
  Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(axis);
  if (left.norm() < 1e-12) left = Eigen::Vector3d(basis[1], basis[4], 0.0);
  left.normalize();
  const Eigen::Vector3d up = axis.cross(left);
  return std::atan2(body_y.dot(up), body_y.dot(left));
}

Track roll_track(const Track& track, const std::vector<double>& roll) {
  assert(roll.size() == track.time.size());
  Track rolled = track;
  rolled.heading.clear();
  for (const double angle : roll) append_unwrapped(rolled.heading, angle);
  return rolled;
}

double thin_end_down_fraction(const std::vector<Track>& tracks) {
  long down = 0, samples = 0;
  for (const Track& track : tracks) {
    for (const double tilt : track.tilt) down += tilt < 0.0 ? 1 : 0;
    samples += static_cast<long>(track.tilt.size());
  }
  return samples > 0 ? static_cast<double>(down) / static_cast<double>(samples)
                     : std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> axial_velocities(const Track& track, int lag, int stride) {
  assert(lag > 0 && stride > 0);
  std::vector<double> velocities;
  const std::size_t n = track.time.size();
  for (std::size_t i = 0; i + static_cast<std::size_t>(lag) < n;
       i += static_cast<std::size_t>(stride)) {
    const std::size_t j = i + static_cast<std::size_t>(lag);
    const double mean_heading = 0.5 * (track.heading[i] + track.heading[j]);
    const Eigen::Vector2d axis(std::cos(mean_heading), std::sin(mean_heading));
    velocities.push_back((track.position[j] - track.position[i]).dot(axis) /
                         (track.time[j] - track.time[i]));
  }
  return velocities;
}

LagStatistics lag_statistics(const std::vector<Track>& tracks, const std::vector<int>& lags) {
  LagStatistics statistics;
  for (const int lag : lags) {
    double position = 0.0, heading_square = 0.0, correlation = 0.0, time = 0.0;
    long count = 0;
    for (const Track& track : tracks) {
      for (std::size_t i = 0; i + static_cast<std::size_t>(lag) < track.time.size(); ++i) {
        const std::size_t j = i + static_cast<std::size_t>(lag);
        const double turn = track.heading[j] - track.heading[i];
        position += (track.position[j] - track.position[i]).squaredNorm();
        heading_square += turn * turn;
        correlation += std::cos(turn);
        time += track.time[j] - track.time[i];
        ++count;
      }
    }
    const double n = count > 0 ? static_cast<double>(count) : std::nan("");
    statistics.lag_time.push_back(time / n);
    statistics.position_msd.push_back(position / n);
    statistics.heading_msd.push_back(heading_square / n);
    statistics.orientation_correlation.push_back(correlation / n);
  }
  return statistics;
}

double rotational_diffusion_fit(const std::vector<double>& lag_time,
                                const std::vector<double>& heading_msd) {
  const LineFit line = fit_line(lag_time, heading_msd);
  return lag_time.size() >= 2 && line.determined ? 0.5 * line.slope : std::nan("");
}

double turn_rate(const Track& track) {
  if (track.heading.size() < 2) return std::nan("");
  return (track.heading.back() - track.heading.front()) / (track.time.back() - track.time.front());
}

Track without_steady_turn(const Track& track, double rate) {
  Track turned = track;
  for (std::size_t i = 0; i < turned.heading.size(); ++i) {
    turned.heading[i] -= rate * (track.time[i] - track.time.front());
  }
  return turned;
}

bool circles(double rate, double duration, double diffusion_about_turn) {
  const double net_turn = std::abs(rate) * duration;
  return net_turn > 2.0 * std::numbers::pi &&
         net_turn > 5.0 * std::sqrt(2.0 * std::max(diffusion_about_turn, 0.0) * duration);
}

RunsAndTumbles runs_and_tumbles(const std::vector<std::vector<double>>& velocity_series,
                                double window, double threshold,
                                const std::vector<std::vector<double>>& boundary_headings) {
  assert(boundary_headings.empty() || boundary_headings.size() == velocity_series.size());
  RunsAndTumbles result;
  result.threshold = threshold;
  long windows = 0, running = 0, run_windows = 0, tumble_windows = 0;
  double run_turn_square = 0.0, tumble_turn_square = 0.0;
  for (std::size_t k = 0; k < velocity_series.size(); ++k) {
    const std::vector<double>& series = velocity_series[k];
    const std::vector<double>* headings =
        boundary_headings.empty() ? nullptr : &boundary_headings[k];
    assert(headings == nullptr || series.empty() || headings->size() == series.size() + 1);
    std::size_t start = 0;
    for (std::size_t i = 0; i < series.size(); ++i) {
      const bool runs = series[i] > threshold;
      ++windows;
      if (runs) ++running;
      const bool last = i + 1 == series.size();
      if (!last && (series[i + 1] > threshold) == runs) continue;
      // A segment [start, i] ends here; only those bounded on both sides by the other kind count.
      if (start > 0 && !last) {
        const long length = static_cast<long>(i - start + 1);
        const double turn = headings ? std::remainder((*headings)[i + 1] - (*headings)[start],
                                                      2.0 * std::numbers::pi)
                                     : 0.0;
        if (runs) {
          ++result.runs;
          run_windows += length;
          run_turn_square += turn * turn;
        } else {
          ++result.tumbles;
          tumble_windows += length;
          tumble_turn_square += turn * turn;
        }
      }
      start = i + 1;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto per = [nan](double total, long count) {
    return count > 0 ? total / static_cast<double>(count) : nan;
  };
  result.running_fraction = per(static_cast<double>(running), windows);
  result.mean_run = window * per(static_cast<double>(run_windows), result.runs);
  result.mean_tumble = window * per(static_cast<double>(tumble_windows), result.tumbles);
  const bool turns = !boundary_headings.empty();
  result.run_turn_rms = turns ? std::sqrt(per(run_turn_square, result.runs)) : nan;
  result.tumble_turn_rms = turns ? std::sqrt(per(tumble_turn_square, result.tumbles)) : nan;
  return result;
}

double backward_fraction(const std::vector<double>& axial_velocities) {
  if (axial_velocities.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto backward = std::count_if(axial_velocities.begin(), axial_velocities.end(),
                                      [](double v) { return v < -kBackwardSpeed; });
  return static_cast<double>(backward) / static_cast<double>(axial_velocities.size());
}

std::vector<double> window_boundary_headings(const Track& track, int lag) {
  assert(lag > 0);
  std::vector<double> headings;
  const std::size_t n = track.heading.size();
  const std::size_t step = static_cast<std::size_t>(lag);
  for (std::size_t i = 0; i < n; i += step) headings.push_back(track.heading[i]);
  return headings;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return values[below] + fraction * (values[above] - values[below]);
}

TwoPeaks two_peaks(const std::vector<double>& bin_centre, const std::vector<double>& density) {
  TwoPeaks peaks;
  const std::size_t n = density.size();
  if (n == 0) return peaks;
  std::vector<double> smooth(n);
  for (std::size_t b = 0; b < n; ++b) {
    const std::size_t first = b > 0 ? b - 1 : 0, last = std::min(b + 1, n - 1);
    double sum = 0.0;
    for (std::size_t c = first; c <= last; ++c) sum += density[c];
    smooth[b] = sum / static_cast<double>(last - first + 1);
  }
  const std::size_t top =
      static_cast<std::size_t>(std::max_element(smooth.begin(), smooth.end()) - smooth.begin());
  peaks.main = peaks.second = bin_centre[top];
  if (smooth[top] <= 0.0) return peaks;
  // The second peak is the one that rises most above the valley separating it from the main
  // peak (its prominence); walking away from the main peak, the lowest density met so far is
  // that valley.
  double best_prominence = 0.0;
  for (const int direction : {-1, 1}) {
    double lowest = smooth[top];
    std::size_t b = top;
    while (direction < 0 ? b > 0 : b + 1 < n) {
      b = direction < 0 ? b - 1 : b + 1;
      lowest = std::min(lowest, smooth[b]);
      const double prominence = smooth[b] - lowest;
      if (prominence > best_prominence) {
        best_prominence = prominence;
        peaks.second = bin_centre[b];
        peaks.second_height = smooth[b] / smooth[top];
        peaks.valley = lowest / smooth[b];
      }
    }
  }
  return peaks;
}

}  // namespace rodsort::metrics
