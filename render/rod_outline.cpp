#include "render/rod_outline.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

namespace rodsort::render {
namespace {

constexpr double kPi = 3.141592653589793;

/// The angle above the axis at which disc `sphere` reaches the point x of the axis.
double upper_angle(const engine::Sphere& sphere, double x) {
  return std::acos(std::clamp((x - sphere.axial) / sphere.radius, -1.0, 1.0));
}

/// Where disc j overtakes disc i in the upper envelope (a_j > a_i).
double crossing(const engine::Sphere& i, const engine::Sphere& j) {
  return ((i.radius * i.radius - i.axial * i.axial) - (j.radius * j.radius - j.axial * j.axial)) /
         (2.0 * (j.axial - i.axial));
}

double left_end(const engine::Sphere& sphere) { return sphere.axial - sphere.radius; }
double right_end(const engine::Sphere& sphere) { return sphere.axial + sphere.radius; }

/// The disc whose left end is leftmost among those reaching right of `beyond`, if any.
std::optional<std::size_t> leftmost_beyond(const std::vector<engine::Sphere>& spheres,
                                           double beyond) {
  std::optional<std::size_t> found;
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    if (right_end(spheres[s]) <= beyond) continue;
    if (!found || left_end(spheres[s]) < left_end(spheres[*found])) found = s;
  }
  return found;
}

struct Piece {
  std::size_t sphere;
  double from_x, to_x;
};

/// The upper envelope of one connected piece of the union, left to right, from disc `owner`'s
/// left end. Each piece ends where a disc further right overtakes the owner (the first crossing;
/// the steepest line when several cross there), or at the owner's own right end, which is then the
/// right end of the union's piece.
std::vector<Piece> upper_envelope(const std::vector<engine::Sphere>& spheres, std::size_t owner) {
  std::vector<Piece> pieces;
  double x = left_end(spheres[owner]);
  for (;;) {
    const engine::Sphere& current = spheres[owner];
    double next_x = right_end(current);
    std::size_t next_owner = owner;
    for (std::size_t s = 0; s < spheres.size(); ++s) {
      if (spheres[s].axial <= current.axial) continue;
      const double at = crossing(current, spheres[s]);
      if (at <= x) continue;
      if (at < next_x ||
          (at == next_x && next_owner != owner && spheres[s].axial > spheres[next_owner].axial)) {
        next_x = at;
        next_owner = s;
      }
    }
    pieces.push_back({owner, x, next_x});
    if (next_owner == owner) return pieces;
    owner = next_owner;
    x = next_x;
  }
}

}  // namespace

std::vector<OutlineLoop> rod_outline(const engine::RodShape& shape) {
  const std::vector<engine::Sphere>& spheres = shape.spheres;
  assert(!spheres.empty());
  std::vector<OutlineLoop> loops;
  double done_to = -std::numeric_limits<double>::infinity();
  while (const std::optional<std::size_t> first = leftmost_beyond(spheres, done_to)) {
    const std::vector<Piece> pieces = upper_envelope(spheres, *first);
    OutlineLoop loop;
    for (const Piece& piece : pieces) {
      const engine::Sphere& sphere = spheres[piece.sphere];
      loop.push_back({sphere.axial, sphere.radius, upper_angle(sphere, piece.from_x),
                      upper_angle(sphere, piece.to_x)});
    }
    for (auto piece = pieces.rbegin(); piece != pieces.rend(); ++piece) {
      const engine::Sphere& sphere = spheres[piece->sphere];
      loop.push_back({sphere.axial, sphere.radius, -upper_angle(sphere, piece->to_x),
                      -upper_angle(sphere, piece->from_x)});
    }
    // The piece's ends lie on the axis: exact angles there, where acos is steepest.
    loop.front().from = kPi;
    loop[pieces.size() - 1].to = 0.0;
    loop[pieces.size()].from = 0.0;
    loop.back().to = -kPi;
    loops.push_back(std::move(loop));
    done_to = pieces.back().to_x;
  }
  return loops;
}

}  // namespace rodsort::render
