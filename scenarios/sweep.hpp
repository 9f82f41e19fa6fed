#pragma once
// A sweep file: one base scenario and a grid of values for some of its keys. Each point of the grid
// is the base with `--set`-like overrides, so a point goes through exactly the checks a scenario
// does, and its errors name the line of the sweep file that set the bad value. Running the points
// is the runner's business; this file only reads, expands and checks them.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/diagnostic.hpp"
#include "scenarios/override.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/source_node.hpp"

namespace rodsort::scenarios {

struct SweepPoint {
  std::size_t index = 0;  ///< position in the grid, the first axis varying slowest
  std::string name;       ///< unique in the sweep, fit for a directory: "angle-120_seed-1"
  std::vector<Override> overrides;  ///< one per swept key, in axis order
};

struct Sweep {
  std::string name;
  std::filesystem::path file;       ///< the sweep file
  std::filesystem::path base_file;  ///< the base scenario's file; empty when inline
  SourceNode base;                  ///< the base scenario, before overrides
  std::vector<Override> fixed;      ///< the `set` values, applied to every point before its own
  std::vector<std::string> keys;    ///< the swept key paths, in axis order
  std::vector<SweepPoint> points;
};

struct SweepLoadResult {
  std::optional<Sweep> sweep;           ///< absent when there is any error
  std::vector<Diagnostic> diagnostics;  ///< of the sweep file and of every point

  bool ok() const { return sweep.has_value(); }
};

/// Reads a sweep file and expands its grid. With `check_points`, every point is also loaded as a
/// scenario (rods placed, nothing run) and its problems reported, each once. `set_options`
/// ("key.path=value", as `rodsort sweep --set` takes them) are applied to every point after the
/// file's own `set` values; a swept key cannot be set.
SweepLoadResult load_sweep(const std::filesystem::path& path, bool check_points = true,
                           const std::vector<std::string>& set_options = {});

/// The scenario of one point: the base, the sweep's `set` values, then the point's; named
/// "<base name>_<point name>".
LoadResult load_sweep_point(const Sweep& sweep, const SweepPoint& point);

}  // namespace rodsort::scenarios
