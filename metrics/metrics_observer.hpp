#pragma once
// Turns the frames of a run, in time order, into the rows of metrics.csv: the trapping and
// sorting measures of every frame that has a frame at least tau earlier to measure speeds
// against. It holds the few frames it still needs, so it runs the same on a live simulation (the
// runner feeds it every output frame) and on rods.csv read back (`rodsort analyze`).
//
// Frames usually arrive every tau (the default output interval is the paper's 0.07 s). When they
// arrive more often, the speed of a frame at t is measured against the latest frame at or before
// t - tau; when less often, against the previous frame. Speeds always divide by the real time
// between the two frames.

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "engine/frame.hpp"
#include "metrics/sorting.hpp"
#include "metrics/trapping.hpp"

namespace rodsort::metrics {

struct MetricsConfig {
  std::vector<std::string> species_names;  ///< index = species index
  std::vector<double> species_area;        ///< projected area a_s of each species [mm^2]
  double trap_area = 0.0;                  ///< A_t [mm^2]; 0 when there is no trap
  InsidePredicate inside;                  ///< empty when there is no trap
  /// Whether a rod's centre lies along a bounded cell's wall (within a rod's reach of it);
  /// empty for the periodic cell.
  InsidePredicate at_wall;
  double window = kDefaultWindow;          ///< tau [s]
  double stationary_speed_threshold = kDefaultStationarySpeed;  ///< [mm/s]
};

struct MetricsRow {
  double time = 0.0;             ///< of the later frame [s]
  double window = 0.0;           ///< real time between the two frames [s]
  double mean_speed = 0.0;       ///< over all rods [mm/s]
  std::vector<bool> stationary;  ///< per rod, speed over the window below the threshold
  TrappingCounts counts;
  Efficiency efficiency;  ///< NaN everywhere when there is no trap
  Sorting sorting;
  int at_wall = 0;  ///< rods along a bounded cell's wall; 0 for the periodic cell
};

class MetricsObserver {
 public:
  explicit MetricsObserver(MetricsConfig config);

  /// Feeds the next frame (later than the previous one); returns its row once a frame at least
  /// tau earlier has been seen.
  std::optional<MetricsRow> observe(const engine::Frame& frame);

  /// The columns of metrics.csv, without a newline:
  /// t,eta,eta_trap,n_rods,n_stationary,n_trap,n_stationary_trap,mean_speed, then for each
  /// species s: n_stationary_s,n_trap_s,n_stationary_trap_s,eta_s,eta_trap_s,fraction_trap_s,
  /// purity_s, then sorting_index when there are two species or more, then n_wall in a bounded
  /// cell.
  std::string csv_header() const;
  /// One row in the order of csv_header(), without a newline; undefined values are "nan".
  std::string csv_line(const MetricsRow& row) const;

  const MetricsConfig& config() const { return config_; }

 private:
  MetricsConfig config_;
  std::deque<engine::Frame> recent_;  ///< frames that a later frame may still measure against
};

}  // namespace rodsort::metrics
