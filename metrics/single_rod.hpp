#pragma once
// What a single free rod does, the two numbers that summarise an active Brownian particle:
// its self-propulsion speed v0 along its axis, and the rotational diffusion D_r of its heading.
// The experiments give v0 = 3.6 +- 2.5 mm/s toward the thin end (Nat. Commun. 5, 4688); the
// collision kick eps = 0.01 /mm was chosen in the paper to reproduce the measured D_r.

#include <vector>

#include "engine/frame.hpp"

namespace rodsort::metrics {

/// Mean axial speed v0 [mm/s], positive toward the thin end: over every listed rod and every pair
/// of frames `lag` apart, the displacement of the unwrapped centre projected on the rod's in-plane
/// axis (the normalised sum of the two frames' in-plane thick-to-thin axes), over the time between
/// the frames. Measuring over a window rather than from instantaneous velocities filters out the
/// fast rattling between the plates.
double mean_axial_speed(const std::vector<engine::Frame>& frames, const std::vector<int>& rods,
                        int lag = 1);

struct RotationalDiffusion {
  double coefficient = 0.0;         ///< D_r [rad^2/s]
  double intercept = 0.0;           ///< c of the fit [rad^2]: short-time rattling of the heading
  std::vector<double> lag_times;    ///< [s]
  std::vector<double> mean_square;  ///< <(phi(t + lag) - phi(t))^2> per lag [rad^2]
};

/// Rotational diffusion from the mean squared change of the unwrapped in-plane heading phi.
/// phi is unwrapped frame by frame (each step's change wrapped into (-pi, pi], so frames must be
/// close enough that a rod turns by less than half a turn between them); the mean square is
/// averaged over all listed rods and all start frames, for lags of min_lag..max_lag frames; a
/// least-squares line MSD = c + 2 D_r t over those lags gives D_r. The intercept keeps the fast,
/// bounded rattling of the heading out of D_r.
RotationalDiffusion rotational_diffusion(const std::vector<engine::Frame>& frames,
                                         const std::vector<int>& rods, int min_lag, int max_lag);

}  // namespace rodsort::metrics
