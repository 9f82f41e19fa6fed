#include "runner/lammps_dump.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace rodsort::runner {

LammpsDumpFormatter::LammpsDumpFormatter(const engine::Model& model, double z_low, double z_high,
                                         DumpStyle style)
    : style_(style),
      rod_count_(model.rods.size()),
      box_x_(model.box_x),
      box_y_(model.box_y),
      z_low_(z_low),
      z_high_(z_high) {
  for (std::size_t s = 0; s < model.species.size(); ++s) {
    species_spheres_.push_back(model.species[s].shape.spheres);
    type_names_.push_back(style == DumpStyle::named ? model.species[s].name
                                                    : std::to_string(s + 1));
  }
  for (const engine::RodInit& rod : model.rods) {
    atom_count_ +=
        static_cast<std::int64_t>(species_spheres_[static_cast<std::size_t>(rod.species)].size());
  }
}

std::string LammpsDumpFormatter::header_start(double time_s, std::int64_t step) const {
  char line[96];
  std::string text;
  if (style_ == DumpStyle::named) {
    std::snprintf(line, sizeof line, "ITEM: TIME\n%.10g\n", time_s);
    text += line;
  }
  std::snprintf(line, sizeof line, "ITEM: TIMESTEP\n%lld\n", static_cast<long long>(step));
  return text + line;
}

std::string LammpsDumpFormatter::format(const engine::Frame& frame, std::int64_t step) const {
  assert(frame.rods.size() == rod_count_);
  std::string text = header_start(frame.time, step);
  text.reserve(static_cast<std::size_t>(atom_count_) * 56 + 256);
  char line[256];
  std::snprintf(line, sizeof line,
                "ITEM: NUMBER OF ATOMS\n%lld\n"
                "ITEM: BOX BOUNDS pp pp ff\n%.10g %.10g\n%.10g %.10g\n%.10g %.10g\n"
                "ITEM: ATOMS id mol type x y z radius\n",
                static_cast<long long>(atom_count_), 0.0, box_x_, 0.0, box_y_, z_low_, z_high_);
  text += line;
  long long atom_id = 1;
  for (std::size_t rod = 0; rod < frame.rods.size(); ++rod) {
    const engine::RodFrame& r = frame.rods[rod];
    const auto& spheres = species_spheres_[static_cast<std::size_t>(r.species)];
    // A frame has the axis but not the roll about it: off-axis spheres are written on the axis.
    for (const engine::Sphere& sphere : spheres) {
      const double x = r.position.x() + sphere.axial * r.axis.x();
      const double y = r.position.y() + sphere.axial * r.axis.y();
      const double z = r.z + sphere.axial * r.axis.z();
      std::snprintf(line, sizeof line, "%lld %zu %s %.5f %.5f %.5f %.4f\n", atom_id++, rod + 1,
                    type_names_[static_cast<std::size_t>(r.species)].c_str(), x, y, z,
                    sphere.radius);
      text += line;
    }
  }
  return text;
}

std::string LammpsDumpFormatter::walls(const engine::Model& model) const {
  if (model.walls.empty()) return "";
  struct Bead {
    double x, y, radius;
    std::size_t wall;
  };
  std::vector<Bead> beads;
  for (std::size_t w = 0; w < model.walls.size(); ++w) {
    const engine::Wall& wall = model.walls[w];
    const auto gaps = static_cast<int>(std::ceil(2.0 * wall.half_length / wall.half_thickness));
    for (int i = 0; i <= gaps; ++i) {
      const double along = -wall.half_length + 2.0 * wall.half_length * i / gaps;
      beads.push_back({wall.center_x + along * std::cos(wall.yaw),
                       wall.center_y + along * std::sin(wall.yaw), wall.half_thickness, w});
    }
  }
  std::string text = header_start(0.0, 0);
  char line[256];
  std::snprintf(line, sizeof line,
                "ITEM: NUMBER OF ATOMS\n%zu\n"
                "ITEM: BOX BOUNDS pp pp ff\n%.10g %.10g\n%.10g %.10g\n%.10g %.10g\n"
                "ITEM: ATOMS id mol type x y z radius\n",
                beads.size(), 0.0, box_x_, 0.0, box_y_, z_low_, z_high_);
  text += line;
  for (std::size_t b = 0; b < beads.size(); ++b) {
    std::snprintf(line, sizeof line, "%zu %zu %s %.5f %.5f %.5f %.4f\n", b + 1, beads[b].wall + 1,
                  style_ == DumpStyle::named ? "wall" : "1", beads[b].x, beads[b].y,
                  0.5 * model.drive.gap, beads[b].radius);
    text += line;
  }
  return text;
}

}  // namespace rodsort::runner
