#pragma once
// A rod is a union of spheres, centred on its axis or, for a rod that is not straight, off it in
// one plane. Its mass, centre of mass and inertia are those of the union (overlaps counted once),
// not the sum of the spheres.

#include <string>
#include <utility>
#include <vector>

namespace rodsort::engine {

/// The RnT preset's length, tip to tip, and the radius of its thick part [mm].
inline constexpr double kRntLength = 3.5;
inline constexpr double kRntThickRadius = 0.55;
inline constexpr double kRntThinRadius = 0.3;  ///< the preset's thin part [mm]

/// One sphere of a rod profile.
struct Sphere {
  double
      axial;  ///< position of the centre on the rod axis [mm]; grows from the thick to the thin end
  double radius;  ///< [mm]
  /// Offset of the centre from the axis, along the body's y axis [mm]: 0 for a straight rod. Every
  /// off-axis sphere lies in the body's x-y plane.
  double lateral = 0.0;
};

/// The spheres of a rod, in any axial frame (the shape recentres them on the centre of mass).
struct RodProfile {
  std::vector<Sphere> spheres;
};

/// Paper rod A: 9 spheres, radii linear 0.55 -> 0.20 mm, 4.5 mm tip to tip.
RodProfile preset_a_profile();
/// Paper RnT rod: 3.5 mm tip to tip, thick part r = thick_radius (0.55 mm, the paper's) from the
/// thick tip to the step, `step` mm from the thick tip (mid-length by default), thin part
/// r = thin_radius beyond it.
/// `thin_offset`: the thin part's axis lies that far from the thick part's, parallel to it [mm].
RodProfile preset_rnt_profile(double thin_radius = kRntThinRadius, double step = kRntLength / 2,
                              double thick_radius = kRntThickRadius, double thin_offset = 0.0);
/// How a rod is bent in the plane of its offsets, `sagitta` being the largest offset from the
/// straight axis through its tips: `arc`, the centres on a parabola through the tips, bulging by
/// the sagitta at mid-length; `s`, one sine wave along the rod, its thick half to one side and its
/// thin half to the other, the tips and mid-length on the straight axis.
enum class BendForm { arc, s };
/// Adds the bend to every sphere's lateral offset, at its axial position measured from the thick
/// tip of a rod `length` long [mm].
void bend_profile(RodProfile& profile, double length, double sagitta, BendForm form);
/// A rod of cylinders in steps, thick end first, `length` tip to tip [mm]: section i has radius
/// radii[i] and begins at steps[i - 1] from the thick tip (the first at the tip); one fewer step
/// than radii, the steps growing, the radii not. Each section is built as the RnT preset's two
/// are: its spheres evenly spaced at most 0.872 radii apart, from the one touching the thick tip
/// (or centred on the section's step) to the one whose outline comes down to the next radius
/// exactly at the next step (or that touches the thin tip). With radii {thick, thin} and steps
/// {step} it is the RnT preset's profile. Throws std::invalid_argument for radii and steps out of
/// that order or a section with no room for one sphere (stepped_section_spans says which).
RodProfile stepped_profile(double length, const std::vector<double>& radii,
                           const std::vector<double>& steps);
/// Where the sphere centres of each section of stepped_profile run, first to last [mm]: a section
/// whose last comes before its first has no room for one sphere. Radii and steps as there; the
/// sizes must match (one fewer step than radii) and each radius be at least the next.
std::vector<std::pair<double, double>> stepped_section_spans(double length,
                                                             const std::vector<double>& radii,
                                                             const std::vector<double>& steps);
/// Where the RnT preset's step may lie, from the thick tip [mm], for given radii: far enough from
/// the thick tip for one whole thick sphere, and from the thin tip for one thin sphere.
double rnt_step_min(double thin_radius, double thick_radius = kRntThickRadius);
double rnt_step_max(double thin_radius);
/// `sphere_count` spheres, radii linear from thick_radius to thin_radius, `length` tip to tip [mm].
RodProfile linear_taper_profile(double length, double thick_radius, double thin_radius,
                                int sphere_count);

/// Whether every sphere is centred on the axis (no lateral offset).
bool is_straight(const std::vector<Sphere>& spheres);

/// A rod ready for the engine: spheres relative to the centre of mass, and the mass properties of
/// their union. The body axes are the union's principal axes: for a straight rod x is the rod's
/// axis; for one with off-axis spheres, x is its axis of least inertia, which leans from the
/// profile's axis by `axis_lean` within the plane of the offsets.
struct RodShape {
  std::vector<Sphere>
      spheres;                ///< positions measured from the centre of mass, on the body axes [mm]
  double density;             ///< [g/mm^3]
  double volume;              ///< of the union [mm^3]
  double mass;                ///< [g]
  double inertia_axial;       ///< about the body x axis through the centre of mass [g mm^2]
  double inertia_transverse;  ///< about the body y axis through the centre of mass [g mm^2]
  double
      inertia_normal;  ///< about the body z axis, = inertia_transverse for a straight rod [g mm^2]
  double axis_lean;    ///< angle from the profile's axis to the body x axis [rad]
  double projected_area;     ///< area of the union's outline in the body x-y plane [mm^2]
  double length;             ///< tip to tip [mm]
  double max_radius;         ///< largest sphere radius [mm]
  double max_lateral = 0.0;  ///< largest |lateral| of a sphere, 0 for a straight rod [mm]
  double thick_tip;          ///< axial position of the thick tip, from the centre of mass [mm] (<0)
  double thin_tip;           ///< axial position of the thin tip, from the centre of mass [mm] (>0)
};

/// Computes the union's mass properties and recentres the profile on its centre of mass, turned
/// onto its principal axes. Exact up to rounding for a straight rod; with off-axis spheres the
/// integrals are taken on a grid across the rod, to a few parts in 10^5 (rod_shape.cpp).
RodShape make_rod_shape(const RodProfile& profile, double density);

}  // namespace rodsort::engine
