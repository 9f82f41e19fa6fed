#pragma once
// Turns the frames of a run, in time order, into the rows of metrics.csv: the trapping and
// sorting measures of every frame that has a frame at least tau earlier to measure speeds
// against. It holds the few frames it still needs, so it runs the same on a live simulation (the
// runner feeds it every output frame) and on rods.csv read back (`rodsort analyze`).
//
// A rod is held when it is inside the trap and moved less than held_distance since the latest
// frame at or before t - held_lag (metrics/sorting.hpp); the held columns are NaN until such a
// frame has been seen.
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
  double window = kDefaultWindow;                               ///< tau [s]
  double stationary_speed_threshold = kDefaultStationarySpeed;  ///< [mm/s]
  double held_distance = kDefaultHeldDistance;  ///< a held rod moved less than this [mm]
  double held_lag = kDefaultHeldLag;            ///< over this time [s]
};

struct MetricsRow {
  double time = 0.0;             ///< of the later frame [s]
  double window = 0.0;           ///< real time between the two frames [s]
  double mean_speed = 0.0;       ///< over all rods [mm/s]
  std::vector<bool> stationary;  ///< per rod, speed over the window below the threshold
  TrappingCounts counts;
  Efficiency efficiency;  ///< NaN everywhere when there is no trap
  Sorting sorting;
  /// Rods inside the trap that moved less than held_distance over held_lag; empty without a trap
  /// or until a frame held_lag earlier has been seen.
  std::optional<Held> held;
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
  /// cell, then with a trap n_held_trap and for each species n_held_trap_s, fraction_held_s,
  /// purity_held_s.
  std::string csv_header() const;
  /// One row in the order of csv_header(), without a newline; undefined values are "nan".
  std::string csv_line(const MetricsRow& row) const;

  const MetricsConfig& config() const { return config_; }
  /// How far back the observer looks [s]: a resumed observer needs the frames of this span again.
  double history() const;

 private:
  MetricsConfig config_;
  struct Positions {
    double time;
    std::vector<Eigen::Vector2d> unwrapped;
  };
  bool has_trap() const;
  /// The latest frame at or before `time` - `span` among `frames`, dropping those before it.
  template <class Stored>
  static const Stored* earlier_than(std::deque<Stored>& frames, double time, double span);

  std::deque<engine::Frame> recent_;    ///< frames that a later frame may still measure against
  std::deque<Positions> held_history_;  ///< positions that a later frame may still compare with
};

}  // namespace rodsort::metrics
