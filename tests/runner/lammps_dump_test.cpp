#include "runner/lammps_dump.hpp"

#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "engine/units.hpp"

using namespace rodsort;
using runner::LammpsDumpFormatter;

namespace {

engine::Model two_species_model() {
  engine::Model model;
  model.box_x = 40.0;
  model.box_y = 30.0;
  engine::Species two_spheres;
  two_spheres.shape.spheres = {{-1.0, 0.5}, {1.0, 0.25}};
  engine::Species one_sphere;
  one_sphere.shape.spheres = {{0.0, 0.4}};
  model.species = {two_spheres, one_sphere};
  model.rods = {{0, 10.0, 10.0, 0.0}, {1, 20.0, 5.0, 0.0}};
  return model;
}

/// A rod frame with every field set (Eigen leaves vectors uninitialised).
engine::RodFrame rod_frame(int species, Eigen::Vector2d position, double z, Eigen::Vector3d axis) {
  engine::RodFrame rod;
  rod.species = species;
  rod.position = position;
  rod.unwrapped = position;
  rod.z = z;
  rod.axis = axis;
  rod.velocity.setZero();
  rod.angular_velocity.setZero();
  return rod;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("a LAMMPS dump frame lists every sphere of every rod", "[runner][lammps_dump]") {
  const engine::Model model = two_species_model();
  const LammpsDumpFormatter formatter(model, -0.05, 1.25);
  engine::Frame frame;
  frame.time = 0.5;
  frame.rods = {rod_frame(0, {10.0, 12.0}, 0.6, {0.0, 1.0, 0.0}),
                rod_frame(1, {39.9, 0.2}, 0.45, {1.0, 0.0, 0.0})};

  const std::vector<std::string> lines = lines_of(formatter.format(frame, 5000));
  const std::vector<std::string> expected = {
      "ITEM: TIMESTEP",
      "5000",
      "ITEM: NUMBER OF ATOMS",
      "3",
      "ITEM: BOX BOUNDS pp pp ff",
      "0 40",
      "0 30",
      "-0.05 1.25",
      "ITEM: ATOMS id mol type x y z radius",
      "1 1 1 10.00000 11.00000 0.60000 0.5000",  // thick end, 1 mm behind along the axis
      "2 1 1 10.00000 13.00000 0.60000 0.2500",
      "3 2 2 39.90000 0.20000 0.45000 0.4000",
  };
  CHECK(lines == expected);
}

TEST_CASE("consecutive LAMMPS dump frames concatenate", "[runner][lammps_dump]") {
  const engine::Model model = two_species_model();
  const LammpsDumpFormatter formatter(model, 0.0, 1.2);
  engine::Frame frame;
  for (const engine::RodInit& init : model.rods) {
    frame.rods.push_back(rod_frame(init.species, {init.x, init.y}, 0.5, {1.0, 0.0, 0.0}));
  }
  const std::string both = formatter.format(frame, 0) + formatter.format(frame, 700);
  const std::vector<std::string> lines = lines_of(both);
  REQUIRE(lines.size() == 24);
  CHECK(lines[12] == "ITEM: TIMESTEP");
  CHECK(lines[13] == "700");
}

TEST_CASE("the trap's walls are a dump of spheres along each wall's centre line",
          "[runner][lammps_dump]") {
  engine::Model model = two_species_model();
  model.drive.gap = 1.2;
  const LammpsDumpFormatter formatter(model, -0.05, 1.25);
  CHECK(formatter.walls(model).empty());
  // A wall 4 mm long and 1 mm thick along y, centred at (20, 15): spheres every 0.5 mm.
  model.walls = {{20.0, 15.0, 2.0, 0.5, rodsort::kPi / 2}};
  const std::vector<std::string> lines = lines_of(formatter.walls(model));
  REQUIRE(lines.size() == 9 + 9);
  CHECK(lines[3] == "9");
  CHECK(lines[8] == "ITEM: ATOMS id mol type x y z radius");
  CHECK(lines[9] == "1 1 1 20.00000 13.00000 0.60000 0.5000");
  CHECK(lines[13] == "5 1 1 20.00000 15.00000 0.60000 0.5000");
  CHECK(lines[17] == "9 1 1 20.00000 17.00000 0.60000 0.5000");
}

TEST_CASE("a named LAMMPS dump gives the time and the species' names, as LAMMPS's type labels",
          "[runner][lammps_dump]") {
  engine::Model model = two_species_model();
  model.species[0].name = "A";
  model.species[1].name = "RnT";
  const LammpsDumpFormatter formatter(model, -0.05, 1.25, runner::DumpStyle::named);
  engine::Frame frame;
  frame.time = 0.35;
  frame.rods = {rod_frame(0, {10.0, 12.0}, 0.6, {0.0, 1.0, 0.0}),
                rod_frame(1, {39.9, 0.2}, 0.45, {1.0, 0.0, 0.0})};
  const std::vector<std::string> lines = lines_of(formatter.format(frame, 3500));
  const std::vector<std::string> expected = {
      "ITEM: TIME",
      "0.35",
      "ITEM: TIMESTEP",
      "3500",
      "ITEM: NUMBER OF ATOMS",
      "3",
      "ITEM: BOX BOUNDS pp pp ff",
      "0 40",
      "0 30",
      "-0.05 1.25",
      "ITEM: ATOMS id mol type x y z radius",
      "1 1 A 10.00000 11.00000 0.60000 0.5000",
      "2 1 A 10.00000 13.00000 0.60000 0.2500",
      "3 2 RnT 39.90000 0.20000 0.45000 0.4000",
  };
  CHECK(lines == expected);

  model.drive.gap = 1.2;
  model.walls = {{20.0, 15.0, 2.0, 0.5, rodsort::kPi / 2}};
  const std::vector<std::string> walls = lines_of(formatter.walls(model));
  REQUIRE(walls.size() == 11 + 9);
  CHECK(walls[0] == "ITEM: TIME");
  CHECK(walls[1] == "0");
  CHECK(walls[11] == "1 1 wall 20.00000 13.00000 0.60000 0.5000");
}
