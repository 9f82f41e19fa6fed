#pragma once
// What one free rod does on the vibrated plate, as the experiments report it: the axial velocity
// V_x over the camera's interval (its mean is v0, its distribution P(V_x) shows runs and tumbles),
// the mean squared displacement of the centre, and the decorrelation of the heading (D_r and the
// persistence time). A track is one rod followed frame by frame, unwrapped: positions across the
// periodic edges and headings across +-pi, so every lag sees the real motion.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "engine/frame.hpp"

namespace rodsort::metrics {

struct Track {
  std::vector<double> time;               ///< [s], equally spaced
  std::vector<Eigen::Vector2d> position;  ///< unwrapped centre of mass [mm]
  std::vector<double> heading;            ///< unwrapped in-plane thick-to-thin direction [rad]
  std::vector<double> tilt;  ///< vertical component of the thick-to-thin axis (< 0: thin end down)
};

/// Rod `rod` of every frame as a track. Frames must be close enough that the rod turns by less
/// than half a turn between two of them.
Track track_of(const std::vector<engine::Frame>& frames, int rod);

/// A rod's roll about its own axis [rad], in (-pi, pi]: the angle of its body y axis from the
/// horizontal direction to the left of its axis, counter-clockwise seen from the thin end, so that
/// pi / 2 has body y pointing up. `basis` is the rotation matrix, row-major, whose first column is
/// the rod's axis (engine::RodState::basis). For a rod whose spheres lie off its axis, body y
/// points to their side (engine/rod_shape.hpp): the roll says where the off-axis part lies.
double roll_angle(const std::array<double, 9>& basis);

/// A track of the roll instead of the heading: `track` with its heading replaced by `roll`, one
/// angle per sample, unwrapped across +-pi, so that D_r, turn_rate and without_steady_turn read the
/// rod's turning about its own axis.
Track roll_track(const Track& track, const std::vector<double>& roll);

/// The fraction of all samples of the tracks in which the thin end is lower than the thick one
/// (tilt < 0): the tilt of the gait that moves a tapered rod toward its thin end. NaN for no
/// samples.
double thin_end_down_fraction(const std::vector<Track>& tracks);

/// Axial velocity over windows of `lag` samples [mm/s]: the displacement from sample i to i + lag
/// projected on the mean in-plane axis of the two samples, over the time between them; positive
/// toward the thin end. Windows start every `stride` samples (stride = lag: back to back).
std::vector<double> axial_velocities(const Track& track, int lag, int stride);

/// Averages over tracks and start samples, at each lag (in samples).
struct LagStatistics {
  std::vector<double> lag_time;                 ///< [s]
  std::vector<double> position_msd;             ///< <|r(t + lag) - r(t)|^2> [mm^2]
  std::vector<double> heading_msd;              ///< <(phi(t + lag) - phi(t))^2> [rad^2]
  std::vector<double> orientation_correlation;  ///< <cos(phi(t + lag) - phi(t))>
};
LagStatistics lag_statistics(const std::vector<Track>& tracks, const std::vector<int>& lags);

/// D_r from a least-squares line heading_msd = c + 2 D_r t over the given lag times; the intercept
/// keeps the fast, bounded rattling of the heading out of D_r [rad^2/s].
double rotational_diffusion_fit(const std::vector<double>& lag_time,
                                const std::vector<double>& heading_msd);

/// The steady part of the heading's change: the net turn from the first sample to the last over
/// the time between them [rad/s], counter-clockwise positive. A rod whose heading diffuses turns
/// by about sqrt(2 D_r T) over a track of duration T, so this rate falls as 1/sqrt(T); a rod that
/// circles keeps it. NaN for a track of fewer than two samples.
double turn_rate(const Track& track);

/// The track with a steady turn taken out of its heading: phi(t) - rate (t - t_first). A steady
/// turn makes the heading's MSD grow as rate^2 t^2, which a line c + 2 D_r t reads as a large D_r;
/// the heading's MSD of this track is the diffusion about the turn alone.
Track without_steady_turn(const Track& track, double rate);

/// Whether a rod circles: its net turn over the track, |rate| T, exceeds one full turn and five
/// times the sqrt(2 D T) that a heading diffusing with `diffusion_about_turn` [rad^2/s] would
/// reach by chance (a chance below 1e-6 for a rod that does not circle).
bool circles(double rate, double duration, double diffusion_about_turn);

/// Runs and tumbles from back-to-back windows: a window runs when its axial velocity exceeds the
/// threshold, tumbles otherwise; consecutive windows of one kind make one run or one tumble.
/// Segments cut by the start or the end of a series are counted in the fraction but not in the
/// durations.
///
/// With the heading at every window boundary (`boundary_headings[k]` has one more entry than
/// `velocity_series[k]`: the heading where each window starts, and where the last ends), the
/// turn over each complete segment is its heading change from its first window's start to its
/// last window's end, taken to (-pi, pi]: how far a tumble turns the rod between the run before
/// and the run after. A tumble that picks a new direction at random turns it by pi / sqrt(3)
/// (104 degrees) RMS; a pause turns it no more than a run of the same length does.
struct RunsAndTumbles {
  double threshold = 0.0;         ///< [mm/s]
  double running_fraction = 0.0;  ///< of all windows
  double mean_run = 0.0;          ///< duration of complete runs [s]; NaN when there is none
  double mean_tumble = 0.0;       ///< duration of complete tumbles [s]; NaN when there is none
  long runs = 0;                  ///< complete runs
  long tumbles = 0;               ///< complete tumbles
  double run_turn_rms = 0.0;      ///< RMS turn over a complete run [rad]; NaN without headings
  double tumble_turn_rms = 0.0;   ///< RMS turn over a complete tumble [rad]; NaN without headings
};
RunsAndTumbles runs_and_tumbles(const std::vector<std::vector<double>>& velocity_series,
                                double window, double threshold,
                                const std::vector<std::vector<double>>& boundary_headings = {});

/// A window goes backward when the rod moves against its heading faster than this [mm/s]: well
/// beyond the rattling of a rod at rest along its axis.
inline constexpr double kBackwardSpeed = 1.0;

/// The fraction of the axial velocities V_x below -kBackwardSpeed; NaN without any.
double backward_fraction(const std::vector<double>& axial_velocities);

/// The heading at every boundary of back-to-back windows of `lag` samples, as
/// axial_velocities(track, lag, lag) lays them: samples 0, lag, 2 lag, ... while a window fits.
std::vector<double> window_boundary_headings(const Track& track, int lag);

/// The q-quantile (0..1) of the values, by linear interpolation between order statistics.
double quantile(std::vector<double> values, double q);

/// The two highest peaks of a distribution given as a density on equal bins (P(V_x)), after a
/// running mean over three bins. The second peak is the highest bin that is separated from the
/// main one by a valley: the lowest density between them relative to the second peak's height.
/// P(V_x) of run-and-tumble motion has a tumble peak near zero and a run peak; a unimodal
/// distribution has no second peak (second_height 0, valley 1).
struct TwoPeaks {
  double main = 0.0;           ///< position of the highest peak (bin centre)
  double second = 0.0;         ///< position of the second peak
  double second_height = 0.0;  ///< its height relative to the main peak's
  double valley = 1.0;         ///< lowest density between the peaks over the second's height
  /// Two clear peaks: the second at least 10% as high as the main one, a valley at most half
  /// the second's height between them.
  bool bimodal() const { return second_height >= 0.1 && valley <= 0.5; }
};
TwoPeaks two_peaks(const std::vector<double>& bin_centre, const std::vector<double>& density);

}  // namespace rodsort::metrics
