#include <filesystem>
#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "app/number_checks.hpp"
#include "metrics/rod_frames.hpp"
#include "render/run_render.hpp"
#include "render/scene.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_plan.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::app {
namespace {

int render_run_directory(const render::RenderRequest& request) {
  const std::filesystem::path& directory = request.run_directory;
  const std::filesystem::path resolved = directory / runner::kResolvedScenarioFile;
  if (!std::filesystem::exists(resolved) || metrics::rod_frames_file(directory).empty()) {
    std::cerr << "rodsort: " << directory.string() << " is not a run directory (no "
              << runner::kResolvedScenarioFile << " and " << runner::kRodsCsvFile << " or "
              << runner::kRodsH5mdFile << ")\n";
    return runner::kExitUsage;
  }
  const scenarios::LoadResult loaded = scenarios::load_scenario(resolved);
  std::cerr << scenarios::format_diagnostics(loaded.diagnostics, false);
  if (!loaded.ok()) return runner::kExitFailure;
  // The run's own metrics settings, so that the marks and eta match its metrics.csv.
  const render::RenderResult result =
      render::render_run(request, render::scenario_scene(*loaded.scenario),
                         runner::metrics_config(*loaded.scenario), &std::cerr);
  for (const std::string& note : result.notes) std::cerr << "rodsort: note: " << note << '\n';
  for (const std::filesystem::path& path : result.written) std::cout << path.string() << '\n';
  return runner::kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto request = std::make_shared<render::RenderRequest>();
  CLI::App* render = app.add_subcommand(
      "render",
      "Draw top views of a run's cell as PNG (and SVG): rods coloured by species, stationary "
      "rods marked, the trap, time and eta; --movie makes an MP4 with ffmpeg");
  render->add_option("RUN_DIR", request->run_directory, "Run directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  render->add_option("--at", request->times,
                     "Times [s] to draw, the nearest frame each (default: the first and the last "
                     "frame); several may follow one --at");
  render->add_flag("--svg", request->svg, "Also write each picture as SVG");
  render->add_flag(
      "--movie", request->movie,
      "Also make movie.mp4 of every frame in the output directory (-o; default RUN_DIR/render; "
      "needs ffmpeg)");
  render->add_option("--every", request->movie_every, "Movie: take every N-th frame (default 1)")
      ->check(positive_number());
  render->add_option("--fps", request->movie_fps, "Movie: frames per second (default 20)")
      ->check(CLI::Range(1.0, 240.0));
  render
      ->add_option("--width", request->view.width_px,
                   "Picture width in pixels (default 1000); the height follows the cell")
      ->check(CLI::Range(render::kMinimumWidth, 8000));
  render->add_flag(
      "--no-header", [request](std::int64_t) { request->view.header = false; },
      "Leave out the line of name, time and eta above the cell (for a figure)");
  render->add_option("-o,--output", request->output,
                     "Directory for the pictures (default: RUN_DIR/render)");
  return {render, [request] { return render_run_directory(*request); }};
}

}  // namespace rodsort::app
