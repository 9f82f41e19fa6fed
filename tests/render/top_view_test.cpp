#include "render/top_view.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "render/png_pixels.hpp"
#include "render/synthetic_run.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort;
using render::testing::kBoxX;
using render::testing::kBoxY;
using render::testing::PngPixels;
using rodsort::testing::TempDirectory;
using render::testing::test_frame;
using render::testing::test_marks;
using render::testing::TestScene;

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("A top view has even dimensions and the cell's aspect ratio", "[render][top_view]") {
  const TestScene test;
  const render::ViewLayout layout = render::layout_view(test.scene, {601});
  CHECK(layout.width == 602);
  CHECK(layout.height % 2 == 0);
  CHECK(layout.cell_width / layout.cell_height == Approx(kBoxX / kBoxY));
  CHECK(layout.scale == Approx(layout.cell_width / kBoxX));
  CHECK(layout.cell_top + layout.cell_height < layout.legend_top);
  CHECK(layout.legend_top < layout.height);
  // y grows upward in the cell, downward in the image.
  CHECK(layout.to_pixels({0.0, 0.0}).y() == Approx(layout.cell_top + layout.cell_height));
  CHECK(layout.to_pixels({kBoxX, kBoxY}).x() == Approx(layout.cell_left + layout.cell_width));
}

TEST_CASE("A PNG top view shows the rods in their species' colours and the trap's walls",
          "[render][top_view]") {
  const TestScene test;
  const TempDirectory directory;
  const engine::Frame frame = test_frame(test.trap);
  const render::ViewLayout layout = render::layout_view(test.scene, {600});
  render::write_png(directory / "view.png", layout, test.scene, frame, test_marks());

  const PngPixels png(directory / "view.png");
  REQUIRE(png.width() == layout.width);
  REQUIRE(png.height() == layout.height);
  const int x0 = static_cast<int>(std::ceil(layout.cell_left));
  const int y0 = static_cast<int>(std::ceil(layout.cell_top));
  const int x1 = static_cast<int>(layout.cell_left + layout.cell_width);
  const int y1 = static_cast<int>(layout.cell_top + layout.cell_height);
  const double px_per_mm2 = layout.scale * layout.scale;

  // Three A rods (one of them in two pieces across the edge) and one RnT rod, each covering its
  // projected area less the thin outline and, for the stationary one, its central dot.
  const double rod_a_px = test.scene.species[0].shape.projected_area * px_per_mm2;
  const double rod_rnt_px = test.scene.species[1].shape.projected_area * px_per_mm2;
  const int a_pixels = png.count(render::species_colour(0), x0, y0, x1, y1);
  const int rnt_pixels = png.count(render::species_colour(1), x0, y0, x1, y1);
  CHECK(a_pixels > 0.75 * 3.0 * rod_a_px);
  CHECK(a_pixels < 1.0 * 3.0 * rod_a_px);
  CHECK(rnt_pixels > 0.75 * rod_rnt_px);
  CHECK(rnt_pixels < 1.0 * rod_rnt_px);

  // Rod 2 reaches 2.5 mm left of its centre at x = 0.5 mm: its image shows at the right edge.
  const Eigen::Vector2d image = layout.to_pixels({kBoxX - 1.0, 26.0});
  CHECK(png.has_colour(static_cast<int>(image.x()), static_cast<int>(image.y()),
                       render::species_colour(0)));
  const Eigen::Vector2d outside = layout.to_pixels({kBoxX + 0.5, 26.0});
  CHECK_FALSE(png.has_colour(static_cast<int>(outside.x()), static_cast<int>(outside.y()),
                             render::species_colour(0)));

  // The walls, whole inside the cell.
  double wall_px = 0.0;
  for (const engine::Wall& wall : test.scene.walls) {
    wall_px += 4.0 * wall.half_length * wall.half_thickness * px_per_mm2;
  }
  const int wall_pixels = png.count(render::kWallColour, x0, y0, x1, y1);
  CHECK(wall_pixels > 0.7 * wall_px);
  CHECK(wall_pixels < 1.05 * wall_px);

  // The stationary rod carries the black dot on its centre; a moving one does not.
  const Eigen::Vector2d stationary = layout.to_pixels(frame.rods[3].position);
  CHECK(png.has_colour(static_cast<int>(stationary.x()), static_cast<int>(stationary.y()),
                       render::kStationaryColour));
  const Eigen::Vector2d moving = layout.to_pixels(frame.rods[0].position);
  CHECK(png.has_colour(static_cast<int>(moving.x()), static_cast<int>(moving.y()),
                       render::species_colour(0)));
}

TEST_CASE("An SVG top view is written", "[render][top_view]") {
  const TestScene test;
  const TempDirectory directory;
  const render::ViewLayout layout = render::layout_view(test.scene, {400});
  render::write_svg(directory / "view.svg", layout, test.scene, test_frame(test.trap),
                    test_marks());
  const std::string svg = read_text(directory / "view.svg");
  CHECK(svg.find("<svg") != std::string::npos);
  CHECK(svg.find("width=\"" + std::to_string(layout.width)) != std::string::npos);
  CHECK(svg.find("</svg>") != std::string::npos);
  // The text is text: the title, the legend and the scale bar's length, after the drawing.
  CHECK_THAT(svg, Catch::Contains(">" + test.scene.title + "</text>"));
  CHECK_THAT(svg, Catch::Contains(" mm</text>"));
  CHECK(svg.find("<text") > svg.find("<path"));
  CHECK(svg.rfind("</text>") < svg.rfind("</svg>"));
}

TEST_CASE("A top view for a figure leaves out the header, and the scale bar is a round length",
          "[render][top_view]") {
  const TestScene test;
  const render::ViewLayout with = render::layout_view(test.scene, {400});
  render::ViewOptions bare{400};
  bare.header = false;
  const render::ViewLayout without = render::layout_view(test.scene, bare);
  CHECK(without.cell_top < with.cell_top);
  CHECK(without.height < with.height);
  const TempDirectory directory;
  render::write_svg(directory / "bare.svg", without, test.scene, test_frame(test.trap),
                    test_marks());
  CHECK_THAT(read_text(directory / "bare.svg"), !Catch::Contains(test.scene.title + "</text>"));
  CHECK(render::scale_bar_length(86.85) == 10.0);
  CHECK(render::scale_bar_length(30.0) == 5.0);
  CHECK(render::scale_bar_length(24.0) == 2.0);
  CHECK(render::scale_bar_length(1100.0) == 200.0);
}

TEST_CASE("Writing a top view where no file can be made names the file", "[render][top_view]") {
  const TestScene test;
  const render::ViewLayout layout = render::layout_view(test.scene, {400});
  const std::filesystem::path path = "/nonexistent-directory/view.png";
  CHECK_THROWS_WITH(render::write_png(path, layout, test.scene, test_frame(test.trap), {}),
                    Catch::Contains(path.string()));
}
