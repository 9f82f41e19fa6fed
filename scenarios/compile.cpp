#include "scenarios/compile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "engine/units.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/placement.hpp"
#include "scenarios/plausibility.hpp"
#include "trap/cell_wall.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::scenarios {
namespace {

/// More rods than this with run.contact_solver: exact get a warning about the cost.
constexpr std::size_t kExactSolverRods = 8;

std::string mm(double value) { return format_real(value) + " mm"; }

std::string percent(double fraction) {
  return format_real(std::round(fraction * 1000.0) / 10.0) + "%";
}

std::string at(const SourceLocation& where) { return " (" + where.to_string() + ")"; }

/// A stepped rod's profile, once its radii and steps are in order and every section has room for
/// one whole sphere; else an error on the key at fault.
std::optional<engine::RodProfile> build_stepped_profile(const ShapeSpec& shape,
                                                        Diagnostics& diagnostics) {
  const double length = shape.stepped_length.value;
  const std::vector<double>& radii = shape.stepped_radii.value;
  const std::vector<double>& steps = shape.stepped_steps.value;
  const Sourced<std::vector<double>>& radii_key = shape.stepped_radii;
  const Sourced<std::vector<double>>& steps_key = shape.stepped_steps;
  if (radii.empty()) return std::nullopt;  // missing: said when read
  if (steps.size() + 1 != radii.size()) {
    diagnostics.error(steps_key.where, steps_key.path,
                      "expected " + std::to_string(radii.size() - 1) +
                          (radii.size() == 2 ? " step" : " steps") + ", one fewer than the " +
                          std::to_string(radii.size()) + " radii, got " +
                          std::to_string(steps.size()));
    return std::nullopt;
  }
  for (std::size_t i = 1; i < radii.size(); ++i) {
    if (radii[i] > radii[i - 1]) {
      diagnostics.error(radii_key.where, radii_key.path,
                        "radius " + std::to_string(i) + " (" + mm(radii[i]) +
                            ") is larger than radius " + std::to_string(i - 1) + " (" +
                            mm(radii[i - 1]) +
                            "); list the sections from the thick end, none thicker than the one "
                            "before");
      return std::nullopt;
    }
  }
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double before = i == 0 ? 0.0 : steps[i - 1];
    if (!(steps[i] > before) || !(steps[i] < length)) {
      diagnostics.error(steps_key.where, steps_key.path,
                        "step " + std::to_string(i) + " at " + mm(steps[i]) + " must lie beyond " +
                            (i == 0 ? "the thick tip" : mm(before)) +
                            " and before the thin tip at " + mm(length) +
                            "; list the steps from the thick tip, growing");
      return std::nullopt;
    }
  }
  const auto spans = engine::stepped_section_spans(length, radii, steps);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    if (spans[i].second < spans[i].first - 1e-12) {
      const bool last = i + 1 == spans.size();
      const Sourced<double>& length_key = shape.stepped_length;
      const std::string what = "section " + std::to_string(i) + " (radius " + mm(radii[i]) +
                               ") has no room for one whole sphere: its centres would run from " +
                               mm(std::round(spans[i].first * 1e4) / 1e4) + " to " +
                               mm(std::round(spans[i].second * 1e4) / 1e4) + " from the thick tip";
      if (last && steps.empty()) {
        diagnostics.error(
            length_key.where, length_key.path,
            what + "; expected a length of at least twice the radius, got " + mm(length));
      } else {
        diagnostics.error(steps_key.where, steps_key.path,
                          what + "; expected the steps further apart, or from the tips");
      }
      return std::nullopt;
    }
  }
  engine::RodProfile profile = engine::stepped_profile(length, radii, steps);
  // As many spheres as an explicit list or a taper may have.
  constexpr std::size_t kMaxSpheres = 200;
  if (profile.spheres.size() > kMaxSpheres) {
    diagnostics.error(radii_key.where, radii_key.path,
                      "give a rod of " + std::to_string(profile.spheres.size()) +
                          " spheres (neighbours at most 0.872 radii apart), more than " +
                          std::to_string(kMaxSpheres) + "; expected larger radii");
    return std::nullopt;
  }
  return profile;
}

std::optional<engine::RodProfile> build_profile(const ShapeSpec& shape, Diagnostics& diagnostics) {
  switch (shape.kind) {
    case ShapeSpec::Kind::preset:
      if (shape.preset.value == "RnT") {
        const double thick = shape.thick_radius.value;
        const double thin = shape.thin_radius.value;
        const double step = shape.step.value;
        if (thin > thick) {
          diagnostics.error(shape.thin_radius.where, shape.thin_radius.path,
                            "must be <= thick_radius (" + mm(thick) + "), got " + mm(thin) +
                                "; the RnT preset is thick from its thick tip to the step");
          return std::nullopt;
        }
        const double step_min = engine::rnt_step_min(thin, thick);
        const double step_max = engine::rnt_step_max(thin);
        if (step_min > step_max) {
          diagnostics.error(shape.thick_radius.where, shape.thick_radius.path,
                            mm(thick) +
                                " leaves no room for a step on the 3.5 mm RnT rod with "
                                "thin_radius " +
                                mm(thin) +
                                " (thick_radius + sqrt(thick_radius^2 - thin_radius^2) must be at "
                                "most 3.5 mm - thin_radius)");
          return std::nullopt;
        }
        if (step < step_min || step > step_max) {
          diagnostics.error(shape.step.where, shape.step.path,
                            "must be from " + mm(std::ceil(step_min * 1e3) / 1e3) + " to " +
                                mm(std::floor(step_max * 1e3) / 1e3) + " with thick_radius " +
                                mm(thick) + " and thin_radius " + mm(thin) +
                                " (one whole sphere on each side of the step), got " + mm(step));
          return std::nullopt;
        }
        const double offset = shape.thin_offset.value;
        if (offset > thick - thin) {
          diagnostics.error(shape.thin_offset.where, shape.thin_offset.path,
                            "must be at most thick_radius - thin_radius (" +
                                mm(std::round((thick - thin) * 1e9) / 1e9) +
                                ") so that the thin part stays within the rod's thickness, got " +
                                mm(offset));
          return std::nullopt;
        }
        engine::RodProfile profile = engine::preset_rnt_profile(thin, step, thick, offset);
        if (shape.bend.value > 0.0) {
          engine::bend_profile(
              profile, engine::kRntLength, shape.bend.value,
              shape.bend_form.value == "s" ? engine::BendForm::s : engine::BendForm::arc);
        }
        // As many spheres as an explicit list or a taper may have: a very thin part would take
        // thousands, and the mass properties of a union cost the square of its spheres' count.
        constexpr std::size_t kMaxSpheres = 200;
        if (profile.spheres.size() > kMaxSpheres) {
          const Sourced<double>& key = thin < thick ? shape.thin_radius : shape.thick_radius;
          diagnostics.error(key.where, key.path,
                            "gives an RnT of " + std::to_string(profile.spheres.size()) +
                                " spheres (neighbours at most 0.872 radii apart), more than " +
                                std::to_string(kMaxSpheres) +
                                "; expected a larger radius (the preset's thin part is 0.3 mm, "
                                "its thick part 0.55 mm), got " +
                                mm(key.value));
          return std::nullopt;
        }
        return profile;
      }
      return engine::preset_a_profile();
    case ShapeSpec::Kind::taper: {
      const double length = shape.taper_length.value;
      const double thick = shape.taper_thick_radius.value;
      const double thin = shape.taper_thin_radius.value;
      if (thin > thick) {
        diagnostics.error(shape.taper_thin_radius.where, shape.taper_thin_radius.path,
                          "must be <= thick_radius (" + mm(thick) + "), got " + mm(thin) +
                              "; the axis runs from the thick to the thin end");
        return std::nullopt;
      }
      // The end spheres must be the tips: the radius may not shrink faster than the centres move.
      if (length - thick - thin < thick - thin || length <= thick + thin) {
        diagnostics.error(shape.taper_length.where, shape.taper_length.path,
                          "must be more than 2 x thick_radius (" + mm(2.0 * thick) +
                              ") for a taper whose ends are its tips, got " + mm(length));
        return std::nullopt;
      }
      return engine::linear_taper_profile(length, thick, thin,
                                          static_cast<int>(shape.taper_spheres.value));
    }
    case ShapeSpec::Kind::stepped:
      return build_stepped_profile(shape, diagnostics);
    case ShapeSpec::Kind::spheres: {
      engine::RodProfile profile;
      for (const auto& [axial, radius, lateral] : shape.spheres.value) {
        if (!profile.spheres.empty() && axial <= profile.spheres.back().axial) {
          diagnostics.error(shape.spheres.where, shape.spheres.path,
                            "sphere " + std::to_string(profile.spheres.size()) +
                                " is at axial position " + mm(axial) + ", not beyond sphere " +
                                std::to_string(profile.spheres.size() - 1) + " at " +
                                mm(profile.spheres.back().axial) +
                                "; list the spheres from the thick end to the thin end, the "
                                "axial position growing");
          return std::nullopt;
        }
        profile.spheres.push_back({axial, radius, lateral});
      }
      // The mass properties of a rod with offsets are integrated on a fixed number of lines
      // across it (engine/rod_shape.cpp), accurate while the offsets stay within its thickness.
      double low = 0.0, high = 0.0, widest = 0.0;
      for (const engine::Sphere& sphere : profile.spheres) {
        low = std::min(low, sphere.lateral);
        high = std::max(high, sphere.lateral);
        widest = std::max(widest, 2.0 * sphere.radius);
      }
      if (high - low > widest) {
        diagnostics.error(shape.spheres.where, shape.spheres.path,
                          "the offsets from the axis span " + mm(high - low) +
                              ", more than the thickest sphere's diameter (" + mm(widest) +
                              "); expected a rod along its axis, bent by less than its "
                              "thickness (give the axial positions along the rod)");
        return std::nullopt;
      }
      return profile;
    }
  }
  return std::nullopt;
}

/// A rough plate must fit its modes in the cell, and its highest points should leave the thickest
/// rod room between base and lid.
void check_roughness(const ScenarioSpec& spec, const engine::Model& model,
                     Diagnostics& diagnostics) {
  double reach = 0.0;
  for (int plate = 0; plate < 2; ++plate) {
    const Sourced<double>& slope = plate == 0 ? spec.base_slope : spec.lid_slope;
    if (slope.value == 0.0) continue;
    try {
      reach += engine::PlateRoughness(slope.value, model.roughness.wavelength, model.box_x,
                                      model.box_y, model.seed, plate)
                   .reach();
    } catch (const std::invalid_argument&) {
      diagnostics.error(spec.roughness_wavelength.where, spec.roughness_wavelength.path,
                        "a wavelength of " + mm(model.roughness.wavelength) +
                            " is too long for the cell (box.size): fewer than " +
                            std::to_string(engine::PlateRoughness::kModes) +
                            " distinct waves fit; expected a wavelength of a few mm at most");
      return;
    }
  }
  double thickest = 0.0;
  for (const engine::Species& species : model.species) {
    thickest = std::max(thickest, 2.0 * species.shape.max_radius);
  }
  const double clearance = model.drive.gap - thickest;
  if (reach > 0.0 && clearance > 0.0 && reach >= 0.5 * clearance) {
    const Sourced<double>& slope = spec.base_slope.value > 0.0 ? spec.base_slope : spec.lid_slope;
    diagnostics.warning(slope.where, slope.path,
                        "the rough plates' highest points can stand out by up to " + mm(reach) +
                            " together, half or more of the " + mm(clearance) +
                            " between the thickest rod and the gap (drive.gap)");
  }
}

/// How thick a rod is at its thickest roll about its axis: its width in the plane of its offsets,
/// which stands upright at some roll (a straight rod's diameter).
double thickness_at_any_roll(const engine::RodShape& shape) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const engine::Sphere& sphere : shape.spheres) {
    low = std::min(low, sphere.lateral - sphere.radius);
    high = std::max(high, sphere.lateral + sphere.radius);
  }
  return high - low;
}

void check_fits_gap(const engine::RodShape& shape, const SpeciesSpec& species,
                    const ScenarioSpec& spec, Diagnostics& diagnostics) {
  const double gap = spec.gap.value;
  if (2.0 * shape.max_radius >= gap) {
    diagnostics.error(species.shape.where, species.shape.path,
                      "the rod is " + mm(2.0 * shape.max_radius) +
                          " thick, which does not fit in the gap of " + mm(gap) +
                          " between base and lid (drive.gap" + at(spec.gap.where) +
                          "); the gap must exceed the rod's thickness");
  } else if (const double rolled = thickness_at_any_roll(shape); rolled >= gap) {
    // Placement draws the roll of a rod with off-axis spheres at random.
    const bool bent = species.shape.bend.value > 0.0;
    diagnostics.error(bent ? species.shape.bend.where : species.shape.where,
                      bent ? species.shape.bend.path : species.shape.path,
                      "the rod is " + mm(std::ceil(rolled * 1e4) / 1e4) +
                          " thick when rolled about its axis so that its off-axis spheres lie "
                          "above one another, which does not fit in the gap of " +
                          mm(gap) + " between base and lid (drive.gap" + at(spec.gap.where) +
                          "); the gap must exceed the rod's thickness at every roll, since "
                          "placement draws the roll at random");
  }
  if (shape.length <= gap) {
    diagnostics.error(species.shape.where, species.shape.path,
                      "the rod is " + mm(shape.length) + " long, no longer than the gap of " +
                          mm(gap) + " (drive.gap" + at(spec.gap.where) +
                          "), so it could stand on end; rods must be longer than the gap");
  }
}

/// Steps in an interval; reports an interval shorter than dt, and warns when it is not a multiple.
std::int64_t to_steps(const Sourced<double>& interval, double dt, Diagnostics& diagnostics) {
  const double exact = interval.value / dt;
  if (exact > kMaxSteps) {
    diagnostics.error(interval.where, interval.path,
                      format_real(interval.value) + " s is " + format_real(exact) +
                          " steps of run.dt = " + format_real(dt) + " s; at most " +
                          format_real(kMaxSteps) +
                          " steps are accepted (some three CPU-hours per rod at the fastest)");
    return 1;
  }
  const auto steps = static_cast<std::int64_t>(std::llround(exact));
  if (steps < 1) {
    diagnostics.error(interval.where, interval.path,
                      "must be at least one time step (run.dt = " + format_real(dt) + " s), got " +
                          format_real(interval.value) + " s");
    return 1;
  }
  if (std::abs(exact - static_cast<double>(steps)) > 1e-6 * exact) {
    diagnostics.warning(interval.where, interval.path,
                        format_real(interval.value) + " s is not a multiple of run.dt = " +
                            format_real(dt) + " s; using " + std::to_string(steps) + " steps (" +
                            format_real(static_cast<double>(steps) * dt) + " s)");
  }
  return steps;
}

bool is_rnt_preset(const SpeciesSpec& species) {
  return species.shape.kind == ShapeSpec::Kind::preset && species.shape.preset.value == "RnT";
}

/// RnT's rotational diffusion under the collision kick has not converged at dt = 1e-4 s (40% low,
/// docs/model.md, "Step-tapered rods"); from 5e-5 s on it is within 10-20%.
void warn_unconverged_kick(const SpeciesSpec& species, double dt, Diagnostics& diagnostics) {
  constexpr double kLargestConvergedDt = 5.0e-5;  // [s]
  if (!is_rnt_preset(species) || species.kick_eps.value == 0.0 ||
      dt <= kLargestConvergedDt * (1.0 + 1e-9))
    return;
  diagnostics.warning(species.kick_eps.where, species.kick_eps.path,
                      "the collision kick's rotational diffusion of RnT rods has not converged at "
                      "run.dt = " +
                          format_real(dt) +
                          " s (at 1e-4 s it is about 40% below its small-dt value, docs/model.md); "
                          "use run.dt = 2.5e-5 s, or white noise (noise.white_Dr)");
}

/// An RnT outline moved off the preset's, its step from mid-length to 3 mm, has a gait that can
/// change with dt and with the contact solve (docs/model.md, "Where the RnT's step lies", items 4
/// and 5, and "The clearance to the lid", item 7): a thin radius of 0.4 mm with the step at
/// 2.25 mm runs forward at 22.8 mm/s at dt = 1e-4 s, shuttles from 1.25e-5 s on with the default
/// ten sweeps, and runs steadily backward at 6.25e-6 s with 30 sweeps or more or the exact solve,
/// where 1.25e-5 s with 100 or 300 sweeps leaves it standing; RnT 1.0 mm thick runs in 54% of its
/// windows at 1e-4 s and in 75% at 2.5e-5 s. The preset's own outline is left unwarned: its speed
/// moves by 20% with dt, its gait does not; as are short thick parts, steady at every dt.
void warn_unconverged_step(const SpeciesSpec& species, const engine::Model& model,
                           Diagnostics& diagnostics) {
  constexpr double kLargestConvergedDt = 6.25e-6;  // [s]
  constexpr int kFewestConvergedSweeps = 30;
  constexpr double kMidLength = engine::kRntLength / 2;  // the preset's step [mm]
  constexpr double kLongThickPart = 3.0;  // from here on the rod lies level and rattles [mm]
  const ShapeSpec& shape = species.shape;
  const bool converged_solve =
      model.exact_contact_solver || model.solver_iterations >= kFewestConvergedSweeps;
  if (!is_rnt_preset(species) ||
      (model.dt <= kLargestConvergedDt * (1.0 + 1e-9) && converged_solve)) {
    return;
  }
  const double step = shape.step.value;
  if (step < kMidLength - 1e-9 || step >= kLongThickPart) return;
  const bool preset_outline = std::abs(step - kMidLength) < 1e-9 &&
                              std::abs(shape.thin_radius.value - engine::kRntThinRadius) < 1e-9 &&
                              std::abs(shape.thick_radius.value - engine::kRntThickRadius) < 1e-9;
  if (preset_outline) return;
  const Sourced<double>& key = shape.step.given          ? shape.step
                               : shape.thin_radius.given ? shape.thin_radius
                                                         : shape.thick_radius;
  const std::string solve = model.exact_contact_solver
                                ? std::string("the exact solve")
                                : std::to_string(model.solver_iterations) + " solver sweeps";
  diagnostics.warning(
      key.where, key.path,
      "an RnT outline other than the preset's (thick_radius " + mm(shape.thick_radius.value) +
          ", thin_radius " + mm(shape.thin_radius.value) + ", step " + mm(step) +
          ") may change its gait with run.dt = " + format_real(model.dt) + " s and " + solve +
          ", as the step study's did from the step at mid-length to 3 mm "
          "(docs/model.md, \"Where the RnT's step lies\"; thin_radius 0.4 mm with the step at "
          "2.25 mm runs forward at 1e-4 s, shuttles at 1.25e-5 s with ten sweeps, and runs "
          "backward at 6.25e-6 s with 30); check its gait with rodsort single at "
          "run.dt = 6.25e-6 s and run.solver_iterations = 30");
}

/// An RnT whose thin part lies off its axis, or that is bent, changes its gait with dt
/// (docs/model.md, "An RnT whose thin part is off its axis" and "A bent RnT"): at an offset of
/// 0.05 mm it circles at dt = 1e-4 s and its heading diffuses from 2.5e-5 s on; at 0.1 mm its turn
/// rate falls from 0.61 to 0.24 rad/s by 1.25e-5 s; an arc of 0.1 mm circles at 0.20 rad/s at
/// 1e-4 s and at 4.1 rad/s at 2.5e-5 s. Each key that is set is warned of above 1.25e-5 s.
void warn_unconverged_off_axis(const SpeciesSpec& species, double dt, Diagnostics& diagnostics) {
  constexpr double kSmallestStudiedDt = 1.25e-5;  // [s]
  if (!is_rnt_preset(species) || dt <= kSmallestStudiedDt * (1.0 + 1e-9)) return;
  const std::string check = "); check its gait with rodsort single at run.dt = 1.25e-5 s";
  const auto warn = [&](const Sourced<double>& key, const std::string& what,
                        const std::string& evidence) {
    if (!(key.value > 0.0)) return;
    diagnostics.warning(key.where, key.path,
                        what + " may change its gait with run.dt = " + format_real(dt) +
                            " s (docs/model.md, " + evidence + check);
  };
  warn(species.shape.thin_offset, "an RnT whose thin part lies off its axis",
       "\"An RnT whose thin part is off its axis\": at 0.05 mm it circles at 1e-4 s and turns at "
       "random from 2.5e-5 s");
  warn(species.shape.bend, "a bent RnT",
       "\"A bent RnT\": an arc of 0.1 mm circles at 0.20 rad/s at 1e-4 s and at 4.1 rad/s at "
       "2.5e-5 s");
}

/// Restitutions of base and lid both above 0.65 make a rod rattle between the plates, and its gait
/// then depends on the order in which a step meets their contacts (docs/model.md, "Restitution of
/// base and lid together"): at 0.8 rod A's v0 is -11.1, 2.3, 8.4, 9.8 and 10.5 mm/s at dt = 1e-4,
/// 5e-5, 2.5e-5, 1.25e-5 and 6.25e-6 s; at 0.65 and below, and with either plate alone at 0.9, it
/// is within 10% from 1e-4 s down. Warned once per rod material, at the pair that raised the
/// restitution, above 1.25e-5 s.
void warn_lively_plates(const ScenarioSpec& spec, const engine::MaterialTable& materials,
                        Diagnostics& diagnostics) {
  constexpr double kLargestSettledDt = 1.25e-5;  // [s]
  constexpr double kSettledRestitution = 0.65;   // the largest with a gait steady in dt
  if (spec.dt.value <= kLargestSettledDt * (1.0 + 1e-9)) return;
  std::vector<std::string> warned;
  for (const SpeciesSpec& species : spec.species) {
    const std::string& rod = species.material.value;
    if (std::find(warned.begin(), warned.end(), rod) != warned.end()) continue;
    const int index = materials.index_of(rod);
    const double base = materials.get(index, engine::MaterialTable::kBase).restitution;
    const double lid = materials.get(index, engine::MaterialTable::kLid).restitution;
    if (std::min(base, lid) <= kSettledRestitution) continue;
    warned.push_back(rod);
    // The pair given last for this rod's base or lid: a lively lid and base need both set.
    const MaterialPairSpec* given = nullptr;
    for (const MaterialPairSpec& pair : spec.materials) {
      const bool rod_pair = pair.first == rod || pair.second == rod;
      const bool plate = pair.first == "base" || pair.second == "base" || pair.first == "lid" ||
                         pair.second == "lid";
      if (rod_pair && plate && pair.restitution) given = &pair;
    }
    const SourceLocation where = given ? given->restitution->where : spec.dt.where;
    const std::string path = given ? given->restitution->path : spec.dt.path;
    diagnostics.warning(
        where, path,
        "restitutions of " + format_real(base) + " with the base and " + format_real(lid) +
            " with the lid (rod material " + rod +
            ") make rods rattle between the plates, and their gait changes with "
            "run.dt = " +
            format_real(spec.dt.value) +
            " s (docs/model.md, \"Restitution of base and lid together\": at 0.8 "
            "rod A's v0 is -11.1 mm/s at 1e-4 s and 9.8 at 1.25e-5 s); check the "
            "gait with rodsort single --dt-halvings, down to run.dt = 1.25e-5 s and "
            "below");
  }
}

/// With the split impulse's turns applied in full, an RnT rod at dt = 1e-4 or 2.5e-5 s is locked in
/// its slow glide, about half the speed of its run (5.1 against 10.2 mm/s alone at 1e-4 s); only at
/// 1.25e-5 s does it run again (docs/model.md, "Checks while a run goes"). Rod A is not affected.
void warn_rnt_glide(const ScenarioSpec& spec, Diagnostics& diagnostics) {
  constexpr double kLargestRunningDt = 1.25e-5;  // [s]
  if (spec.turn_correction.value != "full" || spec.dt.value <= kLargestRunningDt * (1.0 + 1e-9))
    return;
  for (const SpeciesSpec& species : spec.species) {
    if (!is_rnt_preset(species)) continue;
    diagnostics.warning(spec.turn_correction.where, spec.turn_correction.path,
                        "full at run.dt = " + format_real(spec.dt.value) + " s locks RnT rods (" +
                            species.name.value +
                            ") in a slow glide at about half the speed of their run (5.1 against "
                            "10.2 mm/s alone at 1e-4 s and the 1.2 mm gap; 2.4 against 3.1 mm/s "
                            "at a 1.31 mm gap, docs/model.md); they run again at "
                            "run.dt = 1.25e-5 s");
    return;
  }
}

struct Counts {
  std::vector<int> per_species;
  bool ok = true;
};

Counts count_rods(const ScenarioSpec& spec, const std::vector<engine::RodShape>& shapes,
                  double trap_area, double cell_area, Diagnostics& diagnostics) {
  Counts counts;
  counts.per_species.assign(spec.species.size(), 0);
  double auto_area = 0.0;  // total projected area of the species counted auto [mm^2]
  double weighted_area = 0.0;
  const SpeciesSpec* first_auto = nullptr;
  for (std::size_t i = 0; i < spec.species.size(); ++i) {
    const SpeciesSpec& species = spec.species[i];
    if (!species.auto_count()) {
      counts.per_species[i] = static_cast<int>(species.count.value.number);
      continue;
    }
    if (!first_auto) first_auto = &species;
    weighted_area += (species.fraction ? species.fraction->value : 1.0) * shapes[i].projected_area;
  }
  if (!first_auto) return counts;
  if (spec.area_fraction) {
    auto_area = spec.area_fraction->value * cell_area;
  } else if (spec.trap) {
    auto_area = spec.trap_area_ratio.value * trap_area;
  } else {
    diagnostics.error(first_auto->count.where, first_auto->count.path,
                      "`count: auto` sets N = round(r A_t / a) from the trap's area, but there is "
                      "no trap; give a number of rods, or population.area_fraction");
    counts.ok = false;
    return counts;
  }
  const double total = auto_area / weighted_area;
  for (std::size_t i = 0; i < spec.species.size(); ++i) {
    const SpeciesSpec& species = spec.species[i];
    if (!species.auto_count()) continue;
    const double count = (species.fraction ? species.fraction->value : 1.0) * total;
    if (count > 1.0e6) {
      diagnostics.error(species.count.where, species.count.path,
                        "`count: auto` gives " + format_real(std::round(count)) +
                            " rods, more than the 1000000 rodsort accepts");
      counts.ok = false;
      continue;
    }
    counts.per_species[i] = static_cast<int>(std::llround(count));
  }
  return counts;
}

PlacementRegion region_of(const std::string& word) {
  if (word == "inside_trap") return PlacementRegion::inside_trap;
  if (word == "outside_trap") return PlacementRegion::outside_trap;
  return PlacementRegion::anywhere;
}

/// Refuses more rods than random placement can fit in a region.
void check_crowding(const ScenarioSpec& spec, const std::vector<engine::RodShape>& shapes,
                    const std::vector<int>& counts, double trap_area, double cell_area,
                    Diagnostics& diagnostics) {
  struct Region {
    PlacementRegion region;
    const char* description;
    double area;
  };
  const Region regions[] = {
      {PlacementRegion::anywhere, "the cell", cell_area},
      {PlacementRegion::inside_trap, "the trap", trap_area},
      {PlacementRegion::outside_trap, "the cell outside the trap", cell_area - trap_area}};
  double total = 0.0;
  for (std::size_t i = 0; i < counts.size(); ++i) total += counts[i] * shapes[i].projected_area;
  for (const Region& region : regions) {
    if (region.region != PlacementRegion::anywhere && !spec.trap) continue;
    double covered = 0.0;
    const SpeciesSpec* first = nullptr;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      if (region_of(spec.species[i].initial_region.value) != region.region) continue;
      covered += counts[i] * shapes[i].projected_area;
      if (!first) first = &spec.species[i];
    }
    if (region.region == PlacementRegion::anywhere) covered = total;
    if (first == nullptr || region.area <= 0.0 || covered <= kMaxPlacementFraction * region.area) {
      continue;
    }
    diagnostics.error(first->count.where, first->count.path,
                      "the rods cover " + percent(covered / region.area) + " of " +
                          region.description + " (" + format_real(std::round(covered)) + " of " +
                          format_real(std::round(region.area)) +
                          " mm^2), more than random placement can fit (" +
                          percent(kMaxPlacementFraction) + "); use fewer rods or a larger cell");
  }
}

/// The wall of a bounded cell, centred in the box, which it sizes when box.size is not given;
/// nothing for the periodic cell or a cell in error.
std::optional<trap::CellWall> build_cell(const ScenarioSpec& spec,
                                         const std::vector<engine::RodShape>& shapes,
                                         engine::Model& model, Diagnostics& diagnostics) {
  const std::string& shape = spec.cell_shape.value;
  const auto only_for = [&](const auto& key, bool applies, const char* shapes_it_is_for) {
    if (key.given && !applies) {
      diagnostics.error(
          key.where, key.path,
          std::string("is only for ") + shapes_it_is_for + ", but cell.shape is " + shape);
    }
  };
  const bool bounded = shape != "periodic";
  only_for(spec.cell_diameter, bounded, "a bounded cell (cell.shape: circle or flower)");
  only_for(spec.cell_wall_thickness, bounded, "a bounded cell (cell.shape: circle or flower)");
  only_for(spec.cell_petals, bounded, "a flower wall (cell.shape: flower)");
  only_for(spec.cell_petal_depth, bounded, "a flower wall (cell.shape: flower)");
  if (!bounded) return std::nullopt;
  // A circle ignores the petals, with a warning only: a sweep may compare both shapes.
  const auto ignored_by_circle = [&](const auto& key) {
    if (key.given && shape == "circle") {
      diagnostics.warning(key.where, key.path,
                          "ignored: it is only for a flower wall, and cell.shape is circle");
    }
  };
  ignored_by_circle(spec.cell_petals);
  ignored_by_circle(spec.cell_petal_depth);

  const double diameter = spec.cell_diameter.value;
  const double thickness = spec.cell_wall_thickness.value;
  const int petals = static_cast<int>(spec.cell_petals.value);
  bool ok = true;
  if (shape == "flower") {
    const double deepest = trap::CellWall::max_petal_depth(diameter, petals);
    if (spec.cell_petal_depth.value > deepest) {
      diagnostics.error(
          spec.cell_petal_depth.where, spec.cell_petal_depth.path,
          "must be at most " + format_real(std::floor(deepest * 1000.0) / 1000.0) +
              " mm, where the cusps of " + std::to_string(petals) + " petals on a " +
              format_real(diameter) + " mm cell turn the wall by a right angle, got " +
              format_real(spec.cell_petal_depth.value) + "; fewer petals can be deeper");
      ok = false;
    }
  }
  const double side = trap::enclosing_box(diameter, thickness, trap::required_margin(shapes));
  if (!spec.box_size.given) {
    model.box_x = model.box_y = side;
  } else if (model.box_x < side || model.box_y < side) {
    diagnostics.error(spec.box_size.where, spec.box_size.path,
                      "must be at least " + format_real(side) + " mm on each side to hold the " +
                          shape + " cell of " + format_real(diameter) +
                          " mm with its wall clear of the periodic edges by a rod's reach, got [" +
                          format_real(model.box_x) + ", " + format_real(model.box_y) +
                          "]; leave box out to get that size");
    ok = false;
  }
  if (!ok) return std::nullopt;
  const Eigen::Vector2d centre(model.box_x / 2.0, model.box_y / 2.0);
  if (shape == "circle") return trap::CellWall::circle(centre, diameter, thickness);
  return trap::CellWall::flower(centre, diameter, petals, spec.cell_petal_depth.value, thickness);
}

}  // namespace

std::optional<Scenario> compile(const ScenarioSpec& spec, Diagnostics& diagnostics) {
  const std::size_t errors_before = diagnostics.error_count();
  Scenario scenario;
  scenario.name = spec.name.value;
  scenario.spec = spec;
  engine::Model& model = scenario.model;
  model.box_x = spec.box_size.value[0];
  model.box_y = spec.box_size.value[1];
  model.seed = static_cast<std::uint64_t>(spec.seed.value);
  model.dt = spec.dt.value;
  model.solver_iterations = static_cast<int>(spec.solver_iterations.value);
  model.full_turn_correction = spec.turn_correction.value == "full";
  model.exact_contact_solver = spec.contact_solver.value == "exact";
  // A compliance small against every entry of the problem (1e-4 per g on a diagonal of at least
  // 61 per g at dt = 1e-4 s) that keeps rigid contacts along a line solvable (docs/model.md).
  model.constraint_force_mixing = model.exact_contact_solver ? engine::kExactSolverCompliance : 0.0;

  model.drive.frequency = spec.frequency.value;
  model.drive.gap = spec.gap.value;
  model.drive.amplitude =
      spec.amplitude ? spec.amplitude->value
                     : engine::Drive::amplitude_from_gamma(spec.gamma->value, spec.frequency.value);
  model.roughness.base_slope = spec.base_slope.value;
  model.roughness.lid_slope = spec.lid_slope.value;
  model.roughness.wavelength = spec.roughness_wavelength.value;
  if (model.drive.gamma() <= 1.0) {
    const SourceLocation& where = spec.amplitude ? spec.amplitude->where : spec.gamma->where;
    diagnostics.warning(where, spec.amplitude ? spec.amplitude->path : spec.gamma->path,
                        "Gamma = " + format_real(model.drive.gamma()) +
                            " <= 1: the base never accelerates downward faster than gravity, so "
                            "the rods never leave it and do not move");
  }
  const double steps_per_period = 1.0 / (spec.frequency.value * spec.dt.value);
  if (steps_per_period < kMinStepsPerDrivePeriod) {
    diagnostics.error(
        spec.dt.where, spec.dt.path,
        format_real(spec.dt.value) + " s gives " +
            format_real(std::round(steps_per_period * 10.0) / 10.0) +
            " steps per drive period at " + format_real(spec.frequency.value) + " Hz; at least " +
            format_real(kMinStepsPerDrivePeriod) + " are needed: use dt <= " +
            format_real(1.0 / (kMinStepsPerDrivePeriod * spec.frequency.value)) + " s");
  }

  std::vector<engine::RodShape> shapes;
  for (const SpeciesSpec& species : spec.species) {
    try {
      const auto profile = build_profile(species.shape, diagnostics);
      if (profile) {
        shapes.push_back(engine::make_rod_shape(*profile, species.density.value));
        check_fits_gap(shapes.back(), species, spec, diagnostics);
      }
    } catch (const std::invalid_argument& e) {
      diagnostics.error(species.shape.where, species.shape.path, e.what());
    }
  }
  if (shapes.size() != spec.species.size()) return std::nullopt;

  model.materials = engine::MaterialTable::paper();
  for (const SpeciesSpec& species : spec.species) {
    if (model.materials.index_of(species.material.value) < 0) {
      model.materials.add_rod_material(species.material.value);
    }
  }
  for (const MaterialPairSpec& pair : spec.materials) {
    const int a = model.materials.index_of(pair.first);
    const int b = model.materials.index_of(pair.second);
    engine::ContactCoefficients coefficients = model.materials.get(a, b);
    if (pair.friction) coefficients.friction = pair.friction->value;
    if (pair.restitution) coefficients.restitution = pair.restitution->value;
    model.materials.set(a, b, coefficients);
  }
  warn_rnt_glide(spec, diagnostics);
  warn_lively_plates(spec, model.materials, diagnostics);
  for (std::size_t i = 0; i < spec.species.size(); ++i) {
    const SpeciesSpec& species = spec.species[i];
    warn_unconverged_kick(species, model.dt, diagnostics);
    warn_unconverged_step(species, model, diagnostics);
    warn_unconverged_off_axis(species, model.dt, diagnostics);
    engine::Species out;
    out.name = species.name.value;
    out.shape = shapes[i];
    out.noise.kick_eps = species.kick_eps.value;
    out.noise.white_Dr = species.white_Dr.value;
    out.material = model.materials.index_of(species.material.value);
    model.species.push_back(std::move(out));
  }
  check_roughness(spec, model, diagnostics);
  check_step_travel(spec, model, diagnostics);

  if (const auto cell = build_cell(spec, shapes, model, diagnostics)) {
    scenario.cell = std::make_shared<trap::CellWall>(*cell);
    scenario.cell_area = cell->area();
  } else {
    scenario.cell_area = model.box_x * model.box_y;
  }

  std::optional<trap::VTrap> v_trap;
  if (spec.trap) {
    const TrapSpec& t = *spec.trap;
    const double angle = degrees_to_radians(t.angle.value);
    const double direction = degrees_to_radians(t.direction.value);
    v_trap = t.apex ? trap::VTrap({t.apex->value[0], t.apex->value[1]}, angle, t.arm_length.value,
                                  t.wall_thickness.value, direction)
                    : trap::centered_v_trap(model.box_x, model.box_y, angle, t.arm_length.value,
                                            t.wall_thickness.value, direction);
    if (scenario.cell) {
      double longest = 0.0;
      for (const engine::RodShape& shape : shapes) longest = std::max(longest, shape.length);
      if (const auto why = scenario.cell->enclosure_error(*v_trap, longest)) {
        diagnostics.error(t.where, "trap", *why);
      }
    } else if (const auto why =
                   v_trap->fit_error(model.box_x, model.box_y, trap::required_margin(shapes))) {
      diagnostics.error(t.where, "trap", *why);
    }
    scenario.trap = std::make_shared<trap::VTrap>(*v_trap);
    scenario.trap_area = v_trap->area();
    model.walls = v_trap->walls();
  }
  if (scenario.cell) {
    const std::vector<engine::Wall> cell_walls = scenario.cell->walls();
    model.walls.insert(model.walls.end(), cell_walls.begin(), cell_walls.end());
  }

  for (const SpeciesSpec& species : spec.species) {
    if (!spec.trap && species.initial_region.value != "anywhere") {
      diagnostics.error(species.initial_region.where, species.initial_region.path,
                        "`" + species.initial_region.value + "` needs a trap, but trap is none");
    }
    if (!spec.trap && species.initial_heading.value.is("toward_apex")) {
      diagnostics.error(species.initial_heading.where, species.initial_heading.path,
                        "`toward_apex` needs a trap, but trap is none");
    }
  }

  const Counts counts =
      count_rods(spec, shapes, scenario.trap_area, scenario.cell_area, diagnostics);
  if (counts.ok) {
    std::int64_t total = 0;  // up to 64 species of up to 1e6 rods each
    for (const int count : counts.per_species) total += count;
    if (total == 0) {
      diagnostics.error(spec.species_where, "species", "the scenario has no rods");
    }
    check_crowding(spec, shapes, counts.per_species, scenario.trap_area, scenario.cell_area,
                   diagnostics);
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    scenario.species.push_back(
        {counts.per_species[i], shapes[i].projected_area, shapes[i].mass, shapes[i].length});
  }

  const double dt = spec.dt.value;
  scenario.run.duration = spec.duration.value;
  scenario.run.steps = to_steps(spec.duration, dt, diagnostics);
  OutputSettings& output = scenario.output;
  output.frame_interval = spec.frame_interval.value;
  output.frame_steps = to_steps(spec.frame_interval, dt, diagnostics);
  if (spec.h5md_precision.given && spec.h5md_precision.value != "single" &&
      spec.rods_format.value == "csv") {
    // A warning only: a sweep may compare the formats. Only a value other than the default is
    // worth one: every resolved scenario (a sweep's points, a run's scenario.resolved.yaml)
    // names the precision, and a run writing rods.csv reads it back.
    diagnostics.warning(spec.h5md_precision.where, spec.h5md_precision.path,
                        "ignored: it is only for rods.h5, and output.rods_format is csv");
  }
  output.rods_csv = spec.rods_format.value != "h5md";
  output.rods_h5md = spec.rods_format.value != "csv";
  output.h5md_double = spec.h5md_precision.value == "double";
  output.trajectory_interval = spec.trajectory_interval.value;
  output.trajectory_named = spec.trajectory_style.value == "named";
  output.trajectory_steps =
      output.trajectory_interval > 0.0 ? to_steps(spec.trajectory_interval, dt, diagnostics) : 0;
  output.checkpoint_interval = spec.checkpoint_interval.value;
  output.checkpoint_steps =
      std::max<std::int64_t>(1, std::llround(spec.checkpoint_interval.value / dt));
  output.bullet_snapshots = spec.bullet_snapshots.value;
  std::sort(output.bullet_snapshots.begin(), output.bullet_snapshots.end());
  for (const double time : output.bullet_snapshots) {
    if (time > spec.duration.value) {
      diagnostics.error(spec.bullet_snapshots.where, spec.bullet_snapshots.path,
                        "a snapshot at " + format_real(time) + " s is after the end of the run (" +
                            format_real(spec.duration.value) + " s)");
    }
    output.snapshot_steps.push_back(std::llround(time / dt));
  }
  scenario.metrics.stationary_threshold = spec.stationary_threshold.value;
  scenario.metrics.window = spec.metrics_window.value;
  scenario.metrics.held_distance = spec.held_distance.value;
  scenario.metrics.held_lag = spec.held_lag.value;
  const auto short_real = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return std::string(text);
  };
  const double window_frames = spec.metrics_window.value / spec.frame_interval.value;
  if (window_frames < 1.0 - 1e-9) {
    // Pointed at the key the user wrote: the window, or else the frame interval.
    if (spec.metrics_window.given || !spec.frame_interval.given) {
      diagnostics.error(spec.metrics_window.where, spec.metrics_window.path,
                        "must be at least output.frame_interval (" +
                            format_real(spec.frame_interval.value) + " s), got " +
                            format_real(spec.metrics_window.value) +
                            " s: speeds are measured between frames");
    } else {
      diagnostics.error(spec.frame_interval.where, spec.frame_interval.path,
                        "must be at most metrics.window (" +
                            format_real(spec.metrics_window.value) + " s, its default), got " +
                            format_real(spec.frame_interval.value) +
                            " s: speeds are measured between frames; set metrics.window too");
    }
  } else if (std::abs(window_frames - std::round(window_frames)) > 1e-3) {
    // The observer measures a speed between a frame and the latest frame at least one window
    // earlier (metrics_observer.cpp): over a whole number of frame intervals.
    const double frames = std::ceil(window_frames - 1e-3);
    diagnostics.warning(
        spec.metrics_window.given ? spec.metrics_window.where : spec.frame_interval.where,
        spec.metrics_window.path,
        format_real(spec.metrics_window.value) +
            " s is not a multiple of output.frame_interval = " +
            format_real(spec.frame_interval.value) + " s; speeds are measured over " +
            format_real(frames) + " frame intervals (" +
            short_real(frames * spec.frame_interval.value) + " s)");
  }

  if (diagnostics.error_count() != errors_before) return std::nullopt;

  std::vector<SpeciesPlacement> placements;
  for (std::size_t i = 0; i < spec.species.size(); ++i) {
    const SpeciesSpec& species = spec.species[i];
    SpeciesPlacement placement;
    placement.species = static_cast<int>(i);
    placement.count = counts.per_species[i];
    placement.shape = shapes[i];
    placement.region = region_of(species.initial_region.value);
    const NumberOrKeyword& heading = species.initial_heading.value;
    placement.heading.kind = heading.is("random")        ? PlacementHeading::Kind::random
                             : heading.is("toward_apex") ? PlacementHeading::Kind::toward_apex
                                                         : PlacementHeading::Kind::fixed;
    placement.heading.angle = degrees_to_radians(heading.number);
    placements.push_back(placement);
  }
  PlacementCell cell{model.box_x,
                     model.box_y,
                     model.walls,
                     scenario.trap.get(),
                     v_trap ? std::optional<Eigen::Vector2d>(v_trap->apex()) : std::nullopt,
                     scenario.cell.get()};
  PlacementResult placed = place_rods(cell, placements, model.seed);
  if (placed.failure) {
    const SpeciesSpec& species = spec.species[static_cast<std::size_t>(placed.failure->species)];
    diagnostics.error(species.count.where, species.count.path,
                      "could place only " + std::to_string(placed.failure->placed) + " of " +
                          std::to_string(placed.failure->requested) + " rods of species " +
                          species.name.value + " without overlap (" +
                          std::to_string(kPlacementAttempts) +
                          " random draws failed for the next one); use fewer rods or more room");
    return std::nullopt;
  }
  model.rods = std::move(placed.rods);
  if (model.exact_contact_solver && model.rods.size() > kExactSolverRods) {
    diagnostics.warning(spec.contact_solver.where, spec.contact_solver.path,
                        "exact solves of " + std::to_string(model.rods.size()) +
                            " rods: its cost grows as the cube of the contacts solved together, "
                            "and crowded rods are solved together; meant for lone rods");
  }
  return scenario;
}

}  // namespace rodsort::scenarios
