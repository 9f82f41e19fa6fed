#include "metrics/trapping.hpp"

#include <cassert>

namespace rodsort::metrics {

std::vector<bool> stationary_flags(const std::vector<double>& speeds, double threshold) {
  std::vector<bool> flags(speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) flags[i] = speeds[i] < threshold;
  return flags;
}

std::vector<bool> inside_flags(const engine::Frame& frame, const InsidePredicate& inside) {
  std::vector<bool> flags(frame.rods.size());
  for (std::size_t i = 0; i < flags.size(); ++i) flags[i] = inside(frame.rods[i].position);
  return flags;
}

TrappingCounts count_trapping(const engine::Frame& frame, const std::vector<bool>& stationary,
                              const std::vector<bool>& inside, int species_count) {
  assert(stationary.size() == frame.rods.size() && inside.size() == frame.rods.size());
  TrappingCounts counts;
  counts.species.resize(species_count);
  for (std::size_t i = 0; i < frame.rods.size(); ++i) {
    const int species = frame.rods[i].species;
    assert(species >= 0 && species < species_count);
    for (Counts* c : {&counts.all, &counts.species[species]}) {
      c->rods += 1;
      c->stationary += stationary[i] ? 1 : 0;
      c->inside += inside[i] ? 1 : 0;
      c->stationary_inside += stationary[i] && inside[i] ? 1 : 0;
    }
  }
  return counts;
}

Efficiency trapping_efficiency(const TrappingCounts& counts,
                               const std::vector<double>& species_area, double trap_area) {
  assert(species_area.size() == counts.species.size());
  assert(trap_area > 0.0);
  Efficiency efficiency;
  for (std::size_t s = 0; s < counts.species.size(); ++s) {
    const double eta = counts.species[s].stationary * species_area[s] / trap_area;
    const double eta_trap = counts.species[s].stationary_inside * species_area[s] / trap_area;
    efficiency.eta_species.push_back(eta);
    efficiency.eta_trap_species.push_back(eta_trap);
    efficiency.eta += eta;
    efficiency.eta_trap += eta_trap;
  }
  return efficiency;
}

}  // namespace rodsort::metrics
