#pragma once
// rodsort works in millimetre, gram, second everywhere inside; angles in radians.

namespace rodsort {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kGravity = 9810.0;  ///< standard gravity [mm/s^2]
inline constexpr double kBrassDensity = 8.5e-3;  ///< [g/mm^3]

inline constexpr double degrees_to_radians(double degrees) { return degrees * kPi / 180.0; }
inline constexpr double radians_to_degrees(double radians) { return radians * 180.0 / kPi; }

}  // namespace rodsort
