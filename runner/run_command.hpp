#pragma once
// `rodsort run` and `rodsort validate`: from a scenario file (and --set overrides) to a run
// directory, or to the resolved scenario on stdout. Each returns the process's exit status
// (runner/exit_code.hpp) and writes its messages to `err`.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "runner/run.hpp"

namespace rodsort::runner {

struct RunRequest {
  std::filesystem::path scenario;        ///< the scenario file
  std::vector<std::string> set_options;  ///< "key.path=value", applied in order
  std::filesystem::path output;          ///< the run directory; empty: runs/<scenario name>
  bool force = false;                    ///< replace a run already in `output`
  RunOptions options;
};

/// Loads, checks and runs a scenario. A refused scenario writes nothing and returns kExitUsage;
/// so does an output directory that already holds a run, unless `force`.
int run_scenario_file(const RunRequest& request, std::ostream& err);

/// Continues the run in `directory` from its checkpoint (a complete run is left as it is). With
/// `duration` [s], the run, complete or not, is continued to that simulated time instead of its
/// own: scenario.resolved.yaml is rewritten with the new run.duration, nothing else changes, and
/// the files come out as those of a run started with that duration. A duration the run has
/// already passed, or one the scenario's checks refuse, is refused (kExitUsage).
int resume_run_directory(const std::filesystem::path& directory, const RunOptions& options,
                         std::ostream& err, std::optional<double> duration = std::nullopt);

/// Prints the resolved scenario on `out`, or its errors on `err` (kExitUsage).
int validate_scenario_file(const std::filesystem::path& scenario,
                           const std::vector<std::string>& set_options, std::ostream& out,
                           std::ostream& err);

/// The directory a run of scenario `name` goes to when no -o is given.
std::filesystem::path default_run_directory(const std::string& name);

}  // namespace rodsort::runner
