#include "metrics/rods_csv.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using rodsort::engine::Frame;
using testing::frame_at;
using testing::rod_at;

namespace {

std::vector<Frame> sample_frames() {
  std::vector<Frame> frames;
  for (int k = 0; k < 3; ++k) {
    auto a = rod_at(99.9 + 0.123456789 * k, 12.5, 0.3 + 0.01 * k, 0);
    a.z = 0.61234567;
    a.axis = Eigen::Vector3d(0.8, 0.59, 0.1).normalized();
    a.velocity = {7.5, -0.25, 12.0};
    a.angular_velocity = {3.0, -2.0, 0.125};
    auto b = rod_at(-3.25, 250.0 - k, -2.0, 1);
    frames.push_back(frame_at(1000.07 + 0.07 * k, {a, b}));
  }
  return frames;
}

std::string written(const std::vector<Frame>& frames) {
  std::ostringstream out;
  RodsCsvWriter writer(out, {"A", "RnT"});
  writer.write_header();
  for (const Frame& frame : frames) writer.write(frame);
  return out.str();
}

/// The first error reading `text` as rods.csv, or "" when it reads cleanly.
std::string read_error(const std::string& text, std::vector<std::string> species = {"A", "RnT"}) {
  std::istringstream in(text);
  RodsCsvReader reader(in, "rods.csv", std::move(species));
  Frame frame;
  while (reader.next(frame)) {
  }
  return reader.error();
}

const std::string kHeader = std::string(kRodsCsvHeader) + "\n";
const std::string kRow0 = "0,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n";
const std::string kRow1 = "0,1,RnT,3,4,3,4,0.6,0,1,0,0,0,0,0\n";

}  // namespace

TEST_CASE("rods.csv writes the documented header and full lines", "[metrics][rods_csv]") {
  const std::string text = written(sample_frames());
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  CHECK(line == "t,rod,species,x,y,xu,yu,z,ux,uy,uz,vx,vy,vz,wz");
  std::getline(in, line);
  CHECK(line.rfind("1000.07,0,A,99.9,12.5,99.9,12.5,0.61234567,", 0) == 0);
  std::getline(in, line);
  CHECK(line.rfind("1000.07,1,RnT,96.75,50,-3.25,250,", 0) == 0);
  CHECK(text.back() == '\n');
}

TEST_CASE("rods.csv round trip", "[metrics][rods_csv]") {
  const auto frames = sample_frames();
  std::istringstream in(written(frames));
  RodsCsvReader reader(in, "rods.csv");
  std::vector<Frame> read;
  Frame frame;
  while (reader.next(frame)) read.push_back(frame);
  INFO(reader.error());
  REQUIRE(reader.error().empty());
  CHECK(reader.warning().empty());
  CHECK(reader.species() == std::vector<std::string>{"A", "RnT"});
  REQUIRE(read.size() == frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    CHECK(read[k].time == Approx(frames[k].time).epsilon(1e-9));
    REQUIRE(read[k].rods.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& a = frames[k].rods[i];
      const auto& b = read[k].rods[i];
      CHECK(b.species == a.species);
      CHECK((b.position - a.position).norm() < 1e-6);
      CHECK((b.unwrapped - a.unwrapped).norm() < 1e-6);
      CHECK(b.z == Approx(a.z).epsilon(1e-8));
      CHECK((b.axis - a.axis).norm() < 1e-8);
      CHECK((b.velocity - a.velocity).norm() < 1e-7);
      CHECK(b.angular_velocity.z() == Approx(a.angular_velocity.z()));
      CHECK(b.angular_velocity.x() == 0.0);  // not kept
    }
  }
}

TEST_CASE("rods.csv reader maps species names onto the run's indices", "[metrics][rods_csv]") {
  const std::string text = kHeader + kRow0 + kRow1;
  std::istringstream in(text);
  RodsCsvReader reader(in, "rods.csv", {"RnT", "A"});
  Frame frame;
  REQUIRE(reader.next(frame));
  CHECK(frame.rods[0].species == 1);
  CHECK(frame.rods[1].species == 0);
  CHECK_FALSE(reader.next(frame));
  CHECK(reader.error().empty());
}

TEST_CASE("rods.csv read from a file", "[metrics][rods_csv]") {
  const auto path = std::filesystem::path(RODSORT_BINARY_DIR) / "rods_csv_test.csv";
  {
    std::ofstream out(path);
    out << written(sample_frames());
  }
  const RodsCsv csv = read_rods_csv(path);
  CHECK(csv.error.empty());
  CHECK(csv.frames.size() == 3);
  std::filesystem::remove(path);
  const RodsCsv missing = read_rods_csv(path);
  CHECK_THAT(missing.error, Catch::Contains("rods_csv_test.csv: cannot open"));
}

TEST_CASE("rods.csv reader errors name the line, the field and what was expected",
          "[metrics][rods_csv]") {
  CHECK_THAT(read_error(""), Catch::Contains("rods.csv:0: empty file, expected the header"));
  CHECK_THAT(read_error("t,rod,species,x,y\n" + kRow0),
             Catch::Contains("rods.csv:1: expected the header 't,rod,species,x,y,xu,yu,z,ux,uy,"
                             "uz,vx,vy,vz,wz', got 't,rod,species,x,y'"));
  CHECK_THAT(read_error(kHeader + "0,0,A,1,2,1,2,0.6,1,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:2: expected 15 comma-separated fields") &&
                 Catch::Contains("got 14"));
  CHECK_THAT(read_error(kHeader + "0,0,A,1,2,1,2.5.1,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:2:13: field 'yu': expected a number, got '2.5.1'"));
  CHECK_THAT(read_error(kHeader + "0,0,A,1,2,1,2,0.6,1,0,0,nan,0,0,0\n"),
             Catch::Contains("field 'vx': expected a finite number, got 'nan'"));
  CHECK_THAT(read_error(kHeader + "0,0,A,1,2,1,,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("field 'yu': expected a number, got ''"));
  CHECK_THAT(read_error(kHeader + "0,x,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:2:3: field 'rod': expected a rod index"));
  CHECK_THAT(read_error(kHeader + "0,0,B,1,2,1,2,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:2:5: field 'species': expected one of the run's species "
                             "('A', 'RnT'), got 'B'"));
  CHECK_THAT(read_error(kHeader + kRow1),
             Catch::Contains("rods.csv:2: field 'rod': expected rod 0"));
  // Time going backwards between frames.
  CHECK_THAT(read_error(kHeader + "1,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n" + kRow0),
             Catch::Contains("rods.csv:3:1: field 't': expected a time after 1, got 0"));
  // A frame in the middle with a rod missing.
  CHECK_THAT(read_error(kHeader + kRow0 + kRow1 + "1,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n" +
                        "2,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:4: frame at t = 1") &&
                 Catch::Contains("has 1 rods, the first frame had 2"));
  // A rod changing species.
  CHECK_THAT(read_error(kHeader + kRow0 + kRow1 + "1,0,RnT,1,2,1,2,0.6,1,0,0,0,0,0,0\n"),
             Catch::Contains("rods.csv:4: field 'species': rod 0 was 'A' in the first frame, "
                             "got 'RnT'"));
  // Garbage never crashes.
  for (const std::string& garbage :
       {std::string(",,,,,,,,,,,,,,\n"), std::string("\x01\x02\n"), std::string(200, ',') + "\n",
        std::string("1e999,0,A") + std::string(12, ',') + "\n"}) {
    CHECK_FALSE(read_error(kHeader + garbage).empty());
  }
  CHECK(read_error(kHeader + kRow0 + kRow1 + "\r\n").empty());
}

TEST_CASE("rods.csv reader drops an incomplete last frame and says so", "[metrics][rods_csv]") {
  SECTION("a line cut short") {
    std::istringstream in(kHeader + kRow0 + kRow1 + "1,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n1,1,Rn");
    RodsCsvReader reader(in, "rods.csv");
    Frame frame;
    REQUIRE(reader.next(frame));
    CHECK_FALSE(reader.next(frame));
    CHECK(reader.error().empty());
    CHECK_THAT(reader.warning(), Catch::Contains("rods.csv:5: the last line is cut short"));
    CHECK_THAT(reader.warning(), Catch::Contains("dropped the incomplete frame at t = 1"));
  }
  SECTION("a frame missing its last rods") {
    std::istringstream in(kHeader + kRow0 + kRow1 + "1,0,A,1,2,1,2,0.6,1,0,0,0,0,0,0\n");
    RodsCsvReader reader(in, "rods.csv");
    Frame frame;
    REQUIRE(reader.next(frame));
    CHECK_FALSE(reader.next(frame));
    CHECK(reader.error().empty());
    CHECK_THAT(reader.warning(), Catch::Contains("has 1 of 2 rods"));
  }
}
