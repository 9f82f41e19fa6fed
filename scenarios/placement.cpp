#include "scenarios/placement.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/random_stream.hpp"
#include "engine/segment_distance.hpp"
#include "engine/units.hpp"
#include "trap/obstacle.hpp"

namespace rodsort::scenarios {
namespace {

/// A rod's bounding capsule in the plane.
struct Capsule {
  Eigen::Vector2d center;  ///< centre of mass [mm]
  Eigen::Vector2d a, b;    ///< ends of the segment, relative to the centre [mm]
  double radius;           ///< [mm]
  double reach;            ///< from the centre to the farthest point of the capsule [mm]
};

Capsule capsule_of(const engine::RodShape& shape, const Eigen::Vector2d& center, double heading) {
  const Eigen::Vector2d axis(std::cos(heading), std::sin(heading));
  const double radius = shape.max_radius;
  double back = shape.thick_tip + radius;
  double front = shape.thin_tip - radius;
  if (back > front) back = front = 0.5 * (back + front);  // a rod hardly longer than thick
  const Eigen::Vector2d a = back * axis;
  const Eigen::Vector2d b = front * axis;
  // Off-axis spheres are the straight rod's moved by at most their largest offset.
  return {center, a, b, radius + shape.max_lateral,
          std::max(a.norm(), b.norm()) + radius + shape.max_lateral};
}

/// Nearest image of a displacement in the periodic cell.
Eigen::Vector2d nearest_image(Eigen::Vector2d d, double box_x, double box_y) {
  d.x() -= box_x * std::round(d.x() / box_x);
  d.y() -= box_y * std::round(d.y() / box_y);
  return d;
}

bool capsules_overlap(const Capsule& p, const Capsule& q, double box_x, double box_y) {
  const Eigen::Vector2d d = nearest_image(q.center - p.center, box_x, box_y);
  const double contact = p.radius + q.radius + kPlacementClearance;
  if (d.norm() > p.reach + q.reach + kPlacementClearance) return false;
  return segment_distance(p.a, p.b, d + q.a, d + q.b) < contact;
}

/// The capsules placed so far, binned in a periodic grid whose cells are at least as wide as the
/// largest reach twice plus the clearance: a candidate can only overlap capsules in its own cell
/// and the eight around it (the reach test of capsules_overlap), so testing those gives the same
/// answer as testing every capsule, in time independent of how many are placed.
class PlacedCapsules {
 public:
  PlacedCapsules(double box_x, double box_y, double largest_reach) : box_x_(box_x), box_y_(box_y) {
    const double cell = 2.0 * largest_reach + kPlacementClearance;
    nx_ = std::max(1, static_cast<int>(std::floor(box_x / cell)));
    ny_ = std::max(1, static_cast<int>(std::floor(box_y / cell)));
    // Fewer than three cells across would make a cell its own neighbour: one bin then.
    if (nx_ < 3 || ny_ < 3) nx_ = ny_ = 1;
    bins_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  }

  bool overlaps(const Capsule& candidate) const {
    const auto [ix, iy] = cell_of(candidate.center);
    const int reach = nx_ == 1 ? 0 : 1;
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (const int other : bins_[bin(ix + dx, iy + dy)]) {
          if (capsules_overlap(candidate, capsules_[static_cast<std::size_t>(other)], box_x_,
                               box_y_)) {
            return true;
          }
        }
      }
    }
    return false;
  }

  void add(const Capsule& capsule) {
    const auto [ix, iy] = cell_of(capsule.center);
    bins_[bin(ix, iy)].push_back(static_cast<int>(capsules_.size()));
    capsules_.push_back(capsule);
  }

 private:
  std::pair<int, int> cell_of(const Eigen::Vector2d& p) const {
    return {static_cast<int>(std::floor(p.x() / box_x_ * nx_)),
            static_cast<int>(std::floor(p.y() / box_y_ * ny_))};
  }
  std::size_t bin(int ix, int iy) const {
    const int x = ((ix % nx_) + nx_) % nx_;
    const int y = ((iy % ny_) + ny_) % ny_;
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(x);
  }

  double box_x_, box_y_;
  int nx_ = 1, ny_ = 1;
  std::vector<Capsule> capsules_;
  std::vector<std::vector<int>> bins_;
};

bool capsule_hits_wall(const Capsule& c, const engine::Wall& wall, double box_x, double box_y) {
  const Eigen::Vector2d wall_center(wall.center_x, wall.center_y);
  const Eigen::Vector2d d = nearest_image(c.center - wall_center, box_x, box_y);
  // In the wall's frame the wall is the rectangle |x| <= half_length, |y| <= half_thickness.
  const Eigen::Vector2d along(std::cos(wall.yaw), std::sin(wall.yaw));
  const Eigen::Vector2d across(-along.y(), along.x());
  const auto to_wall = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d r = d + p;
    return Eigen::Vector2d(r.dot(along), r.dot(across));
  };
  const Eigen::Vector2d a = to_wall(c.a);
  const Eigen::Vector2d b = to_wall(c.b);
  const double hx = wall.half_length;
  const double hy = wall.half_thickness;
  const double contact = c.radius + kPlacementClearance;
  if (std::abs(d.dot(along)) > hx + c.reach + contact ||
      std::abs(d.dot(across)) > hy + c.reach + contact) {
    return false;
  }
  const auto inside = [&](const Eigen::Vector2d& p) {
    return std::abs(p.x()) <= hx && std::abs(p.y()) <= hy;
  };
  if (inside(a) || inside(b)) return true;
  const Eigen::Vector2d corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  for (int i = 0; i < 4; ++i) {
    if (segment_distance(a, b, corners[i], corners[(i + 1) % 4]) < contact) return true;
  }
  return false;
}

/// Order in which rods are drawn: species interleaved in proportion to their counts.
std::vector<int> drawing_order(const std::vector<SpeciesPlacement>& species) {
  struct Slot {
    double key;
    int index;
  };
  std::vector<Slot> slots;
  for (std::size_t i = 0; i < species.size(); ++i) {
    for (int k = 0; k < species[i].count; ++k) {
      slots.push_back({(k + 0.5) / species[i].count, static_cast<int>(i)});
    }
  }
  std::stable_sort(slots.begin(), slots.end(), [](const Slot& l, const Slot& r) {
    return l.key < r.key || (l.key == r.key && l.index < r.index);
  });
  std::vector<int> order;
  for (const Slot& slot : slots) order.push_back(slot.index);
  return order;
}

}  // namespace

double segment_distance(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                        const Eigen::Vector2d& q0, const Eigen::Vector2d& q1) {
  return std::sqrt(engine::segment_distance_squared(p0, p1, q0, q1));
}

PlacementResult place_rods(const PlacementCell& cell, const std::vector<SpeciesPlacement>& species,
                           std::uint64_t seed) {
  engine::RandomStream random(seed, 0, engine::StreamPurpose::kPlacement);
  const auto uniform_in = [&](double low, double high) {
    return low + (high - low) * random.uniform();
  };
  const auto draw_center = [&](PlacementRegion region) {
    for (;;) {
      Eigen::Vector2d p;
      if (region == PlacementRegion::inside_trap) {
        const trap::Bounds bounds = cell.trap->bounds();
        p = {uniform_in(bounds.min.x(), bounds.max.x()),
             uniform_in(bounds.min.y(), bounds.max.y())};
      } else {
        p = {uniform_in(0.0, cell.box_x), uniform_in(0.0, cell.box_y)};
      }
      if (cell.boundary != nullptr && !cell.boundary->contains(p)) continue;
      const bool in_trap = cell.trap != nullptr && cell.trap->contains(p);
      if (region == PlacementRegion::anywhere ||
          (region == PlacementRegion::inside_trap) == in_trap) {
        return p;
      }
    }
  };

  PlacementResult result;
  double largest_reach = 0.0;
  for (const SpeciesPlacement& s : species) {
    largest_reach = std::max(largest_reach, capsule_of(s.shape, {0.0, 0.0}, 0.0).reach);
  }
  PlacedCapsules placed(cell.box_x, cell.box_y, largest_reach);
  std::vector<int> placed_count(species.size(), 0);
  for (const int index : drawing_order(species)) {
    const SpeciesPlacement& s = species[static_cast<std::size_t>(index)];
    bool done = false;
    for (int attempt = 0; attempt < kPlacementAttempts && !done; ++attempt) {
      const Eigen::Vector2d center = draw_center(s.region);
      double heading = 0.0;
      switch (s.heading.kind) {
        case PlacementHeading::Kind::random:
          heading = uniform_in(-kPi, kPi);
          break;
        case PlacementHeading::Kind::toward_apex: {
          const Eigen::Vector2d to_apex =
              nearest_image(*cell.apex - center, cell.box_x, cell.box_y);
          heading = std::atan2(to_apex.y(), to_apex.x());
          break;
        }
        case PlacementHeading::Kind::fixed:
          heading = s.heading.angle;
          break;
      }
      // A rod that is not straight lands with its off-axis part facing any way about its axis; a
      // straight one draws nothing, so that its placements stay as they were.
      const double roll = engine::is_straight(s.shape.spheres) ? 0.0 : uniform_in(-kPi, kPi);
      const Capsule capsule = capsule_of(s.shape, center, heading);
      const bool free =
          std::none_of(cell.walls.begin(), cell.walls.end(),
                       [&](const engine::Wall& wall) {
                         return capsule_hits_wall(capsule, wall, cell.box_x, cell.box_y);
                       }) &&
          !placed.overlaps(capsule);
      if (free) {
        placed.add(capsule);
        result.rods.push_back({s.species, center.x(), center.y(), heading, roll});
        ++placed_count[static_cast<std::size_t>(index)];
        done = true;
      }
    }
    if (!done) {
      result.failure =
          PlacementFailure{s.species, placed_count[static_cast<std::size_t>(index)], s.count};
      return result;
    }
  }
  std::stable_sort(
      result.rods.begin(), result.rods.end(),
      [](const engine::RodInit& l, const engine::RodInit& r) { return l.species < r.species; });
  return result;
}

}  // namespace rodsort::scenarios
