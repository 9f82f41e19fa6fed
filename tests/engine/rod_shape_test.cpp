#include "engine/rod_shape.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/units.hpp"

using rodsort::kBrassDensity;
using rodsort::kPi;
using namespace rodsort::engine;

namespace {

double sphere_volume(double radius) { return 4.0 / 3.0 * kPi * radius * radius * radius; }

/// Volume of a spherical cap of height `height` cut from a sphere of radius `radius`.
double cap_volume(double radius, double height) {
  return kPi * height * height * (3.0 * radius - height) / 3.0;
}

/// Distance from the sphere's centre to the centroid of that cap.
double cap_centroid(double radius, double height) {
  return 3.0 * (2.0 * radius - height) * (2.0 * radius - height) / (4.0 * (3.0 * radius - height));
}

}  // namespace

TEST_CASE("one sphere has the closed-form mass properties", "[rod_shape]") {
  const double radius = 0.7;
  const RodShape shape = make_rod_shape({{{2.5, radius}}}, 2.0);
  const double mass = 2.0 * sphere_volume(radius);
  CHECK(shape.volume == Approx(sphere_volume(radius)).epsilon(1e-12));
  CHECK(shape.mass == Approx(mass).epsilon(1e-12));
  CHECK(shape.inertia_axial == Approx(0.4 * mass * radius * radius).epsilon(1e-12));
  CHECK(shape.inertia_transverse == Approx(0.4 * mass * radius * radius).epsilon(1e-12));
  CHECK(shape.projected_area == Approx(kPi * radius * radius).epsilon(1e-12));
  REQUIRE(shape.spheres.size() == 1);
  CHECK(shape.spheres[0].axial == Approx(0.0).margin(1e-12));
  CHECK(shape.length == Approx(2.0 * radius));
  CHECK(shape.thick_tip == Approx(-radius));
  CHECK(shape.thin_tip == Approx(radius));
  CHECK(shape.max_radius == radius);
}

TEST_CASE("two disjoint spheres add up with the parallel-axis theorem", "[rod_shape]") {
  const double big = 0.5, small = 0.3, distance = 2.0;
  const RodShape shape = make_rod_shape({{{1.0, big}, {1.0 + distance, small}}}, 1.0);
  const double big_mass = sphere_volume(big), small_mass = sphere_volume(small);
  const double mass = big_mass + small_mass;
  const double com_from_big = small_mass * distance / mass;
  CHECK(shape.mass == Approx(mass).epsilon(1e-12));
  CHECK(shape.spheres[0].axial == Approx(-com_from_big).epsilon(1e-12));
  CHECK(shape.spheres[1].axial == Approx(distance - com_from_big).epsilon(1e-12));
  const double own = 0.4 * (big_mass * big * big + small_mass * small * small);
  CHECK(shape.inertia_axial == Approx(own).epsilon(1e-12));
  const double shifted = big_mass * com_from_big * com_from_big +
                         small_mass * (distance - com_from_big) * (distance - com_from_big);
  CHECK(shape.inertia_transverse == Approx(own + shifted).epsilon(1e-12));
  CHECK(shape.projected_area == Approx(kPi * (big * big + small * small)).epsilon(1e-12));
  CHECK(shape.length == Approx(distance + big + small));
  CHECK(shape.thick_tip == Approx(-com_from_big - big));
}

TEST_CASE("two overlapping equal spheres count their lens once", "[rod_shape]") {
  const double radius = 0.5, distance = 0.6;
  const RodShape shape = make_rod_shape({{{0.0, radius}, {distance, radius}}}, 1.0);
  const double lens_volume = kPi * (4.0 * radius + distance) * (2.0 * radius - distance) *
                             (2.0 * radius - distance) / 12.0;
  CHECK(shape.volume == Approx(2.0 * sphere_volume(radius) - lens_volume).epsilon(1e-12));
  const double lens_area = 2.0 * radius * radius * std::acos(distance / (2.0 * radius)) -
                           0.5 * distance * std::sqrt(4.0 * radius * radius - distance * distance);
  CHECK(shape.projected_area == Approx(2.0 * kPi * radius * radius - lens_area).epsilon(1e-12));
  CHECK(shape.spheres[0].axial == Approx(-0.5 * distance).epsilon(1e-12));
  CHECK(shape.spheres[1].axial == Approx(0.5 * distance).epsilon(1e-12));
}

TEST_CASE("a sphere inside another adds nothing", "[rod_shape]") {
  const RodShape alone = make_rod_shape({{{0.0, 0.6}}}, 1.0);
  const RodShape nested = make_rod_shape({{{0.0, 0.6}, {0.2, 0.3}, {0.0, 0.6}}}, 1.0);
  CHECK(nested.volume == Approx(alone.volume).epsilon(1e-12));
  CHECK(nested.inertia_transverse == Approx(alone.inertia_transverse).epsilon(1e-12));
  CHECK(nested.projected_area == Approx(alone.projected_area).epsilon(1e-12));
}

TEST_CASE("a dense chain of tapered spheres approaches the envelope cone with spherical ends",
          "[rod_shape]") {
  // Spheres with centres a and radii r(a) = r0 + k (a - a0), |k| < 1, packed densely, fill the
  // envelope of the family: a cone whose radius at s is r(s) / sqrt(1 - k^2), touching the end
  // spheres at s = a - k r, closed by the end spheres beyond those planes. (The frustum with the
  // spheres' own radii and hemispherical ends is 0.7% smaller here: it is not the limit.)
  const double length = 4.5, thick = 0.55, thin = 0.20;
  const int count = 301;
  const RodShape shape = make_rod_shape(linear_taper_profile(length, thick, thin, count), 1.0);

  const double a0 = thick, a1 = length - thin;
  const double k = (thin - thick) / (a1 - a0);
  const double c = std::sqrt(1.0 - k * k);
  const double s0 = a0 - k * thick, s1 = a1 - k * thin;
  const double rho0 = thick * c, rho1 = thin * c;
  const double thick_cap_height = thick * (1.0 - k), thin_cap_height = thin * (1.0 + k);

  const double h = s1 - s0;
  const double frustum_sum = rho0 * rho0 + rho0 * rho1 + rho1 * rho1;
  const double frustum_volume = kPi * h * frustum_sum / 3.0;
  const double frustum_centroid =
      s0 + h * (rho0 * rho0 + 2.0 * rho0 * rho1 + 3.0 * rho1 * rho1) / (4.0 * frustum_sum);
  const double thick_cap = cap_volume(thick, thick_cap_height);
  const double thin_cap = cap_volume(thin, thin_cap_height);
  const double volume = frustum_volume + thick_cap + thin_cap;
  const double centroid = (frustum_volume * frustum_centroid +
                           thick_cap * (a0 - cap_centroid(thick, thick_cap_height)) +
                           thin_cap * (a1 + cap_centroid(thin, thin_cap_height))) /
                          volume;

  // The envelope's second moments, integrated finely from its closed-form radius.
  const auto envelope_squared_radius = [&](double s) {
    if (s < s0) return thick * thick - (s - a0) * (s - a0);
    if (s > s1) return thin * thin - (s - a1) * (s - a1);
    const double r = (thick + k * (s - a0)) / c;
    return r * r;
  };
  const int slices = 200000;
  const double ds = length / slices;
  double axial = 0.0, transverse = 0.0, area = 0.0;
  for (int n = 0; n < slices; ++n) {
    const double s = (n + 0.5) * ds;
    const double r2 = envelope_squared_radius(s);
    area += 2.0 * std::sqrt(std::max(0.0, r2)) * ds;
    axial += 0.5 * kPi * r2 * r2 * ds;
    transverse += kPi * (0.25 * r2 * r2 + r2 * (s - centroid) * (s - centroid)) * ds;
  }

  // The chain's outline dips between neighbouring spheres by about spacing^2 / (8 r) < 1e-4 mm
  // here, which leaves every property about 1e-4 short of the envelope's (it converges as
  // 1 / count^2); 1e-3 is the tolerance.
  CHECK(shape.volume == Approx(volume).epsilon(1e-3));
  CHECK(shape.volume < volume);
  CHECK(-shape.thick_tip == Approx(centroid).epsilon(1e-3));
  CHECK(shape.inertia_axial == Approx(axial).epsilon(1e-3));
  CHECK(shape.inertia_transverse == Approx(transverse).epsilon(1e-3));
  CHECK(shape.projected_area == Approx(area).epsilon(1e-3));
}

TEST_CASE("shapes do not depend on the profile's axial frame", "[rod_shape]") {
  RodProfile shifted = preset_a_profile();
  for (Sphere& sphere : shifted.spheres) sphere.axial -= 7.0;
  const RodShape reference = make_rod_shape(preset_a_profile(), kBrassDensity);
  const RodShape moved = make_rod_shape(shifted, kBrassDensity);
  const RodShape recentred = make_rod_shape({reference.spheres}, kBrassDensity);
  for (const RodShape* other : {&moved, &recentred}) {
    CHECK(other->mass == Approx(reference.mass).epsilon(1e-12));
    CHECK(other->inertia_transverse == Approx(reference.inertia_transverse).epsilon(1e-12));
    CHECK(other->thick_tip == Approx(reference.thick_tip).epsilon(1e-12));
    for (std::size_t i = 0; i < reference.spheres.size(); ++i) {
      CHECK(other->spheres[i].axial == Approx(reference.spheres[i].axial).margin(1e-12));
    }
  }
}

TEST_CASE("rod A has the paper's size and mass, heavier at the thick end", "[rod_shape]") {
  const RodProfile profile = preset_a_profile();
  REQUIRE(profile.spheres.size() == 9);
  CHECK(profile.spheres.front().radius == Approx(0.55));
  CHECK(profile.spheres.back().radius == Approx(0.20));
  const RodShape shape = make_rod_shape(profile, kBrassDensity);
  CHECK(shape.length == Approx(4.5));
  CHECK(shape.max_radius == Approx(0.55));
  CHECK(shape.volume == Approx(1.95).epsilon(0.01));
  CHECK(shape.mass == Approx(16.5e-3).epsilon(0.01));
  // The centre of mass lies toward the thick end, well short of mid-length.
  CHECK(-shape.thick_tip < 0.4 * shape.length);
  CHECK(shape.thin_tip - shape.thick_tip == Approx(shape.length));
  // Axial positions grow from the thick to the thin end.
  for (std::size_t i = 0; i + 1 < shape.spheres.size(); ++i) {
    CHECK(shape.spheres[i].axial < shape.spheres[i + 1].axial);
  }
  // A slender body: the transverse inertia dominates.
  CHECK(shape.inertia_transverse > 5.0 * shape.inertia_axial);
}

TEST_CASE("rod RnT steps from the thick to the thin radius at mid-length", "[rod_shape]") {
  const RodProfile profile = preset_rnt_profile();
  const RodShape shape = make_rod_shape(profile, kBrassDensity);
  CHECK(shape.length == Approx(3.5));
  CHECK(shape.max_radius == Approx(0.55));
  CHECK(profile.spheres.front().axial - profile.spheres.front().radius ==
        Approx(0.0).margin(1e-12));
  CHECK(profile.spheres.back().radius == Approx(0.3));
  // The thick half is as wide as the spheres allow up to mid-length, the thin half beyond.
  for (const Sphere& sphere : profile.spheres) {
    if (sphere.radius == Approx(0.55)) CHECK(sphere.axial < 1.75);
    if (sphere.radius == Approx(0.3)) CHECK(sphere.axial >= 1.75 - 1e-12);
  }
  // Neighbours overlap: the rod is one piece.
  for (std::size_t i = 0; i + 1 < profile.spheres.size(); ++i) {
    const Sphere& p = profile.spheres[i];
    const Sphere& q = profile.spheres[i + 1];
    CHECK(q.axial - p.axial < 0.9 * (p.radius + q.radius));
  }
  // Close to the ideal stepped outline (two stadium halves), short of it by the dips between
  // spheres and the rounded shoulder.
  const double ideal_area = 0.5 * kPi * 0.55 * 0.55 + 2.0 * 0.55 * (1.75 - 0.55) +
                            2.0 * 0.3 * (1.75 - 0.3) + 0.5 * kPi * 0.3 * 0.3;
  CHECK(shape.projected_area < ideal_area);
  CHECK(shape.projected_area > 0.95 * ideal_area);
  CHECK(-shape.thick_tip < 0.5 * shape.length);

  const RodShape thinner = make_rod_shape(preset_rnt_profile(0.25), kBrassDensity);
  CHECK(thinner.length == Approx(3.5));
  CHECK(thinner.mass < shape.mass);
}

TEST_CASE("rod RnT's step can lie anywhere that leaves a whole sphere on each side",
          "[rod_shape]") {
  for (const double thick : {0.45, 0.55}) {
    for (const double thin : {0.2, 0.3, 0.4}) {
      for (const double step : {rnt_step_min(thin, thick), 1.3, 1.75, 2.5, rnt_step_max(thin)}) {
        CAPTURE(thick, thin, step);
        const RodProfile profile = preset_rnt_profile(thin, step, thick);
        const RodShape shape = make_rod_shape(profile, kBrassDensity);
        CHECK(shape.length == Approx(3.5));
        CHECK(profile.spheres.front().axial - profile.spheres.front().radius ==
              Approx(0.0).margin(1e-12));
        for (const Sphere& sphere : profile.spheres) {
          if (sphere.radius == Approx(thick)) CHECK(sphere.axial < step);
          if (sphere.radius == Approx(thin)) CHECK(sphere.axial >= step - 1e-12);
        }
        // The last thick sphere's outline comes down to the thin radius at the step.
        const auto first_thin = std::find_if(profile.spheres.begin(), profile.spheres.end(),
                                             [thin](const Sphere& s) { return s.radius == thin; });
        REQUIRE(first_thin != profile.spheres.begin());
        const Sphere& last_thick = *(first_thin - 1);
        CHECK(last_thick.radius == thick);
        CHECK(std::sqrt(thick * thick - (step - last_thick.axial) * (step - last_thick.axial)) ==
              Approx(thin));
        // One piece, and no sphere twice.
        for (std::size_t i = 0; i + 1 < profile.spheres.size(); ++i) {
          const Sphere& p = profile.spheres[i];
          const Sphere& q = profile.spheres[i + 1];
          CHECK(q.axial - p.axial < 0.9 * (p.radius + q.radius));
          CHECK(q.axial - p.axial > 1e-9);
        }
      }
    }
  }
  // A longer thick part makes a heavier rod, with its centre of mass further from the thick tip.
  const RodShape short_thick = make_rod_shape(preset_rnt_profile(0.3, 1.3), kBrassDensity);
  const RodShape long_thick = make_rod_shape(preset_rnt_profile(0.3, 2.5), kBrassDensity);
  CHECK(long_thick.mass > short_thick.mass);
  CHECK(-long_thick.thick_tip > -short_thick.thick_tip);
  CHECK_THROWS_AS(preset_rnt_profile(0.3, rnt_step_min(0.3) - 1e-3), std::invalid_argument);
  CHECK_THROWS_AS(preset_rnt_profile(0.3, rnt_step_max(0.3) + 1e-3), std::invalid_argument);
  // A thinner thick part: a lighter rod; and the thin part may not be thicker than it.
  CHECK(make_rod_shape(preset_rnt_profile(0.3, 1.75, 0.5), kBrassDensity).mass <
        make_rod_shape(preset_rnt_profile(0.3, 1.75), kBrassDensity).mass);
  CHECK_THROWS_AS(preset_rnt_profile(0.3, 1.75, 0.25), std::invalid_argument);
}

TEST_CASE("invalid profiles and densities are rejected", "[rod_shape]") {
  CHECK_THROWS_AS(make_rod_shape({}, kBrassDensity), std::invalid_argument);
  CHECK_THROWS_AS(make_rod_shape({{{0.0, 0.0}}}, kBrassDensity), std::invalid_argument);
  CHECK_THROWS_AS(make_rod_shape({{{0.0, 0.5}, {1.0, -0.2}}}, kBrassDensity),
                  std::invalid_argument);
  CHECK_THROWS_AS(make_rod_shape({{{0.0, 0.5}}}, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(make_rod_shape({{{0.0, 0.5}}}, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(linear_taper_profile(4.5, 0.55, 0.2, 1), std::invalid_argument);
  CHECK_THROWS_AS(linear_taper_profile(0.7, 0.55, 0.2, 9), std::invalid_argument);
  CHECK_THROWS_AS(linear_taper_profile(4.5, 0.0, 0.2, 9), std::invalid_argument);
  CHECK_THROWS_AS(preset_rnt_profile(0.0), std::invalid_argument);
  CHECK_THROWS_AS(preset_rnt_profile(0.6), std::invalid_argument);
}

TEST_CASE("an off-axis union integrated on lines agrees with the exact straight rod",
          "[rod_shape]") {
  // A lateral offset of a nanometre sends rod A and the RnT preset down the grid integration; their
  // exact values differ from it by a few parts in 10^9 at most, far below the grid's error.
  for (const RodProfile& straight : {preset_a_profile(), preset_rnt_profile()}) {
    RodProfile nudged = straight;
    nudged.spheres.back().lateral = 1e-9;
    const RodShape exact = make_rod_shape(straight, kBrassDensity);
    const RodShape grid = make_rod_shape(nudged, kBrassDensity);
    CHECK(grid.mass == Approx(exact.mass).epsilon(5e-5));
    CHECK(grid.inertia_axial == Approx(exact.inertia_axial).epsilon(1e-4));
    CHECK(grid.inertia_transverse == Approx(exact.inertia_transverse).epsilon(5e-5));
    CHECK(grid.inertia_normal == Approx(exact.inertia_transverse).epsilon(5e-5));
    CHECK(grid.projected_area == Approx(exact.projected_area).epsilon(1e-5));
    CHECK(std::abs(grid.axis_lean) < 1e-6);
    for (std::size_t i = 0; i < exact.spheres.size(); ++i) {
      CHECK(grid.spheres[i].axial == Approx(exact.spheres[i].axial).margin(2e-5));
      CHECK(grid.spheres[i].lateral == Approx(0.0).margin(1e-6));
    }
  }
}

TEST_CASE("two disjoint spheres off one axis turn onto their principal axes", "[rod_shape]") {
  // Spheres of radius 0.5 at (0, 0) and 0.3 at (2, 0.4): the line of centres leans by
  // atan(0.2) from the profile's x axis, and for two point-like masses it would be the principal
  // axis; the spheres' own inertia is isotropic, so it is here too.
  const double big = 0.5, small = 0.3;
  const Eigen::Vector2d line(2.0, 0.4);
  RodProfile profile;
  profile.spheres = {{0.0, big}, {line.x(), small, line.y()}};
  const RodShape shape = make_rod_shape(profile, 1.0);
  const double big_mass = sphere_volume(big), small_mass = sphere_volume(small);
  const double mass = big_mass + small_mass;
  CHECK(shape.mass == Approx(mass).epsilon(2e-5));
  CHECK(shape.axis_lean == Approx(std::atan2(line.y(), line.x())).epsilon(1e-5));
  const double distance = line.norm();
  const double com_from_big = small_mass * distance / mass;
  CHECK(shape.spheres[0].axial == Approx(-com_from_big).epsilon(2e-5));
  CHECK(shape.spheres[1].axial == Approx(distance - com_from_big).epsilon(2e-5));
  CHECK(shape.spheres[0].lateral == Approx(0.0).margin(1e-5));
  CHECK(shape.spheres[1].lateral == Approx(0.0).margin(1e-5));
  const double own = 0.4 * (big_mass * big * big + small_mass * small * small);
  const double shifted = big_mass * com_from_big * com_from_big +
                         small_mass * (distance - com_from_big) * (distance - com_from_big);
  CHECK(shape.inertia_axial == Approx(own).epsilon(1e-4));
  CHECK(shape.inertia_transverse == Approx(own + shifted).epsilon(5e-5));
  CHECK(shape.inertia_normal == Approx(own + shifted).epsilon(5e-5));
  CHECK(shape.projected_area == Approx(kPi * (big * big + small * small)).epsilon(1e-5));
}

TEST_CASE("an RnT whose thin part is off its axis", "[rod_shape]") {
  const double offset = 0.05;
  const RodProfile profile =
      preset_rnt_profile(kRntThinRadius, kRntLength / 2, kRntThickRadius, offset);
  for (const Sphere& sphere : profile.spheres) {
    CHECK(sphere.lateral == (sphere.radius == kRntThickRadius ? 0.0 : offset));
  }
  const RodShape straight = make_rod_shape(preset_rnt_profile(), kBrassDensity);
  const RodShape shape = make_rod_shape(profile, kBrassDensity);
  // The same spheres, moved rigidly onto the principal axes. The thin part's first sphere now
  // stands partly clear of the thick part it was buried in, so the union is a little heavier.
  CHECK(shape.mass > straight.mass);
  CHECK(shape.mass < 1.01 * straight.mass);
  CHECK(shape.length == Approx(straight.length).epsilon(1e-3));
  for (std::size_t i = 0; i < profile.spheres.size(); ++i) {
    for (std::size_t j = i + 1; j < profile.spheres.size(); ++j) {
      const Sphere &p = profile.spheres[i], &q = profile.spheres[j];
      const Sphere &pb = shape.spheres[i], &qb = shape.spheres[j];
      CHECK(std::hypot(qb.axial - pb.axial, qb.lateral - pb.lateral) ==
            Approx(std::hypot(q.axial - p.axial, q.lateral - p.lateral)).epsilon(1e-12));
    }
  }
  // The axis of least inertia leans toward the thin part's side, by less than the angle at which
  // the offset is seen from the thick tip.
  CHECK(shape.axis_lean > 0.0);
  CHECK(shape.axis_lean < std::atan2(offset, kRntLength / 2));
  // Every sphere is in the x-y plane, so z stays a principal axis, with the largest moment.
  CHECK(shape.inertia_normal > shape.inertia_transverse);
  CHECK(shape.inertia_normal == Approx(straight.inertia_transverse).epsilon(2e-2));
}

TEST_CASE("a rod in one step is the RnT preset, sphere for sphere", "[rod_shape]") {
  for (const double step : {1.75, 1.2, 3.0}) {
    const RodProfile preset = preset_rnt_profile(0.3, step);
    const RodProfile stepped = stepped_profile(kRntLength, {kRntThickRadius, 0.3}, {step});
    INFO("step " << step);
    REQUIRE(stepped.spheres.size() == preset.spheres.size());
    for (std::size_t k = 0; k < preset.spheres.size(); ++k) {
      CHECK(stepped.spheres[k].axial == preset.spheres[k].axial);
      CHECK(stepped.spheres[k].radius == preset.spheres[k].radius);
    }
  }
}

TEST_CASE("a rod in two steps meets each step and keeps its length", "[rod_shape]") {
  const std::vector<double> radii{0.55, 0.4, 0.25}, steps{1.5, 3.0};
  const RodProfile profile = stepped_profile(4.5, radii, steps);
  const std::vector<Sphere>& spheres = profile.spheres;
  // The tips: the first sphere touches the thick tip, the last the thin one.
  CHECK(spheres.front().axial - spheres.front().radius == Approx(0.0).margin(1e-12));
  CHECK(spheres.back().axial + spheres.back().radius == Approx(4.5).epsilon(1e-12));
  for (std::size_t k = 1; k < spheres.size(); ++k) {
    CHECK(spheres[k].radius <= spheres[k - 1].radius);
    CHECK(spheres[k].axial > spheres[k - 1].axial);
    // Neighbours of one section at most 0.872 radii apart.
    if (spheres[k].radius == spheres[k - 1].radius) {
      CHECK(spheres[k].axial - spheres[k - 1].axial <= 0.872 * spheres[k].radius + 1e-12);
    }
  }
  for (std::size_t i = 0; i < steps.size(); ++i) {
    // The section's last sphere comes down to the next radius exactly at the step, and the next
    // section's first is centred on it.
    double last = -1.0, first = 1e9;
    for (const Sphere& sphere : spheres) {
      if (sphere.radius == radii[i]) last = std::max(last, sphere.axial);
      if (sphere.radius == radii[i + 1]) first = std::min(first, sphere.axial);
    }
    const double reach = std::sqrt(radii[i] * radii[i] - (steps[i] - last) * (steps[i] - last));
    CHECK(reach == Approx(radii[i + 1]).epsilon(1e-12));
    CHECK(first == Approx(steps[i]).epsilon(1e-12));
  }
  // A section with no room for one sphere, radii that grow, or a step count that does not match
  // are refused.
  CHECK_THROWS_AS(stepped_profile(4.5, radii, {0.6, 3.0}), std::invalid_argument);
  CHECK_THROWS_AS(stepped_profile(4.5, {0.25, 0.4}, {2.0}), std::invalid_argument);
  CHECK_THROWS_AS(stepped_profile(4.5, radii, {1.5}), std::invalid_argument);
  CHECK_THROWS_AS(stepped_profile(4.5, radii, {3.0, 1.5}), std::invalid_argument);
}

TEST_CASE("a bent RnT: an arc through its tips, or one sine wave", "[rod_shape]") {
  const RodProfile straight = preset_rnt_profile();
  RodProfile arc = straight;
  bend_profile(arc, kRntLength, 0.1, BendForm::arc);
  RodProfile s = straight;
  bend_profile(s, kRntLength, 0.1, BendForm::s);
  REQUIRE(arc.spheres.size() == straight.spheres.size());
  for (std::size_t k = 0; k < straight.spheres.size(); ++k) {
    const double a = straight.spheres[k].axial;  // from the thick tip
    CHECK(arc.spheres[k].axial == a);
    CHECK(arc.spheres[k].radius == straight.spheres[k].radius);
    // The parabola through the tips (0 and 3.5 mm) with its vertex 0.1 mm off at mid-length.
    CHECK(arc.spheres[k].lateral == Approx(0.1 * a * (3.5 - a) / (1.75 * 1.75)).margin(1e-15));
    CHECK(s.spheres[k].lateral == Approx(-0.1 * std::sin(kPi * a / 1.75)).margin(1e-15));
  }
  // The thin part's first sphere is centred on the step at mid-length: the arc's vertex, the
  // wave's node. The thick half lies to one side of the wave, the thin half to the other.
  CHECK(arc.spheres[3].axial == 1.75);
  CHECK(arc.spheres[3].lateral == Approx(0.1));
  CHECK(std::abs(s.spheres[3].lateral) < 1e-15);
  CHECK(s.spheres[1].lateral < -0.09);
  CHECK(s.spheres[6].lateral > 0.09);
  // Added to an offset already there.
  RodProfile both = preset_rnt_profile(kRntThinRadius, kRntLength / 2, kRntThickRadius, 0.02);
  bend_profile(both, kRntLength, 0.1, BendForm::arc);
  CHECK(both.spheres[5].lateral == Approx(arc.spheres[5].lateral + 0.02));
  CHECK(both.spheres[0].lateral == arc.spheres[0].lateral);
}
