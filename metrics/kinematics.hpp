#pragma once
// Per-rod motion between two frames, from the quantities a camera would see: in-plane positions
// and in-plane orientations. Speeds use unwrapped positions, so that a rod crossing a periodic edge
// between the two frames moves by its real displacement, not by a cell length.

#include <vector>

#include "engine/frame.hpp"

namespace rodsort::metrics {

/// In-plane orientation of a rod: the angle of its thick-to-thin axis projected on the plate,
/// from +x, in (-pi, pi] [rad].
double heading(const engine::RodFrame& rod);

/// Wraps an angle difference into (-pi, pi] [rad].
double wrap_angle(double angle);

/// In-plane speed of every rod, |unwrapped(later) - unwrapped(earlier)| / (t_later - t_earlier)
/// [mm/s]. Both frames hold the same rods in the same order, later.time > earlier.time.
std::vector<double> window_speeds(const engine::Frame& earlier, const engine::Frame& later);

/// Change of the in-plane orientation of each listed rod from `earlier` to `later`, wrapped into
/// (-pi, pi] [rad]: a rod turning from 179° to -179° turned by +2°, not -358°.
std::vector<double> orientation_changes(const engine::Frame& earlier, const engine::Frame& later,
                                        const std::vector<int>& rods);

}  // namespace rodsort::metrics
