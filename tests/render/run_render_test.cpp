#include "render/run_render.hpp"

#include <stdlib.h>

#include <catch2/catch.hpp>
#include <string>

#include "render/external_program.hpp"
#include "render/png_pixels.hpp"
#include "render/synthetic_run.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort;
using render::testing::kFrameInterval;
using render::testing::PngPixels;
using rodsort::testing::TempDirectory;
using render::testing::TestScene;
using render::testing::write_test_run;

namespace {

/// Sets an environment variable for the length of a scope.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    const char* old = std::getenv(name);
    if (old != nullptr) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

bool is_file(const std::filesystem::path& path) { return std::filesystem::is_regular_file(path); }

}  // namespace

TEST_CASE("Render draws the first and the last frame of a run by default", "[render][run]") {
  const TestScene test;
  const TempDirectory run;
  write_test_run(run.path(), test, 6);
  render::RenderRequest request;
  request.run_directory = run.path();
  request.view.width_px = 400;
  const render::RenderResult result =
      render::render_run(request, test.scene, test.metrics_config());
  CHECK(result.notes.empty());
  REQUIRE(result.written.size() == 2);
  CHECK(result.written[0] == run / "render" / "frame-t0.png");
  CHECK(result.written[1] == run / "render" / "frame-t0.35.png");
  CHECK(is_file(result.written[0]));
  CHECK(is_file(result.written[1]));
}

TEST_CASE("Render draws the frames nearest the times asked, marking stationary rods",
          "[render][run]") {
  const TestScene test;
  const TempDirectory run;
  write_test_run(run.path(), test, 6);
  render::RenderRequest request;
  request.run_directory = run.path();
  request.output = run / "pictures";
  request.times = {0.15, 0.1, 9.0, 0.14, 0.38};
  request.svg = true;
  request.view.width_px = 400;
  const render::RenderResult result =
      render::render_run(request, test.scene, test.metrics_config());
  // 0.1 -> 0.07 (0.03 away, 0.14 is 0.04 away); 0.14 and 0.15 -> 0.14, drawn once; 0.38 -> the
  // last frame at 0.35 s, its nearest; 9 -> the last frame too, with a note. Each still has its
  // SVG.
  REQUIRE(result.written.size() == 6);
  CHECK(result.written[0] == run / "pictures" / "frame-t0.07.png");
  CHECK(result.written[1] == run / "pictures" / "frame-t0.07.svg");
  CHECK(result.written[2] == run / "pictures" / "frame-t0.14.png");
  CHECK(result.written[4] == run / "pictures" / "frame-t0.35.png");
  REQUIRE(result.notes.size() == 1);
  CHECK_THAT(result.notes[0],
             Catch::Contains("t = 9 s is after the run's last frame") && Catch::Contains("0.35"));

  // At 0.14 s rods 2 and 3 have rested for a window: the metrics layer calls them stationary,
  // and the picture carries a dot on each; moving rod 0 has none.
  const render::ViewLayout layout = render::layout_view(test.scene, request.view);
  const PngPixels png(run / "pictures" / "frame-t0.14.png");
  const engine::Frame frame = render::testing::test_frame(test.trap, 0.14);
  const auto pixel_at = [&](const engine::RodFrame& rod) {
    const Eigen::Vector2d at = layout.to_pixels(rod.position);
    return std::pair<int, int>(static_cast<int>(at.x()), static_cast<int>(at.y()));
  };
  const auto [x3, y3] = pixel_at(frame.rods[3]);
  CHECK(png.has_colour(x3, y3, render::kStationaryColour));
  const auto [x0, y0] = pixel_at(frame.rods[0]);
  CHECK(png.has_colour(x0, y0, render::species_colour(0)));
}

TEST_CASE("Render refuses a run directory without rods.csv or rods.h5, naming both",
          "[render][run]") {
  const TestScene test;
  const TempDirectory run;
  render::RenderRequest request;
  request.run_directory = run.path();
  CHECK_THROWS_WITH(
      render::render_run(request, test.scene, test.metrics_config()),
      Catch::Contains(run.path().string()) && Catch::Contains("no rods.csv or rods.h5"));
}

TEST_CASE("Render --movie encodes an MP4 with ffmpeg", "[render][run][movie]") {
  if (!render::find_program("ffmpeg")) {
    FAIL("ffmpeg is not on PATH: install Debian's ffmpeg (scripts/install-deps does)");
  }
  const TestScene test;
  const TempDirectory run;
  write_test_run(run.path(), test, 8);
  render::RenderRequest request;
  request.run_directory = run.path();
  request.times = {0.0};
  request.movie = true;
  request.movie_every = 2;
  request.view.width_px = 300;
  const render::RenderResult result =
      render::render_run(request, test.scene, test.metrics_config());
  REQUIRE(result.written.size() == 2);
  const std::filesystem::path movie = run / "render" / "movie.mp4";
  CHECK(result.written[1] == movie);
  REQUIRE(is_file(movie));
  // Frames 0, 2, 4 and 6 of the eight, at the pictures' size, in the pixel format players need.
  const std::optional<std::filesystem::path> ffprobe = render::find_program("ffprobe");
  REQUIRE(ffprobe);
  const render::ProgramOutput probe =
      render::run_program({ffprobe->string(), "-v", "error", "-count_frames", "-select_streams",
                           "v:0", "-show_entries", "stream=width,height,pix_fmt,nb_read_frames",
                           "-of", "default=noprint_wrappers=1", movie.string()});
  INFO(probe.output);
  REQUIRE(probe.exit_status == 0);
  const render::ViewLayout layout = render::layout_view(test.scene, request.view);
  CHECK_THAT(probe.output, Catch::Contains("width=" + std::to_string(layout.width) + "\n") &&
                               Catch::Contains("height=" + std::to_string(layout.height) + "\n") &&
                               Catch::Contains("pix_fmt=yuv420p") &&
                               Catch::Contains("nb_read_frames=4"));
  CHECK_FALSE(std::filesystem::exists(run / "render" / "movie.log"));
}

TEST_CASE("Render --movie without ffmpeg says how to get it", "[render][run][movie]") {
  const TestScene test;
  const TempDirectory run;
  write_test_run(run.path(), test, 3);
  const ScopedEnvironment no_path("PATH", run.path().string());
  render::RenderRequest request;
  request.run_directory = run.path();
  request.movie = true;
  CHECK_THROWS_WITH(render::render_run(request, test.scene, test.metrics_config()),
                    Catch::Contains("needs ffmpeg") && Catch::Contains("install"));
  CHECK_FALSE(std::filesystem::exists(run / "render"));
}
