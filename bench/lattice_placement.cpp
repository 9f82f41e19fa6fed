#include "bench/lattice_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "engine/units.hpp"

namespace rodsort::bench {
namespace {

/// Largest jitter of a rod's centre from its site, per coordinate, as a fraction of the spacing.
constexpr double kJitter = 0.2;
/// Headings and jitters drawn for a site before it is left empty.
constexpr int kTriesPerSite = 50;

struct Disc {
  double x, y, radius;
};

std::vector<Disc> discs_of(const engine::RodShape& shape, double x, double y, double heading) {
  std::vector<Disc> discs;
  for (const engine::Sphere& sphere : shape.spheres) {
    discs.push_back({x + sphere.axial * std::cos(heading), y + sphere.axial * std::sin(heading),
                     sphere.radius});
  }
  return discs;
}

double periodic(double d, double box) { return d - box * std::round(d / box); }

bool discs_overlap(const std::vector<Disc>& a, const std::vector<Disc>& b, double box_x,
                   double box_y) {
  for (const Disc& p : a) {
    for (const Disc& q : b) {
      const double dx = periodic(p.x - q.x, box_x);
      const double dy = periodic(p.y - q.y, box_y);
      const double reach = p.radius + q.radius + kPlacementClearance;
      if (dx * dx + dy * dy < reach * reach) return true;
    }
  }
  return false;
}

/// Distance from a point to a wall's rectangle in the plane, 0 inside [mm].
double distance_to_wall(const engine::Wall& wall, double x, double y) {
  const double c = std::cos(wall.yaw), s = std::sin(wall.yaw);
  const double dx = x - wall.center_x, dy = y - wall.center_y;
  const double along = std::max(std::abs(c * dx + s * dy) - wall.half_length, 0.0);
  const double across = std::max(std::abs(-s * dx + c * dy) - wall.half_thickness, 0.0);
  return std::hypot(along, across);
}

bool touches_a_wall(const std::vector<Disc>& discs, const std::vector<engine::Wall>& walls) {
  for (const engine::Wall& wall : walls) {
    for (const Disc& disc : discs) {
      if (distance_to_wall(wall, disc.x, disc.y) < disc.radius + kPlacementClearance) return true;
    }
  }
  return false;
}

/// Tries a lattice of n x n sites; returns fewer than `count` rods when the sites run out.
std::vector<engine::RodInit> try_lattice(const engine::RodShape& shape, int count, int n,
                                         double box_x, double box_y,
                                         const std::vector<engine::Wall>& walls,
                                         engine::RandomStream& random) {
  const double spacing_x = box_x / n, spacing_y = box_y / n;
  double reach = 0.0;
  for (const engine::Sphere& sphere : shape.spheres) {
    reach = std::max(reach, std::abs(sphere.axial) + sphere.radius);
  }
  // Rods at sites further apart than this many sites cannot touch.
  const double spacing = std::min(spacing_x, spacing_y);
  const int neighbourhood =
      static_cast<int>(std::ceil((2.0 * reach + 2.0 * kJitter * spacing) / spacing));

  std::vector<int> order(static_cast<std::size_t>(n) * n);
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t k = order.size(); k > 1; --k) {  // Fisher-Yates with the seeded stream
    const auto pick = static_cast<std::size_t>(random.uniform() * static_cast<double>(k));
    std::swap(order[k - 1], order[std::min(pick, k - 1)]);
  }

  std::vector<int> rod_at(order.size(), -1);
  std::vector<std::vector<Disc>> placed;
  std::vector<engine::RodInit> rods;
  for (const int site : order) {
    if (static_cast<int>(rods.size()) == count) break;
    const int i = site % n, j = site / n;
    for (int attempt = 0; attempt < kTriesPerSite; ++attempt) {
      const double x = (i + 0.5 + kJitter * (2.0 * random.uniform() - 1.0)) * spacing_x;
      const double y = (j + 0.5 + kJitter * (2.0 * random.uniform() - 1.0)) * spacing_y;
      const double heading = 2.0 * kPi * random.uniform();
      const std::vector<Disc> discs = discs_of(shape, x, y, heading);
      if (touches_a_wall(discs, walls)) continue;
      bool free = true;
      for (int dj = -neighbourhood; dj <= neighbourhood && free; ++dj) {
        for (int di = -neighbourhood; di <= neighbourhood && free; ++di) {
          const int other =
              rod_at[static_cast<std::size_t>(((j + dj + n) % n) * n + (i + di + n) % n)];
          if (other >= 0 &&
              discs_overlap(discs, placed[static_cast<std::size_t>(other)], box_x, box_y)) {
            free = false;
          }
        }
      }
      if (!free) continue;
      rod_at[static_cast<std::size_t>(site)] = static_cast<int>(rods.size());
      placed.push_back(discs);
      rods.push_back({0, x, y, heading});
      break;
    }
  }
  return rods;
}

}  // namespace

std::vector<engine::RodInit> place_on_lattice(const engine::RodShape& shape, int count,
                                              double box_x, double box_y,
                                              const std::vector<engine::Wall>& walls,
                                              engine::RandomStream& random) {
  const int coarsest = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  // A finer lattice has more sites to spare for those a wall or a neighbour blocks.
  for (int n = coarsest; n <= 2 * coarsest; ++n) {
    std::vector<engine::RodInit> rods = try_lattice(shape, count, n, box_x, box_y, walls, random);
    if (static_cast<int>(rods.size()) == count) return rods;
  }
  throw std::runtime_error("cannot place " + std::to_string(count) + " rods in a cell of " +
                           std::to_string(box_x) + " x " + std::to_string(box_y) + " mm");
}

}  // namespace rodsort::bench
