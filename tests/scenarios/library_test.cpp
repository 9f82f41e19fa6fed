// The scenario library (scenarios/*.yaml, scenarios/library/*.yaml) must load without errors: a
// user's first contact with rodsort is one of these files.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scenario.hpp"
#include "scenarios/sweep.hpp"

namespace fs = std::filesystem;
using namespace rodsort::scenarios;

namespace {

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<fs::path> library_files() {
  std::vector<fs::path> files;
  const fs::path root = fs::path(RODSORT_SOURCE_DIR) / "scenarios";
  for (const fs::path& folder : {root, root / "library"}) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("every scenario and sweep of the library loads", "[library]") {
  const std::vector<fs::path> files = library_files();
  REQUIRE(files.size() >= 10);
  for (const fs::path& file : files) {
    CAPTURE(file.string());
    const std::string text = read(file);
    const bool is_sweep = text.find("\ngrid:") != std::string::npos;
    const auto diagnostics =
        is_sweep ? load_sweep(file).diagnostics : load_scenario(file).diagnostics;
    INFO(format_diagnostics(diagnostics));
    CHECK(diagnostics.empty());
    // Each file opens with a comment that says what it is, and a figure file names its figure.
    CHECK(text.rfind("# ", 0) == 0);
    if (file.filename().string().rfind("fig", 0) == 0) {
      CHECK(text.find("# Fig. ") == 0);
    }
  }
}

TEST_CASE("the quickstart is small enough for a few minutes on one core", "[library]") {
  const LoadResult result =
      load_scenario(fs::path(RODSORT_SOURCE_DIR) / "scenarios/quickstart.yaml");
  REQUIRE(result.ok());
  const Scenario& scenario = *result.scenario;
  // At about 3 us per rod and step (docs: the straightforward Bullet build), rods x steps below
  // 1e8 is at most five minutes.
  const double rod_steps = static_cast<double>(scenario.model.rods.size()) * scenario.run.steps;
  CHECK(rod_steps < 1.0e8);
  CHECK(scenario.model.rods.size() >= 50);
  REQUIRE(scenario.trap != nullptr);
}
