#include "engine/model.hpp"

#include "engine/units.hpp"

namespace rodsort::engine {

double Drive::amplitude_from_gamma(double gamma, double frequency) {
  const double omega = 2.0 * kPi * frequency;
  return gamma * kGravity / (omega * omega);
}

Drive Drive::paper() {
  constexpr double kFrequency = 200.0;
  return {kFrequency, amplitude_from_gamma(7.0, kFrequency), 1.2};
}

double Drive::gamma() const {
  const double omega = 2.0 * kPi * frequency;
  return amplitude * omega * omega / kGravity;
}

}  // namespace rodsort::engine
