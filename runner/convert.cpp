#include "runner/convert.hpp"

#include <cmath>
#include <memory>
#include <ostream>

#include "metrics/rod_frames.hpp"
#include "metrics/rods_h5md.hpp"
#include "runner/exit_code.hpp"
#include "runner/frame_file.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_plan.hpp"
#include "runner/run_record.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::runner {

int convert_run(const ConvertRequest& request, std::ostream& err) {
  const std::filesystem::path& directory = request.run_directory;
  const std::filesystem::path resolved = directory / kResolvedScenarioFile;
  const std::filesystem::path rods = directory / kRodsCsvFile;
  const std::filesystem::path h5md = directory / kRodsH5mdFile;
  if (!std::filesystem::exists(resolved) || !std::filesystem::exists(rods)) {
    err << "rodsort: " << directory.string()
        << " is not a run directory with frames to convert (no " << kResolvedScenarioFile << " and "
        << kRodsCsvFile << ")\n";
    return kExitUsage;
  }
  if (std::filesystem::exists(h5md)) {
    err << "rodsort: " << h5md.string() << " already exists; remove it to convert again\n";
    return kExitUsage;
  }
  const auto record = read_run_record(directory);
  if (record && record->status == RunStatus::kRunning) {
    err << "rodsort: " << directory.string()
        << " says it is still running; convert it when it has stopped\n";
    return kExitUsage;
  }
  const scenarios::LoadResult loaded = scenarios::load_scenario(resolved);
  if (!loaded.ok()) {
    err << scenarios::format_diagnostics(loaded.diagnostics);
    return kExitFailure;
  }
  RunPlan plan = make_run_plan(*loaded.scenario);
  plan.h5md_precision =
      request.double_precision ? metrics::H5mdPrecision::full : metrics::H5mdPrecision::single;

  // Written under another name and renamed when complete: a conversion stopped half-way leaves
  // no rods.h5 that could be taken for the run's frames.
  const std::filesystem::path partial = directory / (std::string(kRodsH5mdFile) + ".partial");
  const std::unique_ptr<metrics::RodFrameReader> source =
      metrics::open_rod_frames(rods, plan.metrics.species_names);
  metrics::RodFrameReader& reader = *source;
  std::size_t frames = 0;
  {
    metrics::RodsH5mdWriter writer(partial, h5md_layout(plan));
    engine::Frame frame;
    while (reader.next(frame)) {
      writer.write(frame, std::llround(frame.time / plan.model.dt));
      ++frames;
    }
    writer.commit();
  }
  if (!reader.error().empty()) {
    std::filesystem::remove(partial);
    err << "rodsort: " << reader.error() << '\n';
    return kExitFailure;
  }
  if (!reader.warning().empty()) err << "rodsort: warning: " << reader.warning() << '\n';
  std::filesystem::rename(partial, h5md);
  err << "rodsort: " << frames << " frames of " << rods.string() << " ("
      << std::filesystem::file_size(rods) / 1000000.0 << " MB) -> " << h5md.string() << " ("
      << std::filesystem::file_size(h5md) / 1000000.0 << " MB)\n";
  return kExitOk;
}

}  // namespace rodsort::runner
