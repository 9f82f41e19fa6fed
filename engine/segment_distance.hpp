#pragma once
// Distance between two line segments, for any vector type with +, -, * scalar and dot() (Bullet's
// btVector3 in the rod-rod collision test, Eigen's vectors in initial placement).

#include <algorithm>

namespace rodsort::engine {

/// Squared distance between the segments [p0, p1] and [q0, q1] (the closest points of Ericson,
/// Real-Time Collision Detection, 5.1.9). Degenerate segments (points) are allowed.
template <typename Vector>
double segment_distance_squared(const Vector& p0, const Vector& p1, const Vector& q0,
                                const Vector& q1) {
  const Vector d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  constexpr double kPoint = 1e-300;  // squared length below which a segment is a point [mm^2]
  double s = 0.0, t = 0.0;
  if (a <= kPoint && e <= kPoint) return r.dot(r);
  if (a <= kPoint) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kPoint) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denominator = a * e - b * b;
      // Parallel segments: any s is as good; take 0 and let t, then s, be clamped.
      s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const Vector gap = (p0 + d1 * s) - (q0 + d2 * t);
  return gap.dot(gap);
}

}  // namespace rodsort::engine
