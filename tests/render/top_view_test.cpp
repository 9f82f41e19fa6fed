#include "render/top_view.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "engine/rod_shape.hpp"
#include "engine/units.hpp"
#include "render/png_pixels.hpp"
#include "render/temp_directory.hpp"
#include "trap/v_trap.hpp"

using namespace rodsort;
using render::testing::PngPixels;
using render::testing::TempDirectory;

namespace {

constexpr double kBoxX = 40.0;  // [mm]
constexpr double kBoxY = 30.0;  // [mm]

/// Rod A and rod RnT in a 40 x 30 mm cell, with a 90° trap of 12 mm arms in the middle.
struct TestScene {
  trap::VTrap trap = trap::centered_v_trap(kBoxX, kBoxY, kPi / 2.0, 12.0, 0.5);
  engine::Model model;
  render::Scene scene;

  TestScene() {
    model.box_x = kBoxX;
    model.box_y = kBoxY;
    model.species.push_back({"A",
                             engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity),
                             {},
                             engine::MaterialTable::kFirstRod});
    model.species.push_back({"RnT",
                             engine::make_rod_shape(engine::preset_rnt_profile(), kBrassDensity),
                             {},
                             engine::MaterialTable::kFirstRod});
    model.walls = trap.walls();
    scene = render::make_scene(model, &trap, "render test");
  }
};

engine::RodFrame rod(int species, double x, double y, double heading) {
  engine::RodFrame rod;
  rod.species = species;
  rod.position = {x, y};
  rod.unwrapped = rod.position;
  rod.axis = {std::cos(heading), std::sin(heading), 0.0};
  rod.velocity.setZero();
  rod.angular_velocity.setZero();
  return rod;
}

/// Rod 0 (A) moving in the open, rod 1 (RnT) moving, rod 2 (A) across the left edge of the cell,
/// rod 3 (A) stationary inside the trap.
engine::Frame test_frame(const trap::VTrap& trap) {
  engine::Frame frame;
  frame.time = 1.25;
  frame.rods.push_back(rod(0, 6.0, 6.0, 0.0));
  frame.rods.push_back(rod(1, 34.0, 24.0, kPi / 2.0));
  frame.rods.push_back(rod(0, 0.5, 26.0, 0.0));
  const Eigen::Vector2d in_trap = trap.apex() + 4.0 * trap.bisector();
  frame.rods.push_back(rod(0, in_trap.x(), in_trap.y(), kPi));
  return frame;
}

render::FrameMarks test_marks() { return {{false, false, false, true}, 0.25, 0.2}; }

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
}

TEST_CASE("Writing a top view where no file can be made names the file", "[render][top_view]") {
  const TestScene test;
  const render::ViewLayout layout = render::layout_view(test.scene, {400});
  const std::filesystem::path path = "/nonexistent-directory/view.png";
  CHECK_THROWS_WITH(render::write_png(path, layout, test.scene, test_frame(test.trap), {}),
                    Catch::Contains(path.string()));
}
