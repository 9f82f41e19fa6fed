#include "scenarios/plausibility.hpp"

#include <algorithm>
#include <cmath>

#include "scenarios/number_text.hpp"

namespace rodsort::scenarios {
namespace {

double thinnest_radius(const engine::RodShape& shape) {
  double thinnest = shape.max_radius;
  for (const engine::Sphere& sphere : shape.spheres) thinnest = std::min(thinnest, sphere.radius);
  return thinnest;
}

/// Farthest sphere centre from the centre of mass: how far a turn by one radian moves it [mm].
double lever_arm(const engine::RodShape& shape) {
  double arm = 0.0;
  for (const engine::Sphere& sphere : shape.spheres) arm = std::max(arm, std::abs(sphere.axial));
  return arm;
}

std::string mm(double value) { return format_real(value) + " mm"; }

/// Three significant digits: the bounds are estimates, and 17 digits would pretend otherwise.
std::string rounded(double value) {
  if (value == 0.0 || !std::isfinite(value)) return format_real(value);
  // Dividing by an exact power of ten keeps the shortest form short (0.123, not
  // 0.12300000000000001).
  const double exponent = std::floor(std::log10(std::abs(value))) - 2.0;
  const double power = std::pow(10.0, std::abs(exponent));
  return format_real(exponent < 0.0 ? std::round(value * power) / power
                                    : std::round(value / power) * power);
}

std::string rounded_mm(double value) { return rounded(value) + " mm"; }

}  // namespace

void check_step_travel(const ScenarioSpec& spec, const engine::Model& model,
                       Diagnostics& diagnostics) {
  const double dt = model.dt;
  double thinnest = 0.0;
  for (std::size_t i = 0; i < model.species.size(); ++i) {
    const double r = thinnest_radius(model.species[i].shape);
    thinnest = i == 0 ? r : std::min(thinnest, r);
  }
  const double allowed = kMaxStepTravel * thinnest;

  // The plates move at up to A 2 pi f.
  const double plate_speed = model.drive.amplitude * 2.0 * M_PI * model.drive.frequency;
  const bool drive_resolved = plate_speed * dt <= allowed;
  if (!drive_resolved) {
    const bool by_amplitude = spec.amplitude.has_value();
    const Sourced<double>& source = by_amplitude ? *spec.amplitude : *spec.gamma;
    diagnostics.error(source.where, source.path,
                      "got " + format_real(source.value) + ": the plates move up to " +
                          rounded_mm(plate_speed * dt) + " in one step (A 2 pi f dt, " +
                          "A = " + rounded_mm(model.drive.amplitude) +
                          "), more than half the thinnest " + "sphere's radius (" + mm(allowed) +
                          "): contacts with the plates would be missed; " + "lower " +
                          (by_amplitude ? "the amplitude" : "gamma") + " or run.dt");
  }

  for (std::size_t i = 0; i < model.species.size(); ++i) {
    const engine::Species& species = model.species[i];
    const SpeciesSpec& source = spec.species[i];
    const double arm = lever_arm(species.shape);
    const double own_allowed = kMaxStepTravel * thinnest_radius(species.shape);
    // A kick adds eps v_rel to the spin at an impact; v_rel is at most about twice the plates'
    // speed (a rod falling at it onto a plate rising at it).
    const double kick_spin = species.noise.kick_eps * 2.0 * plate_speed;  // [rad/s]
    // A drive already refused would make every kick look too strong: one message is enough.
    if (drive_resolved && kick_spin * arm * dt > own_allowed) {
      diagnostics.error(
          source.kick_eps.where, source.kick_eps.path,
          "got " + format_real(species.noise.kick_eps) + " /mm: one kick spins a rod at up to " +
              rounded(kick_spin) +
              " rad/s (eps x twice the plates' speed), which turns its tips by " +
              rounded_mm(kick_spin * arm * dt) + " in one step, more than half its thinnest " +
              "sphere's radius (" + mm(own_allowed) + "); expected kick_eps <= " +
              rounded(own_allowed / (2.0 * plate_speed * arm * dt)) + " /mm at this run.dt");
    } else if (species.noise.kick_eps * arm > 1.0) {
      // The spin eps v_rel of a kick moves the end spheres at eps arm v_rel: beyond eps = 1 / arm
      // a kick gives them more speed than the impact had (RnT at eps = 5 on a rough base went
      // 1.2 mm into the base within 0.02 s; at 0.25-2 its contacts went 0.06-0.35 mm deep).
      diagnostics.error(source.kick_eps.where, source.kick_eps.path,
                        "got " + format_real(species.noise.kick_eps) +
                            " /mm: one kick moves the rod's end spheres at " +
                            rounded(species.noise.kick_eps * arm) +
                            " times the speed of the impact that gave it (eps x their distance " +
                            "from the centre of mass, " + rounded_mm(arm) +
                            "); expected kick_eps <= " + rounded(1.0 / arm) + " /mm");
    }
    // White noise turns a rod by sqrt(2 D_r dt) per step (one standard deviation).
    const double turn = std::sqrt(2.0 * species.noise.white_Dr * dt);
    if (turn * arm > own_allowed) {
      diagnostics.error(
          source.white_Dr.where, source.white_Dr.path,
          "got " + format_real(species.noise.white_Dr) + " rad^2/s, which turns " + "a rod by " +
              rounded(turn) + " rad per step (sqrt(2 D_r dt)), " + "its tips by " +
              rounded_mm(turn * arm) + ", more than half its " + "thinnest sphere's radius (" +
              mm(own_allowed) + "); expected " +
              "white_Dr <= " + rounded(own_allowed * own_allowed / (2.0 * arm * arm * dt)) +
              " rad^2/s at this run.dt, or a smaller run.dt");
    }
  }
}

}  // namespace rodsort::scenarios
