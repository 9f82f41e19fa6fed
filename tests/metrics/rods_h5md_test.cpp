#include "metrics/rods_h5md.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "support/temp_directory.hpp"
#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using rodsort::engine::Frame;
using rodsort::testing::TempDirectory;
using testing::frame_at;
using testing::rod_at;

namespace {

constexpr double kBox = 100.0;

H5mdLayout layout(H5mdPrecision precision = H5mdPrecision::single) {
  H5mdLayout result;
  result.species_names = {"A", "RnT"};
  result.rod_species = {0, 1, 0};
  result.box_x = kBox;
  result.box_y = kBox;
  result.box_z = 1.2;
  rodsort::engine::Wall wall{};
  wall.center_x = 50.0;
  wall.center_y = 40.0;
  wall.half_length = 10.0;
  wall.half_thickness = 0.5;
  wall.yaw = 0.3;
  result.walls = {wall};
  result.scenario_yaml = "seed: 1\n";
  result.precision = precision;
  result.creator_version = "test";
  return result;
}

/// Frame k of a made-up run: three rods with values that float cannot hold exactly, one of them
/// several cells away from where it started.
Frame frame_number(int k) {
  auto a = rod_at(99.9 + 0.123456789 * k, 12.5, 0.3 + 0.01 * k, 0, kBox);
  a.z = 0.61234567;
  a.axis = Eigen::Vector3d(0.8, 0.59, 0.1 * k).normalized();
  a.velocity = {7.5 + 1e-9 * k, -0.25, 12.0 / 7.0};
  a.angular_velocity = {0.0, 0.0, 1.0 / 3.0};
  auto b = rod_at(-3.25 - 0.7 * k, 250.0 - k, -2.0, 1, kBox);
  auto c = rod_at(33.3, 66.6, 1.0, 0, kBox);
  return frame_at(0.07 * k, {a, b, c});
}

void require_same(const Frame& a, const Frame& b) {
  REQUIRE(a.time == b.time);
  REQUIRE(a.rods.size() == b.rods.size());
  for (std::size_t i = 0; i < a.rods.size(); ++i) {
    const auto& x = a.rods[i];
    const auto& y = b.rods[i];
    CHECK(x.species == y.species);
    CHECK(x.position == y.position);
    CHECK(x.unwrapped == y.unwrapped);
    CHECK(x.z == y.z);
    CHECK(x.axis == y.axis);
    CHECK(x.velocity == y.velocity);
    CHECK(x.angular_velocity == y.angular_velocity);
  }
}

}  // namespace

TEST_CASE("rods.h5 gives back every frame as H5mdRounding::stored has it", "[h5md]") {
  for (const H5mdPrecision precision : {H5mdPrecision::single, H5mdPrecision::full}) {
    const TempDirectory directory;
    const auto path = directory / "rods.h5";
    const H5mdRounding rounding(precision, kBox, kBox);
    {
      RodsH5mdWriter writer(path, layout(precision));
      // More than a chunk (64 frames), with a commit in the middle of one.
      for (int k = 0; k < 150; ++k) {
        writer.write(frame_number(k), 1000 * k);
        if (k == 70) writer.commit();
      }
      CHECK(writer.frames() == 150);
    }
    RodsH5mdReader reader(path, {"A", "RnT"});
    REQUIRE(reader.error().empty());
    CHECK(reader.frame_count() == 150);
    Frame frame;
    for (int k = 0; k < 150; ++k) {
      REQUIRE(reader.next(frame));
      require_same(frame, rounding.stored(frame_number(k)));
    }
    CHECK_FALSE(reader.next(frame));
    CHECK(reader.error().empty());
    CHECK(reader.warning().empty());

    // Single precision keeps 7 digits; double keeps the numbers themselves.
    const Frame original = frame_number(149);
    const Frame stored = rounding.stored(original);
    const double tolerance = precision == H5mdPrecision::single ? 1e-5 : 0.0;
    CHECK(std::abs(stored.rods[0].velocity.z() - 12.0 / 7.0) <= tolerance * 2);
    CHECK((stored.rods[1].unwrapped - original.rods[1].unwrapped).norm() <= tolerance * 300);
    if (precision == H5mdPrecision::single) {
      CHECK(stored.rods[0].velocity.z() != 12.0 / 7.0);
    } else {
      require_same(stored, original);
    }
  }
}

TEST_CASE("rods.h5 continues after a checkpoint's frame count, dropping later frames", "[h5md]") {
  const TempDirectory directory;
  const auto path = directory / "rods.h5";
  {
    RodsH5mdWriter writer(path, layout());
    for (int k = 0; k < 100; ++k) writer.write(frame_number(k), k);
  }
  {
    RodsH5mdWriter writer(path, layout(), 40);
    CHECK(writer.frames() == 40);
    for (int k = 40; k < 90; ++k) writer.write(frame_number(k), k);
  }
  {
    RodsH5mdReader reader(path);
    CHECK(reader.species() == std::vector<std::string>{"A", "RnT"});
    CHECK(reader.frame_count() == 90);
    reader.seek(85);
    Frame frame;
    REQUIRE(reader.next(frame));
    require_same(frame, H5mdRounding(H5mdPrecision::single, kBox, kBox).stored(frame_number(85)));
  }

  // A checkpoint that counts more frames than the file holds is refused.
  CHECK_THROWS_WITH((RodsH5mdWriter(path, layout(), 91)),
                    Catch::Contains("holds fewer frames than the checkpoint counts"));
}

TEST_CASE("rods.h5 errors name the file and what is wrong", "[h5md]") {
  const TempDirectory directory;
  Frame frame;
  {
    RodsH5mdReader reader(directory / "missing.h5");
    CHECK_FALSE(reader.next(frame));
    CHECK_THAT(reader.error(), Catch::Contains("missing.h5") && Catch::Contains("no such file"));
  }
  {
    std::ofstream(directory / "text.h5") << "t,rod,species\n";
    RodsH5mdReader reader(directory / "text.h5");
    CHECK_FALSE(reader.next(frame));
    CHECK_THAT(reader.error(), Catch::Contains("text.h5") && Catch::Contains("HDF5"));
  }
  {
    const auto path = directory / "rods.h5";
    { RodsH5mdWriter writer(path, layout()); }
    RodsH5mdReader reader(path, {"A", "B"});
    CHECK_FALSE(reader.next(frame));
    CHECK_THAT(reader.error(), Catch::Contains("species A, RnT; the run's scenario has A, B"));
  }
}
