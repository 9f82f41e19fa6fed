// Mass properties of a union of spheres.
//
// The paper models a rod as overlapping spheres. Adding the spheres' masses would count every
// overlap twice (for rod A about 30% too heavy), so the mass, centre of mass and inertia here are
// those of the union.
//
// A straight rod, every sphere centred on its axis, is integrated exactly. A slice of the union at
// axial coordinate s is then a single disc of radius R(s), with
//
//   R(s)^2 = max_i f_i(s),   f_i(s) = r_i^2 - (s - a_i)^2   (where positive),
//
// and every mass property is a one-dimensional integral over s. All f_i share the same leading
// term -s^2, so f_i - f_j is linear in s: two spheres swap dominance at most once. Cutting the axis
// at every sphere end (a_i +- r_i) and at every pairwise crossing leaves pieces on which a single
// sphere dominates (or none: a gap between disjoint spheres). On such a piece R^2 is a quadratic in
// s, so the volume, first and second moments are polynomials of degree at most 4, integrated
// exactly by 3-point Gauss-Legendre; the projected width 2 R(s) has a closed-form antiderivative.
// The result is exact up to rounding, for any number of spheres, overlapping or not.
//
// A rod with spheres off its axis (all in the body's x-y plane, e.g. an RnT whose thin part is not
// coaxial with its thick part) has slices that are unions of discs with different centres, and no
// such closed form. Its integrals are taken over lines parallel to the axis instead: each sphere
// cuts a line at (y, z) in one interval, the union of the intervals is exact, and so are the
// integrals of 1, x and x^2 along it. The lines stand on a midpoint grid across the rod; the sum
// converges as the grid's spacing to the power 3/2 (the chords fall to zero as a square root at the
// outline), which at the grid below puts the mass and inertia within a few parts in 10^5 of the
// exact values (tested on a straight rod against the exact path, and on disjoint spheres). The
// body frame is then turned onto the principal axes, so that Bullet's diagonal inertia is the
// rod's: x becomes the axis of least inertia, leaning from the profile's axis by a small angle.

#include "engine/rod_shape.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/units.hpp"

namespace rodsort::engine {

namespace {

/// Spheres placed for a step profile are at most this far apart, in units of their radius: the
/// outline between two neighbours then dips by at most 10% of the radius
/// (1 - sqrt(1 - (0.872 / 2)^2) = 0.10), about as deep as between rod A's thick spheres.
constexpr double kMaxSpacingOverRadius = 0.872;

/// A stretch of the axis [begin, end] on which one sphere bounds the union.
struct Piece {
  double begin;  ///< [mm]
  double end;    ///< [mm]
  Sphere sphere;
};

double squared_section_radius(const Sphere& sphere, double axial) {
  const double offset = axial - sphere.axial;
  return sphere.radius * sphere.radius - offset * offset;
}

/// Cuts the axis into pieces on each of which one sphere is the outermost; gaps are left out.
std::vector<Piece> union_pieces(const std::vector<Sphere>& spheres) {
  std::vector<double> cuts;
  for (const Sphere& sphere : spheres) {
    cuts.push_back(sphere.axial - sphere.radius);
    cuts.push_back(sphere.axial + sphere.radius);
  }
  const double first = *std::min_element(cuts.begin(), cuts.end());
  const double last = *std::max_element(cuts.begin(), cuts.end());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    for (std::size_t j = i + 1; j < spheres.size(); ++j) {
      const Sphere& p = spheres[i];
      const Sphere& q = spheres[j];
      if (p.axial == q.axial) continue;  // concentric: one contains the other everywhere
      // f_p(s) = f_q(s) is linear in s.
      const double crossing =
          (p.radius * p.radius - q.radius * q.radius - p.axial * p.axial + q.axial * q.axial) /
          (2.0 * (q.axial - p.axial));
      if (crossing > first && crossing < last) cuts.push_back(crossing);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  std::vector<Piece> pieces;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double middle = 0.5 * (cuts[k] + cuts[k + 1]);
    const Sphere* outermost = nullptr;
    double best = 0.0;
    for (const Sphere& sphere : spheres) {
      const double value = squared_section_radius(sphere, middle);
      if (value > best) {
        best = value;
        outermost = &sphere;
      }
    }
    if (outermost == nullptr) continue;  // a gap between disjoint spheres
    if (!pieces.empty() && pieces.back().end == cuts[k] &&
        pieces.back().sphere.axial == outermost->axial &&
        pieces.back().sphere.radius == outermost->radius) {
      pieces.back().end = cuts[k + 1];
    } else {
      pieces.push_back({cuts[k], cuts[k + 1], *outermost});
    }
  }
  return pieces;
}

/// Integral of integrand(s, R^2(s)) over the union; exact for polynomials of degree <= 5 in s.
template <typename Integrand>
double integrate(const std::vector<Piece>& pieces, Integrand integrand) {
  static const double kNode = std::sqrt(3.0 / 5.0);
  static constexpr std::array<double, 3> kWeights = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const std::array<double, 3> nodes = {-kNode, 0.0, kNode};
  double total = 0.0;
  for (const Piece& piece : pieces) {
    const double half = 0.5 * (piece.end - piece.begin);
    const double middle = 0.5 * (piece.end + piece.begin);
    double sum = 0.0;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const double axial = middle + half * nodes[n];
      sum += kWeights[n] * integrand(axial, squared_section_radius(piece.sphere, axial));
    }
    total += half * sum;
  }
  return total;
}

/// Area of the union's outline in a plane through the axis: the integral of 2 R(s).
double projected_area(const std::vector<Piece>& pieces) {
  double area = 0.0;
  for (const Piece& piece : pieces) {
    const double radius = piece.sphere.radius;
    // Antiderivative of 2 sqrt(r^2 - u^2) in u = s - a. The tips sit where the square root is
    // steep, so the half-chord is taken as sqrt((r - u)(r + u)) and the angle by atan2: the
    // rounding of a piece's ends then stays at rounding level in the area.
    const auto primitive = [radius](double u) {
      u = std::clamp(u, -radius, radius);
      const double half_chord = std::sqrt((radius - u) * (radius + u));
      return u * half_chord + radius * radius * std::atan2(u, half_chord);
    };
    area += primitive(piece.end - piece.sphere.axial) - primitive(piece.begin - piece.sphere.axial);
  }
  return area;
}

/// Adds spheres of one radius, centres evenly spread from first to last [mm], no further apart
/// than kMaxSpacingOverRadius radii.
void add_evenly_spaced(std::vector<Sphere>& spheres, double first, double last, double radius) {
  const double span = last - first;
  // One sphere where the span is empty (an RnT step at the end of its range).
  const int intervals =
      span > 0.0
          ? std::max(1,
                     static_cast<int>(std::ceil(span / (kMaxSpacingOverRadius * radius) - 1e-12)))
          : 0;
  for (int k = 0; k <= intervals; ++k) {
    spheres.push_back({intervals == 0 ? first : first + span * k / intervals, radius});
  }
}

/// Moments of a union of spheres over the whole body, in the profile's frame: the integrals of
/// 1, x, y, x^2, y^2, z^2 and x y [mm^3 times mm^k].
struct Moments {
  double volume = 0.0, x = 0.0, y = 0.0, xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0;
};

/// Lines across the rod for an off-axis union: this many midpoint cells over its extent in y, and
/// half as many over z >= 0 (the union is mirror symmetric in z).
constexpr int kLinesAcross = 800;

/// The union's extent across the axis: y from y_low to y_high, |z| up to z_high [mm].
struct Extent {
  double y_low = std::numeric_limits<double>::infinity();
  double y_high = -std::numeric_limits<double>::infinity();
  double z_high = 0.0;
};

Extent extent_across(const std::vector<Sphere>& spheres) {
  Extent extent;
  for (const Sphere& sphere : spheres) {
    extent.y_low = std::min(extent.y_low, sphere.lateral - sphere.radius);
    extent.y_high = std::max(extent.y_high, sphere.lateral + sphere.radius);
    extent.z_high = std::max(extent.z_high, sphere.radius);
  }
  return extent;
}

/// Calls visit(begin, end) for each interval in which the line parallel to the axis through
/// (y, z) crosses the union, the overlapping chords of its spheres merged. `chords` is scratch.
template <typename Visit>
void for_each_crossing(const std::vector<Sphere>& spheres, double y, double z,
                       std::vector<std::pair<double, double>>& chords, Visit visit) {
  chords.clear();
  for (const Sphere& sphere : spheres) {
    const double across = (y - sphere.lateral) * (y - sphere.lateral) + z * z;
    const double half2 = sphere.radius * sphere.radius - across;
    if (half2 <= 0.0) continue;
    const double half = std::sqrt(half2);
    chords.emplace_back(sphere.axial - half, sphere.axial + half);
  }
  if (chords.empty()) return;
  std::sort(chords.begin(), chords.end());
  double begin = chords.front().first, end = chords.front().second;
  for (const auto& [b, e] : chords) {
    if (b > end) {
      visit(begin, end);
      begin = b;
    }
    end = std::max(end, e);
  }
  visit(begin, end);
}

Moments off_axis_moments(const std::vector<Sphere>& spheres) {
  const Extent extent = extent_across(spheres);
  const int y_cells = kLinesAcross;
  const int z_cells = kLinesAcross / 2;
  const double dy = (extent.y_high - extent.y_low) / y_cells;
  const double dz = extent.z_high / z_cells;
  const double weight = 2.0 * dy * dz;  // each z > 0 cell stands for its mirror image too
  std::vector<std::pair<double, double>> chords;
  Moments sum;
  for (int iy = 0; iy < y_cells; ++iy) {
    const double y = extent.y_low + (iy + 0.5) * dy;
    for (int iz = 0; iz < z_cells; ++iz) {
      const double z = (iz + 0.5) * dz;
      // The integrals of 1, x and x^2 along the line.
      double length = 0.0, first = 0.0, second = 0.0;
      for_each_crossing(spheres, y, z, chords, [&](double begin, double end) {
        length += end - begin;
        first += 0.5 * (end - begin) * (end + begin);
        second += (end * end * end - begin * begin * begin) / 3.0;
      });
      sum.volume += weight * length;
      sum.x += weight * first;
      sum.y += weight * y * length;
      sum.xx += weight * second;
      sum.yy += weight * y * y * length;
      sum.zz += weight * z * z * length;
      sum.xy += weight * y * first;
    }
  }
  return sum;
}

/// Area of the union's outline in the x-y plane (the discs of the spheres' great circles there):
/// the lengths of the lines at z = 0, on a fine midpoint grid in y.
double off_axis_projected_area(const std::vector<Sphere>& spheres) {
  constexpr int kLines = 20000;
  const Extent extent = extent_across(spheres);
  const double dy = (extent.y_high - extent.y_low) / kLines;
  std::vector<std::pair<double, double>> chords;
  double area = 0.0;
  for (int iy = 0; iy < kLines; ++iy) {
    const double y = extent.y_low + (iy + 0.5) * dy;
    for_each_crossing(spheres, y, 0.0, chords,
                      [&](double begin, double end) { area += dy * (end - begin); });
  }
  return area;
}

}  // namespace

RodProfile linear_taper_profile(double length, double thick_radius, double thin_radius,
                                int sphere_count) {
  if (!(thick_radius > 0.0) || !(thin_radius > 0.0)) {
    throw std::invalid_argument("linear_taper_profile: radii must be positive, got " +
                                std::to_string(thick_radius) + " and " +
                                std::to_string(thin_radius));
  }
  if (sphere_count < 2) {
    throw std::invalid_argument("linear_taper_profile: needs at least 2 spheres, got " +
                                std::to_string(sphere_count));
  }
  // The end spheres' far sides are the tips only if no inner sphere pokes past them, i.e. the
  // radius changes no faster than the centres move.
  const double span = length - thick_radius - thin_radius;
  if (!(span > 0.0) || std::abs(thick_radius - thin_radius) > span) {
    throw std::invalid_argument("linear_taper_profile: length " + std::to_string(length) +
                                " mm is too short for end radii " + std::to_string(thick_radius) +
                                " and " + std::to_string(thin_radius) + " mm");
  }
  RodProfile profile;
  for (int k = 0; k < sphere_count; ++k) {
    const double fraction = static_cast<double>(k) / (sphere_count - 1);
    profile.spheres.push_back(
        {thick_radius + span * fraction, thick_radius + (thin_radius - thick_radius) * fraction});
  }
  return profile;
}

RodProfile preset_a_profile() { return linear_taper_profile(4.5, 0.55, 0.20, 9); }

namespace {

/// How far before the step the last thick sphere of the RnT preset is centred, so that its outline
/// comes down to the thin radius at the step [mm].
double rnt_shoulder(double thin_radius, double thick_radius) {
  return std::sqrt(thick_radius * thick_radius - thin_radius * thin_radius);
}

}  // namespace

double rnt_step_min(double thin_radius, double thick_radius) {
  return thick_radius + rnt_shoulder(thin_radius, thick_radius);
}

double rnt_step_max(double thin_radius) { return kRntLength - thin_radius; }

std::vector<std::pair<double, double>> stepped_section_spans(double length,
                                                             const std::vector<double>& radii,
                                                             const std::vector<double>& steps) {
  if (radii.empty() || steps.size() + 1 != radii.size()) {
    throw std::invalid_argument("stepped_section_spans: expected one fewer step than radii, got " +
                                std::to_string(steps.size()) + " and " +
                                std::to_string(radii.size()));
  }
  std::vector<std::pair<double, double>> spans;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double radius = radii[i];
    const double first = i == 0 ? radius : steps[i - 1];
    // The last sphere of a section is placed so that its outline comes down to the next radius
    // exactly at the step, and the next section's first sphere is centred there, so the two meet
    // at the step and each section keeps its full radius as far as spheres allow.
    const double last = i + 1 == radii.size()
                            ? length - radius
                            : steps[i] - std::sqrt(radius * radius - radii[i + 1] * radii[i + 1]);
    spans.emplace_back(first, last);
  }
  return spans;
}

namespace {

/// stepped_profile, and where each section's spheres begin in the profile.
RodProfile stepped_sections(double length, const std::vector<double>& radii,
                            const std::vector<double>& steps,
                            std::vector<std::size_t>& section_starts) {
  // Checks that there is one fewer step than radii before the order is read.
  const std::vector<std::pair<double, double>> spans = stepped_section_spans(length, radii, steps);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const bool radius_ok = radii[i] > 0.0 && (i + 1 == radii.size() || radii[i + 1] <= radii[i]);
    const bool step_ok =
        i == 0 || (steps[i - 1] > (i == 1 ? 0.0 : steps[i - 2]) && steps[i - 1] < length);
    if (!radius_ok || !step_ok) {
      throw std::invalid_argument(
          "stepped_profile: radii must be positive and not grow, steps grow within the length; "
          "section " +
          std::to_string(i) + " is out of order");
    }
  }
  RodProfile profile;
  section_starts.clear();
  for (std::size_t i = 0; i < spans.size(); ++i) {
    section_starts.push_back(profile.spheres.size());
    // A section exactly one sphere long may come out a rounding error short.
    if (spans[i].second < spans[i].first - 1e-12) {
      throw std::invalid_argument("stepped_profile: section " + std::to_string(i) + " (radius " +
                                  std::to_string(radii[i]) + " mm) has no room for one sphere");
    }
    add_evenly_spaced(profile.spheres, spans[i].first, spans[i].second, radii[i]);
  }
  return profile;
}

}  // namespace

RodProfile stepped_profile(double length, const std::vector<double>& radii,
                           const std::vector<double>& steps) {
  std::vector<std::size_t> section_starts;
  return stepped_sections(length, radii, steps, section_starts);
}

RodProfile preset_rnt_profile(double thin_radius, double step, double thick_radius,
                              double thin_offset) {
  if (!(thin_radius > 0.0) || !(thin_radius <= thick_radius)) {
    throw std::invalid_argument("preset_rnt_profile: thin radius must be in (0, " +
                                std::to_string(thick_radius) + "] mm, got " +
                                std::to_string(thin_radius));
  }
  const double step_min = rnt_step_min(thin_radius, thick_radius);
  if (!(step >= step_min) || !(step <= rnt_step_max(thin_radius))) {
    throw std::invalid_argument("preset_rnt_profile: step must be in [" + std::to_string(step_min) +
                                ", " + std::to_string(rnt_step_max(thin_radius)) + "] mm, got " +
                                std::to_string(step));
  }
  std::vector<std::size_t> section_starts;
  RodProfile profile =
      stepped_sections(kRntLength, {thick_radius, thin_radius}, {step}, section_starts);
  for (std::size_t k = section_starts[1]; k < profile.spheres.size(); ++k) {
    profile.spheres[k].lateral = thin_offset;
  }
  return profile;
}

void bend_profile(RodProfile& profile, double length, double sagitta, BendForm form) {
  for (Sphere& sphere : profile.spheres) {
    const double u = 2.0 * sphere.axial / length - 1.0;  // -1 at the thick tip, +1 at the thin
    sphere.lateral +=
        sagitta * (form == BendForm::arc ? 1.0 - u * u : std::sin(kPi * u));
  }
}

bool is_straight(const std::vector<Sphere>& spheres) {
  return std::all_of(spheres.begin(), spheres.end(),
                     [](const Sphere& sphere) { return sphere.lateral == 0.0; });
}

RodShape make_rod_shape(const RodProfile& profile, double density) {
  if (profile.spheres.empty()) {
    throw std::invalid_argument("make_rod_shape: the profile has no spheres");
  }
  for (const Sphere& sphere : profile.spheres) {
    if (!(sphere.radius > 0.0) || !std::isfinite(sphere.radius) || !std::isfinite(sphere.axial) ||
        !std::isfinite(sphere.lateral)) {
      throw std::invalid_argument("make_rod_shape: sphere at " + std::to_string(sphere.axial) +
                                  " mm has radius " + std::to_string(sphere.radius) +
                                  " mm; radii must be positive and finite");
    }
  }
  if (!(density > 0.0) || !std::isfinite(density)) {
    throw std::invalid_argument("make_rod_shape: density must be positive, got " +
                                std::to_string(density));
  }

  RodShape shape{};
  shape.density = density;
  const bool straight = is_straight(profile.spheres);
  // The centre of mass in the profile's frame, and the unit vectors of the principal axes x and y
  // there (z stays z: every sphere lies in the x-y plane).
  double center_x = 0.0, center_y = 0.0;
  Eigen::Vector2d principal_x(1.0, 0.0);
  if (straight) {
    const std::vector<Piece> pieces = union_pieces(profile.spheres);
    const double volume = integrate(pieces, [](double, double r2) { return kPi * r2; });
    center_x = integrate(pieces, [](double s, double r2) { return kPi * r2 * s; }) / volume;
    const double axial_moment =
        integrate(pieces, [](double, double r2) { return 0.5 * kPi * r2 * r2; });
    const double transverse_moment = integrate(pieces, [center_x](double s, double r2) {
      return kPi * (0.25 * r2 * r2 + r2 * (s - center_x) * (s - center_x));
    });
    shape.volume = volume;
    shape.inertia_axial = density * axial_moment;
    shape.inertia_transverse = density * transverse_moment;
    shape.inertia_normal = shape.inertia_transverse;
    shape.projected_area = projected_area(pieces);
  } else {
    const Moments m = off_axis_moments(profile.spheres);
    center_x = m.x / m.volume;
    center_y = m.y / m.volume;
    // Second moments about the centre of mass.
    const double xx = m.xx - m.volume * center_x * center_x;
    const double yy = m.yy - m.volume * center_y * center_y;
    const double xy = m.xy - m.volume * center_x * center_y;
    Eigen::Matrix2d in_plane;  // the inertia tensor's x-y block, per unit density
    in_plane << yy + m.zz, -xy, -xy, xx + m.zz;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(in_plane);
    principal_x = principal.eigenvectors().col(0);          // the least moment: the rod's long axis
    if (principal_x.x() < 0.0) principal_x = -principal_x;  // still from the thick to the thin end
    shape.volume = m.volume;
    shape.inertia_axial = density * principal.eigenvalues()(0);
    shape.inertia_transverse = density * principal.eigenvalues()(1);
    shape.inertia_normal = density * (xx + yy);
    shape.projected_area = off_axis_projected_area(profile.spheres);
  }
  shape.mass = density * shape.volume;
  shape.axis_lean = std::atan2(principal_x.y(), principal_x.x());
  shape.thick_tip = std::numeric_limits<double>::infinity();
  shape.thin_tip = -std::numeric_limits<double>::infinity();
  shape.max_radius = 0.0;
  shape.max_lateral = 0.0;
  for (const Sphere& sphere : profile.spheres) {
    Sphere centred{sphere.axial - center_x, sphere.radius};
    if (!straight) {
      const Eigen::Vector2d from_center(sphere.axial - center_x, sphere.lateral - center_y);
      centred.axial = principal_x.dot(from_center);
      centred.lateral = principal_x.x() * from_center.y() - principal_x.y() * from_center.x();
    }
    shape.spheres.push_back(centred);
    shape.thick_tip = std::min(shape.thick_tip, centred.axial - centred.radius);
    shape.thin_tip = std::max(shape.thin_tip, centred.axial + centred.radius);
    shape.max_radius = std::max(shape.max_radius, centred.radius);
    shape.max_lateral = std::max(shape.max_lateral, std::abs(centred.lateral));
  }
  shape.length = shape.thin_tip - shape.thick_tip;
  return shape;
}

}  // namespace rodsort::engine
