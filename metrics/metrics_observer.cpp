#include "metrics/metrics_observer.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>

#include "metrics/kinematics.hpp"

namespace rodsort::metrics {
namespace {

void append(std::string& line, double value) {
  if (std::isnan(value)) {
    line += ",nan";
    return;
  }
  char text[32];
  std::snprintf(text, sizeof text, ",%.9g", value);
  line += text;
}

void append(std::string& line, int value) {
  line += ',';
  line += std::to_string(value);
}

}  // namespace

MetricsObserver::MetricsObserver(MetricsConfig config) : config_(std::move(config)) {
  assert(config_.species_area.size() == config_.species_names.size());
  assert(config_.window > 0.0);
}

bool MetricsObserver::has_trap() const { return config_.inside && config_.trap_area > 0.0; }

double MetricsObserver::history() const {
  return has_trap() ? std::max(config_.window, config_.held_lag) : config_.window;
}

template <class Stored>
const Stored* MetricsObserver::earlier_than(std::deque<Stored>& frames, double time, double span) {
  // Times come from step counts times dt, or back from 9 printed digits: allow a small slack.
  const double latest_start = time - span + 1e-3 * span;
  // Frames before the latest one at or before it are no longer needed by anyone.
  while (frames.size() >= 2 && frames[1].time <= latest_start) frames.pop_front();
  return !frames.empty() && frames.front().time <= latest_start ? &frames.front() : nullptr;
}

std::optional<MetricsRow> MetricsObserver::observe(const engine::Frame& frame) {
  assert(recent_.empty() || frame.time > recent_.back().time);
  const engine::Frame* earlier = earlier_than(recent_, frame.time, config_.window);
  const Positions* held_since =
      has_trap() ? earlier_than(held_history_, frame.time, config_.held_lag) : nullptr;
  std::optional<MetricsRow> row;
  if (earlier != nullptr) {
    assert(earlier->rods.size() == frame.rods.size());
    const std::vector<double> speeds = window_speeds(*earlier, frame);
    const std::vector<bool> stationary =
        stationary_flags(speeds, config_.stationary_speed_threshold);
    const std::vector<bool> inside =
        has_trap() ? inside_flags(frame, config_.inside) : std::vector<bool>(frame.rods.size());
    row.emplace();
    row->time = frame.time;
    row->window = frame.time - earlier->time;
    double speed_sum = 0.0;
    for (const double speed : speeds) speed_sum += speed;
    row->mean_speed = speeds.empty() ? 0.0 : speed_sum / speeds.size();
    const int species_count = static_cast<int>(config_.species_names.size());
    row->counts = count_trapping(frame, stationary, inside, species_count);
    row->stationary = stationary;
    if (has_trap()) {
      row->efficiency = trapping_efficiency(row->counts, config_.species_area, config_.trap_area);
    } else {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      row->efficiency.eta = row->efficiency.eta_trap = kNaN;
      row->efficiency.eta_species.assign(species_count, kNaN);
      row->efficiency.eta_trap_species.assign(species_count, kNaN);
    }
    row->sorting = sorting_measures(row->counts);
    if (held_since != nullptr) {
      assert(held_since->unwrapped.size() == frame.rods.size());
      std::vector<bool> held(frame.rods.size());
      for (std::size_t i = 0; i < frame.rods.size(); ++i) {
        const double moved = (frame.rods[i].unwrapped - held_since->unwrapped[i]).norm();
        held[i] = inside[i] && moved < config_.held_distance;
      }
      row->held = held_measures(frame, held, row->counts);
    }
    if (config_.at_wall) {
      for (const bool along : inside_flags(frame, config_.at_wall)) row->at_wall += along;
    }
  }
  recent_.push_back(frame);
  if (has_trap()) {
    Positions positions{frame.time, {}};
    positions.unwrapped.reserve(frame.rods.size());
    for (const engine::RodFrame& rod : frame.rods) positions.unwrapped.push_back(rod.unwrapped);
    held_history_.push_back(std::move(positions));
  }
  return row;
}

std::string MetricsObserver::csv_header() const {
  std::string header = "t,eta,eta_trap,n_rods,n_stationary,n_trap,n_stationary_trap,mean_speed";
  for (const std::string& s : config_.species_names) {
    for (const char* column : {"n_stationary_", "n_trap_", "n_stationary_trap_", "eta_",
                               "eta_trap_", "fraction_trap_", "purity_"}) {
      header += ',';
      header += column;
      header += s;
    }
  }
  if (config_.species_names.size() >= 2) header += ",sorting_index";
  if (config_.at_wall) header += ",n_wall";
  if (has_trap()) {
    header += ",n_held_trap";
    for (const std::string& s : config_.species_names) {
      for (const char* column : {"n_held_trap_", "fraction_held_", "purity_held_"}) {
        header += ',';
        header += column;
        header += s;
      }
    }
  }
  return header;
}

std::string MetricsObserver::csv_line(const MetricsRow& row) const {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", row.time);
  std::string line = text;
  append(line, row.efficiency.eta);
  append(line, row.efficiency.eta_trap);
  append(line, row.counts.all.rods);
  append(line, row.counts.all.stationary);
  append(line, row.counts.all.inside);
  append(line, row.counts.all.stationary_inside);
  append(line, row.mean_speed);
  for (std::size_t s = 0; s < config_.species_names.size(); ++s) {
    append(line, row.counts.species[s].stationary);
    append(line, row.counts.species[s].inside);
    append(line, row.counts.species[s].stationary_inside);
    append(line, row.efficiency.eta_species[s]);
    append(line, row.efficiency.eta_trap_species[s]);
    append(line, row.sorting.fraction_inside[s]);
    append(line, row.sorting.purity[s]);
  }
  if (config_.species_names.size() >= 2) append(line, row.sorting.index);
  if (config_.at_wall) append(line, row.at_wall);
  if (has_trap()) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    const auto count = [](int n) { return static_cast<double>(n); };
    append(line, row.held ? count(row.held->all) : kNaN);
    for (std::size_t s = 0; s < config_.species_names.size(); ++s) {
      append(line, row.held ? count(row.held->species[s]) : kNaN);
      append(line, row.held ? row.held->fraction[s] : kNaN);
      append(line, row.held ? row.held->purity[s] : kNaN);
    }
  }
  return line;
}

}  // namespace rodsort::metrics
