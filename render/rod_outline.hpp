#pragma once
// The outline of a rod seen from above: the boundary of the union of its spheres' discs, as the
// arcs that make it up. Drawn as one path, a rod is filled once instead of once per sphere, which
// makes a frame of hundreds of rods several times faster to draw and its SVG several times smaller.
//
// The spheres' centres lie on the axis, so the union is symmetric about it and its upper half is
// the upper envelope of semicircles: above the point x of the axis, disc i reaches
// sqrt(r_i^2 - (x - a_i)^2), and the highest disc is the one maximising
// r_i^2 - (x - a_i)^2 + x^2 = 2 a_i x + r_i^2 - a_i^2, a line in x. The outline's arcs are thus the
// pieces of the upper envelope of lines (one per disc), and a disc hidden inside the others never
// appears.
//
// Neighbouring spheres need not overlap: rod A's preset (9 spheres, radii 0.55 -> 0.20 mm over
// 4.5 mm) leaves its thin-tip sphere 0.025 mm clear of the next one. The union is then several
// pieces, and the outline one loop per piece.

#include <vector>

#include "engine/rod_shape.hpp"

namespace rodsort::render {

/// A piece of one disc's circle on the outline, in the frame of a rod lying along +x with its
/// centre of mass at the origin: angles from +x (the thin end), counter-clockwise [rad].
struct OutlineArc {
  double axial;   ///< the disc's centre on the axis [mm]
  double radius;  ///< [mm]
  double from;    ///< start angle [rad]
  double to;      ///< end angle [rad]; loops run clockwise, so to <= from
};

/// One closed loop, clockwise from its leftmost point (toward the thick end): along the upper side
/// to its rightmost point, and back along the lower side.
using OutlineLoop = std::vector<OutlineArc>;

/// The loops of the union's outline, from the thick end to the thin end: one per separate piece.
std::vector<OutlineLoop> rod_outline(const engine::RodShape& shape);

}  // namespace rodsort::render
