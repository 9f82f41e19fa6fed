#include "render/run_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "metrics/rod_frames.hpp"
#include "render/external_program.hpp"
#include "render/movie_encoder.hpp"

namespace rodsort::render {
namespace {

constexpr const char* kMovieLog = "movie.log";
constexpr const char* kMovieFile = "movie.mp4";

std::string format_time(double time) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", time);
  return text;
}

FrameMarks marks_of(const std::optional<metrics::MetricsRow>& row) {
  FrameMarks marks;
  if (!row) return marks;
  marks.stationary = row->stationary;
  if (!std::isnan(row->efficiency.eta)) marks.eta = row->efficiency.eta;
  if (!std::isnan(row->efficiency.eta_trap)) marks.eta_trap = row->efficiency.eta_trap;
  return marks;
}

struct MarkedFrame {
  long index = -1;  ///< in the run, from 0
  engine::Frame frame;
  FrameMarks marks;
};

/// A requested time and whether it has been drawn.
struct Target {
  double time;
  bool done = false;
};

void make_directories(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw std::runtime_error("cannot create " + directory.string() + ": " + error.message());
  }
}

/// Draws stills, once per frame however many requested times pick it.
class StillWriter {
 public:
  StillWriter(const RenderRequest& request, const Scene& scene, const ViewLayout& layout,
              std::filesystem::path directory, RenderResult& result)
      : request_(request),
        scene_(scene),
        layout_(layout),
        directory_(std::move(directory)),
        result_(result) {}

  void write(const MarkedFrame& marked) {
    if (std::find(drawn_.begin(), drawn_.end(), marked.index) != drawn_.end()) return;
    drawn_.push_back(marked.index);
    const std::string name = still_name(marked.frame.time);
    const std::filesystem::path png = directory_ / (name + ".png");
    write_png(png, layout_, scene_, marked.frame, marked.marks);
    result_.written.push_back(png);
    if (request_.svg) {
      const std::filesystem::path svg = directory_ / (name + ".svg");
      write_svg(svg, layout_, scene_, marked.frame, marked.marks);
      result_.written.push_back(svg);
    }
  }

 private:
  const RenderRequest& request_;
  const Scene& scene_;
  const ViewLayout& layout_;
  std::filesystem::path directory_;
  RenderResult& result_;
  std::vector<long> drawn_;
};

}  // namespace

std::string still_name(double time) { return "frame-t" + format_time(time); }

RenderResult render_run(const RenderRequest& request, const Scene& scene,
                        const metrics::MetricsConfig& metrics, std::ostream* progress) {
  RenderResult result;
  const std::filesystem::path output =
      request.output.empty() ? request.run_directory / "render" : request.output;
  std::optional<std::filesystem::path> ffmpeg;
  if (request.movie) {
    ffmpeg = find_program("ffmpeg");
    if (!ffmpeg) {
      throw std::runtime_error(
          "--movie needs ffmpeg, which is not on PATH: install it (Debian's ffmpeg; "
          "scripts/install-deps does), or render stills without --movie");
    }
  }
  const std::filesystem::path rods_path = metrics::rod_frames_file(request.run_directory);
  if (rods_path.empty()) {
    throw std::runtime_error(request.run_directory.string() + " holds no rods.csv or rods.h5");
  }
  const std::unique_ptr<metrics::RodFrameReader> frames =
      metrics::open_rod_frames(rods_path, metrics.species_names);
  metrics::RodFrameReader& reader = *frames;
  metrics::MetricsObserver observer(metrics);

  make_directories(output);
  const ViewLayout layout = layout_view(scene, request.view);
  StillWriter stills(request, scene, layout, output, result);

  const bool first_and_last = request.times.empty();
  std::vector<Target> targets;
  if (first_and_last) {
    targets = {{-std::numeric_limits<double>::infinity()}};
  } else {
    for (const double time : request.times) targets.push_back({time});
    std::sort(targets.begin(), targets.end(),
              [](const Target& a, const Target& b) { return a.time < b.time; });
  }

  using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
  SurfacePtr movie_surface(nullptr, &cairo_surface_destroy);
  std::optional<MovieEncoder> encoder;
  const std::filesystem::path movie = output / kMovieFile;
  if (request.movie) {
    movie_surface.reset(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height));
    encoder.emplace(*ffmpeg, movie, layout.width, layout.height, request.movie_fps,
                    output / kMovieLog);
  }

  std::optional<MarkedFrame> previous;
  double last_interval = 0.0;  ///< between the last two frames [s]
  MarkedFrame current;
  long index = 0;
  while (reader.next(current.frame)) {
    current.index = index++;
    current.marks = marks_of(observer.observe(current.frame));
    for (Target& target : targets) {
      if (target.done || current.frame.time < target.time) continue;
      // The nearer of this frame and the previous one; a tie goes to the earlier.
      const bool previous_nearer =
          previous && target.time - previous->frame.time <= current.frame.time - target.time;
      stills.write(previous_nearer ? *previous : current);
      target.done = true;
    }
    if (encoder && current.index % request.movie_every == 0) {
      cairo_t* cairo = cairo_create(movie_surface.get());
      draw_top_view(cairo, layout, scene, current.frame, current.marks);
      cairo_destroy(cairo);
      encoder->add(movie_surface.get());
      if (progress != nullptr && encoder->frames() % 500 == 0) {
        *progress << "render: " << encoder->frames()
                  << " movie frames (t = " << format_time(current.frame.time) << " s)\n";
      }
    }
    if (previous) last_interval = current.frame.time - previous->frame.time;
    previous = current;
  }
  if (!reader.error().empty()) throw std::runtime_error(reader.error());
  if (!reader.warning().empty()) result.notes.push_back(reader.warning());
  if (!previous) throw std::runtime_error(rods_path.string() + ": no frame to draw");

  for (const Target& target : targets) {
    if (target.done) continue;
    // Within half a frame interval past the last frame, the last frame is the nearest one.
    if (!first_and_last && target.time > previous->frame.time + 0.5 * last_interval) {
      result.notes.push_back("t = " + format_time(target.time) +
                             " s is after the run's last frame; drew that frame (t = " +
                             format_time(previous->frame.time) + " s)");
    }
    stills.write(*previous);
  }
  if (first_and_last) stills.write(*previous);

  if (encoder) {
    encoder->finish();
    result.written.push_back(movie);
  }
  return result;
}

}  // namespace rodsort::render
