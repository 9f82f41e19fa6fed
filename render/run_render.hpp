#pragma once
// `rodsort render`: pictures of a finished (or stopped) run from its directory. Frames come from
// rods.csv, read one at a time so that a long run need not fit in memory; each goes through the
// metrics layer's observer, configured as the run's own, so that the stationary rods marked and
// the eta written on a picture are those of the same frame's row in metrics.csv.
//
// Stills go to RUN_DIR/render/frame-t<time>.png (and .svg); a movie streams every n-th frame to
// ffmpeg, which writes RUN_DIR/render/movie.mp4 (render/movie_encoder.hpp).

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "metrics/metrics_observer.hpp"
#include "render/scene.hpp"
#include "render/top_view.hpp"

namespace rodsort::render {

struct RenderRequest {
  std::filesystem::path run_directory;
  std::filesystem::path output;  ///< empty: run_directory / "render"
  /// Draws the frame nearest each time [s]; empty: the first and the last frame.
  std::vector<double> times;
  bool svg = false;    ///< an SVG beside each PNG still
  bool movie = false;  ///< also a movie of every `movie_every`-th frame
  int movie_every = 1;
  double movie_fps = 20.0;  ///< frames per second of the movie
  ViewOptions view;
};

struct RenderResult {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> notes;  ///< things the user should know: a time beyond the run, ...
};

/// The still's file name for a frame at `time` [s], without extension: "frame-t12.6".
std::string still_name(double time);

/// Renders the run in request.run_directory, whose scene and metrics configuration the caller
/// took from its scenario.resolved.yaml. `progress`, when not null, gets a line now and then
/// while a movie renders. Throws std::runtime_error naming the file or program on a broken run
/// directory, an I/O error, a missing or failing ffmpeg.
RenderResult render_run(const RenderRequest& request, const Scene& scene,
                        const metrics::MetricsConfig& metrics, std::ostream* progress = nullptr);

}  // namespace rodsort::render
