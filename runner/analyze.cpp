#include "runner/analyze.hpp"

#include <ostream>

#include "metrics/metrics_observer.hpp"
#include "metrics/rod_frames.hpp"
#include "runner/atomic_file.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_plan.hpp"
#include "runner/run_record.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::runner {

int analyze_run(const AnalyzeRequest& request, std::ostream& err) {
  const std::filesystem::path& directory = request.run_directory;
  for (const std::string& option : request.set_options) {
    if (option.rfind("metrics.", 0) != 0) {
      err << "rodsort: analyze --set takes metrics.* keys only (the frames are already "
             "simulated), got '"
          << option << "'\n";
      return kExitUsage;
    }
  }
  if (!request.set_options.empty() && request.output.empty()) {
    err << "rodsort: analyze --set needs -o FILE, so that the run's own metrics.csv keeps "
           "matching its scenario\n";
    return kExitUsage;
  }
  const std::filesystem::path resolved = directory / kResolvedScenarioFile;
  const std::filesystem::path rods = metrics::rod_frames_file(directory);
  if (!std::filesystem::exists(resolved) || rods.empty()) {
    err << "rodsort: " << directory.string() << " is not a run directory (no "
        << kResolvedScenarioFile << " and " << kRodsCsvFile << " or " << kRodsH5mdFile << ")\n";
    return kExitUsage;
  }
  const std::filesystem::path output =
      request.output.empty() ? directory / kMetricsCsvFile : request.output;
  const auto record = read_run_record(directory);
  if (output == directory / kMetricsCsvFile && record && record->status == RunStatus::kRunning) {
    err << "rodsort: " << directory.string()
        << " says it is still running; analyze it when it has stopped (or write elsewhere "
           "with -o)\n";
    return kExitUsage;
  }

  const scenarios::LoadResult loaded =
      scenarios::load_scenario_with_options(resolved, request.set_options);
  // The run said the scenario's own warnings when it started; only those of --set are new.
  std::vector<scenarios::Diagnostic> news;
  for (const scenarios::Diagnostic& diagnostic : loaded.diagnostics) {
    if (diagnostic.severity == scenarios::Severity::error ||
        diagnostic.where.source.rfind("--set", 0) == 0) {
      news.push_back(diagnostic);
    }
  }
  err << scenarios::format_diagnostics(news);
  if (!loaded.ok()) return request.set_options.empty() ? kExitFailure : kExitUsage;
  metrics::MetricsObserver observer(metrics_config(*loaded.scenario));

  const std::unique_ptr<metrics::RodFrameReader> source =
      metrics::open_rod_frames(rods, observer.config().species_names);
  metrics::RodFrameReader& reader = *source;
  // The rows of metrics.csv are cut back to the checkpoint's byte count when a run resumes: an
  // unfinished run's file is rewritten only with the columns it has.
  if (output == directory / kMetricsCsvFile && record && record->status != RunStatus::kComplete &&
      metrics_csv_header(directory) != observer.csv_header()) {
    err << "rodsort: " << directory.string()
        << " is not complete and its metrics.csv has other columns than this build writes; "
           "rewritten, it could not be resumed: finish the run first, or write elsewhere with "
           "-o\n";
    return kExitUsage;
  }
  std::string text = observer.csv_header() + "\n";
  engine::Frame frame;
  std::size_t frames = 0;
  std::size_t rows = 0;
  while (reader.next(frame)) {
    ++frames;
    if (const auto row = observer.observe(frame)) {
      text += observer.csv_line(*row) + "\n";
      ++rows;
    }
  }
  if (!reader.error().empty()) {
    err << "rodsort: " << reader.error() << '\n';
    return kExitFailure;
  }
  if (!reader.warning().empty()) err << "rodsort: warning: " << reader.warning() << '\n';
  write_file_atomically(output, text);
  err << "rodsort: " << frames << " frames of " << rods.string() << " -> " << rows << " rows of "
      << output.string() << '\n';
  return kExitOk;
}

}  // namespace rodsort::runner
