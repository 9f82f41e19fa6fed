// `rodsort render` and `rodsort plot` as a user meets them: a small scenario run with the rodsort
// program, then drawn and plotted from its run directory.

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "render/external_program.hpp"
#include "render/plot_script.hpp"
#include "render/png_pixels.hpp"
#include "render/scene.hpp"
#include "support/temp_directory.hpp"
#include "render/top_view.hpp"
#include "scenarios/scenario.hpp"

using namespace rodsort;
using render::testing::PngPixels;
using rodsort::testing::TempDirectory;

namespace {

const std::string kRodsort = RODSORT_BINARY_DIR "/rodsort";
const std::string kSmallRun = RODSORT_SOURCE_DIR "/tests/render/data/small-run.yaml";

render::ProgramOutput run_rodsort(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), kRodsort);
  return render::run_program(arguments);
}

/// Runs the small scenario into `directory`.
void run_small(const std::filesystem::path& directory) {
  const render::ProgramOutput run = run_rodsort({"run", kSmallRun, "-o", directory.string(), "-q"});
  INFO(run.output);
  REQUIRE(run.exit_status == 0);
}

}  // namespace

TEST_CASE("rodsort render draws a run's frame: the right size, with the rods and the trap",
          "[render][cli]") {
  const TempDirectory scratch;
  const std::filesystem::path run = scratch / "run";
  run_small(run);
  const render::ProgramOutput drawn =
      run_rodsort({"render", run.string(), "--at", "0.35", "--svg", "--width", "500"});
  INFO(drawn.output);
  REQUIRE(drawn.exit_status == 0);
  const std::filesystem::path png = run / "render" / "frame-t0.35.png";
  CHECK_THAT(drawn.output, Catch::Contains(png.string()));
  CHECK(std::filesystem::is_regular_file(run / "render" / "frame-t0.35.svg"));

  const scenarios::LoadResult loaded = scenarios::load_scenario(run / "scenario.resolved.yaml");
  REQUIRE(loaded.ok());
  const render::Scene scene = render::scenario_scene(*loaded.scenario);
  const render::ViewLayout layout = render::layout_view(scene, {500});
  const PngPixels pixels(png);
  REQUIRE(pixels.width() == layout.width);
  REQUIRE(pixels.height() == layout.height);
  const int x0 = static_cast<int>(std::ceil(layout.cell_left));
  const int y0 = static_cast<int>(std::ceil(layout.cell_top));
  const int x1 = static_cast<int>(layout.cell_left + layout.cell_width);
  const int y1 = static_cast<int>(layout.cell_top + layout.cell_height);
  // Six rods, each covering its projected area less its outline (and a dot when stationary).
  const double rods_px = 6.0 * scene.species[0].shape.projected_area * layout.scale * layout.scale;
  const int rod_pixels = pixels.count(render::species_colour(0), x0, y0, x1, y1);
  CHECK(rod_pixels > 0.6 * rods_px);
  CHECK(rod_pixels < 1.0 * rods_px);
  CHECK(pixels.count(render::kWallColour, x0, y0, x1, y1) > 100);
}

TEST_CASE("rodsort render and plot refuse a directory that holds no run", "[render][cli]") {
  const TempDirectory scratch;
  const render::ProgramOutput drawn = run_rodsort({"render", scratch.path().string()});
  CHECK(drawn.exit_status == 2);
  CHECK_THAT(drawn.output, Catch::Contains("is not a run directory"));
  const render::ProgramOutput plotted = run_rodsort({"plot", scratch.path().string()});
  CHECK(plotted.exit_status == 2);
  CHECK_THAT(plotted.output, Catch::Contains("neither a run directory"));
}

TEST_CASE("rodsort plot draws a run's curves, and rodsort render --movie its MP4",
          "[render][cli]") {
  const render::PythonLookup python = render::find_plot_python();
  if (!python.python) FAIL(python.error);
  if (!render::find_program("ffmpeg")) {
    FAIL("ffmpeg is not on PATH: install Debian's ffmpeg (scripts/install-deps does)");
  }
  const TempDirectory scratch;
  const std::filesystem::path run = scratch / "run";
  run_small(run);
  const render::ProgramOutput plotted = run_rodsort({"plot", run.string(), "--format", "png"});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  for (const char* name : {"eta.png", "population.png", "dtheta.png"}) {
    CHECK(std::filesystem::is_regular_file(run / "plots" / name));
  }
  const render::ProgramOutput movie = run_rodsort(
      {"render", run.string(), "--movie", "--width", "300", "-o", (scratch / "pictures").string()});
  INFO(movie.output);
  REQUIRE(movie.exit_status == 0);
  CHECK(std::filesystem::file_size(scratch / "pictures" / "movie.mp4") > 1000);
}
