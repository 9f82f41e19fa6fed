#pragma once
// `rodsort summarize SWEEP_DIR`: the sweep's points with their time-averaged eta (the mean over the
// last half of each run), refreshed from the points' metrics.csv, and, when the sweep is over the
// trap's angle, theta_c: the angle where eta falls through half its low-angle plateau (the metrics
// layer's critical_angle), for each combination of the other swept keys, seeds averaged.

#include <filesystem>
#include <iosfwd>

namespace rodsort::runner {

/// Prints the table on `out`, rewrites sweep.csv, and writes critical_angle.csv when the angle was
/// swept.
int summarize_sweep(const std::filesystem::path& sweep_directory, std::ostream& out,
                    std::ostream& err);

}  // namespace rodsort::runner
