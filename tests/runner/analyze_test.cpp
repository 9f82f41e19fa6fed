#include "runner/analyze.hpp"

#include <catch2/catch.hpp>
#include <sstream>

#include "runner/atomic_file.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_command.hpp"
#include "runner/run_directory.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

std::filesystem::path run_tiny(const TempDirectory& directory) {
  RunRequest request;
  request.scenario = RODSORT_SOURCE_DIR "/tests/runner/data/tiny.yaml";
  request.output = directory / "tiny";
  request.options.log = nullptr;
  std::ostringstream err;
  REQUIRE(run_scenario_file(request, err) == kExitOk);
  return request.output;
}

/// metrics.csv as a build before the held count wrote it: every line without its last four
/// columns (n_held_trap and the three of the one species).
std::string without_held_columns(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::size_t end = line.size();
    for (int column = 0; column < 4; ++column) end = line.rfind(',', end - 1);
    out += line.substr(0, end) + "\n";
  }
  return out;
}

}  // namespace

TEST_CASE("analyze brings an older build's metrics.csv up to this build's columns",
          "[runner][analyze]") {
  TempDirectory directory;
  const auto run = run_tiny(directory);
  const std::string live = read_file(run / kMetricsCsvFile);
  const std::string older = without_held_columns(live);
  REQUIRE_THAT(older, Catch::StartsWith("t,eta,"));
  REQUIRE_THAT(older, !Catch::Contains("held"));
  write_file_atomically(run / kMetricsCsvFile, older);
  AnalyzeRequest request;
  request.run_directory = run;
  std::ostringstream err;
  REQUIRE(analyze_run(request, err) == kExitOk);
  CHECK(read_file(run / kMetricsCsvFile) == live);

  // Unfinished, the run resumes by cutting metrics.csv back to a byte count: its file is not
  // rewritten with other columns.
  std::string record = read_file(run / kRunRecordFile);
  const std::size_t at = record.find("\"complete\"");
  REQUIRE(at != std::string::npos);
  record.replace(at, 10, "\"interrupted\"");
  write_file_atomically(run / kRunRecordFile, record);
  write_file_atomically(run / kMetricsCsvFile, older);
  CHECK(analyze_run(request, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("is not complete and its metrics.csv has other columns"));
  CHECK(read_file(run / kMetricsCsvFile) == older);
  request.output = directory / "recomputed.csv";
  REQUIRE(analyze_run(request, err) == kExitOk);
  CHECK(read_file(request.output) == live);
}

TEST_CASE("analyze recomputes the run's own metrics.csv exactly", "[runner][analyze]") {
  TempDirectory directory;
  const auto run = run_tiny(directory);
  const std::string live = read_file(run / kMetricsCsvFile);
  std::filesystem::remove(run / kMetricsCsvFile);
  AnalyzeRequest request;
  request.run_directory = run;
  std::ostringstream err;
  REQUIRE(analyze_run(request, err) == kExitOk);
  CHECK(read_file(run / kMetricsCsvFile) == live);
  CHECK_THAT(err.str(), Catch::Contains("11 frames"));
}

TEST_CASE("analyze measures saved frames with other metrics settings", "[runner][analyze]") {
  TempDirectory directory;
  const auto run = run_tiny(directory);
  AnalyzeRequest request;
  request.run_directory = run;
  request.set_options = {"metrics.stationary_threshold=1000"};
  std::ostringstream err;
  CHECK(analyze_run(request, err) == kExitUsage);  // would overwrite the run's own metrics.csv
  CHECK_THAT(err.str(), Catch::Contains("-o FILE"));

  request.output = directory / "everything-stationary.csv";
  REQUIRE(analyze_run(request, err) == kExitOk);
  const CsvTable table = read_csv(request.output);
  REQUIRE(!table.rows.empty());
  for (const double stationary : table.numbers(*table.column("n_stationary"))) {
    CHECK(stationary == 4);  // every rod is slower than 1000 mm/s
  }

  request.set_options = {"run.duration=1"};
  CHECK(analyze_run(request, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("metrics.* keys only"));
}

TEST_CASE("analyze refuses a directory that is not a run", "[runner][analyze]") {
  TempDirectory directory;
  AnalyzeRequest request;
  request.run_directory = directory.path();
  std::ostringstream err;
  CHECK(analyze_run(request, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("is not a run directory"));
}
