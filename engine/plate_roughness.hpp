#pragma once
// A rough plate: the surface of the base or the lid is not flat but carries a fixed random height
// field h(x, y), the same at every cycle of the drive, that the rods meet wherever they land.

#include <cstdint>
#include <vector>

namespace rodsort::engine {

/// Roughness of the plates' surfaces; a slope of 0 is a flat plate (the paper's model).
struct Roughness {
  double base_slope = 0.0;   ///< RMS slope of the base's surface [rad]
  double lid_slope = 0.0;    ///< RMS slope of the lid's surface [rad]
  double wavelength = 0.25;  ///< mean wavelength of the height field [mm]
};

/// The height field of one rough plate: a sum of kModes sinusoids whose wavelengths spread
/// uniformly in wavenumber over [0.5, 1.5] times 2 pi / wavelength, in random directions and with
/// random phases, each fitting the periodic cell a whole number of times, so that the field is
/// periodic like the cell. All modes have the same amplitude, chosen so that the mean of |grad h|^2
/// over the cell is slope^2. The field depends only on its arguments: it is no part of the State.
class PlateRoughness {
 public:
  static constexpr int kModes = 64;

  /// `plate` tells base (0) and lid (1) apart, so that their fields are independent.
  PlateRoughness(double slope, double wavelength, double box_x, double box_y, std::uint64_t seed,
                 int plate);

  struct Surface {
    double height;   ///< h above the nominal surface [mm]
    double slope_x;  ///< dh/dx
    double slope_y;  ///< dh/dy
  };
  Surface at(double x, double y) const;

  /// An upper bound of |h| anywhere: the sum of the modes' amplitudes [mm].
  double reach() const { return reach_; }
  /// An upper bound of |grad h| anywhere: the sum of the modes' amplitudes times wavenumbers.
  double max_slope() const { return max_slope_; }
  /// RMS height over the cell [mm].
  double rms_height() const { return rms_height_; }

 private:
  struct Mode {
    double kx, ky, phase;
  };
  std::vector<Mode> modes_;
  double amplitude_ = 0.0;
  double reach_ = 0.0;
  double max_slope_ = 0.0;
  double rms_height_ = 0.0;
};

}  // namespace rodsort::engine
