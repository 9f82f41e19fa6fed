// The rough plate's height field. Wave vectors are drawn on the lattice of the periodic cell,
// (2 pi n_x / L_x, 2 pi n_y / L_y) with integer n, so that h is periodic like the cell and a rod
// meets the same surface through either edge. A wave vector and its opposite give the same mode,
// so each is kept in one half plane and drawn again if already taken: distinct modes are
// orthogonal over the cell, which makes the mean squared slope exactly the sum over the modes.
#include "engine/plate_roughness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/random_stream.hpp"
#include "engine/units.hpp"

namespace rodsort::engine {

PlateRoughness::PlateRoughness(double slope, double wavelength, double box_x, double box_y,
                               std::uint64_t seed, int plate) {
  if (!(slope > 0.0) || !(wavelength > 0.0) || !(box_x > 0.0) || !(box_y > 0.0)) {
    throw std::invalid_argument("plate roughness needs a positive slope, wavelength and cell");
  }
  RandomStream random(seed, static_cast<std::uint64_t>(plate), StreamPurpose::kRoughness);
  const double step_x = 2.0 * kPi / box_x;
  const double step_y = 2.0 * kPi / box_y;
  const double k_mean = 2.0 * kPi / wavelength;
  std::vector<std::pair<long long, long long>> taken;
  double sum_k2 = 0.0;
  // A cell much smaller than the wavelength has too few lattice points in the band to hold
  // kModes distinct modes; the draws are bounded so that such a cell fails instead of looping.
  for (int attempt = 0; attempt < 100 * kModes && static_cast<int>(modes_.size()) < kModes;
       ++attempt) {
    const double k = k_mean * (0.5 + random.uniform());
    const double direction = 2.0 * kPi * random.uniform();
    const double phase = 2.0 * kPi * random.uniform();
    long long nx = std::llround(k * std::cos(direction) / step_x);
    long long ny = std::llround(k * std::sin(direction) / step_y);
    if (ny < 0 || (ny == 0 && nx < 0)) {
      nx = -nx;
      ny = -ny;
    }
    if (nx == 0 && ny == 0) continue;
    if (std::find(taken.begin(), taken.end(), std::make_pair(nx, ny)) != taken.end()) continue;
    taken.emplace_back(nx, ny);
    const Mode mode{static_cast<double>(nx) * step_x, static_cast<double>(ny) * step_y, phase};
    sum_k2 += mode.kx * mode.kx + mode.ky * mode.ky;
    modes_.push_back(mode);
  }
  if (static_cast<int>(modes_.size()) < kModes) {
    throw std::invalid_argument(
        "the periodic cell is too small for a rough plate of this "
        "wavelength: fewer than 64 distinct wave vectors fit");
  }
  // <|grad h|^2> = sum_j a^2 k_j^2 / 2 = slope^2.
  amplitude_ = slope / std::sqrt(sum_k2 / 2.0);
  reach_ = amplitude_ * kModes;
  for (const Mode& mode : modes_) max_slope_ += amplitude_ * std::hypot(mode.kx, mode.ky);
  rms_height_ = amplitude_ * std::sqrt(kModes / 2.0);
}

PlateRoughness::Surface PlateRoughness::at(double x, double y) const {
  Surface surface{0.0, 0.0, 0.0};
  for (const Mode& mode : modes_) {
    const double angle = mode.kx * x + mode.ky * y + mode.phase;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    surface.height += c;
    surface.slope_x -= mode.kx * s;
    surface.slope_y -= mode.ky * s;
  }
  surface.height *= amplitude_;
  surface.slope_x *= amplitude_;
  surface.slope_y *= amplitude_;
  return surface;
}

}  // namespace rodsort::engine
