#pragma once
// `rodsort analyze RUN_DIR`: recomputes metrics.csv from rods.csv with the metrics layer, the same
// way the live run computes it. With `--set metrics.window=...` (or the stationary threshold), it
// measures the saved frames with other settings, into another file.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsort::runner {

struct AnalyzeRequest {
  std::filesystem::path run_directory;
  std::vector<std::string> set_options;  ///< metrics.* keys only
  std::filesystem::path output;          ///< default: RUN_DIR/metrics.csv; required with --set
};

int analyze_run(const AnalyzeRequest& request, std::ostream& err);

}  // namespace rodsort::runner
