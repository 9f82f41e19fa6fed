#include "runner/single_particle.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>

#include "engine/simulation.hpp"
#include "metrics/histogram.hpp"
#include "metrics/sample_statistics.hpp"
#include "metrics/single_particle.hpp"
#include "runner/atomic_file.hpp"
#include "runner/clocks.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/progress.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::runner {
namespace {

/// Lags of the heading fit and of lags.csv beyond it, in windows.
constexpr int kFitMaxWindows = 10;
constexpr int kLagMaxWindows = 100;
/// Width of the bins of P(V_x) [mm/s].
constexpr double kVelocityBin = 0.5;

std::string number(double value) { return scenarios::format_real(value); }

/// The golden ratio's fractional part: the rolls of successive rods, as fractions of a turn, spread
/// evenly whatever their number.
constexpr double kGoldenFraction = 0.6180339887498949;

/// The model of one free rod of species `species`, alone in a periodic cell.
engine::Model single_rod_model(const engine::Model& scenario_model, int species, double cell,
                               double heading, double roll, std::uint64_t seed) {
  engine::Model model = scenario_model;
  model.box_x = model.box_y = cell;
  model.walls.clear();
  model.species = {scenario_model.species[static_cast<std::size_t>(species)]};
  model.rods = {{0, 0.5 * cell, 0.5 * cell, heading, roll}};
  model.seed = seed;
  return model;
}

/// P(V_x) on bins of kVelocityBin that cover every value.
metrics::Histogram velocity_histogram(const std::vector<double>& velocities) {
  double low = 0.0, high = 0.0;
  for (const double v : velocities) {
    low = std::min(low, v);
    high = std::max(high, v);
  }
  low = kVelocityBin * std::floor(low / kVelocityBin);
  high = kVelocityBin * (std::floor(high / kVelocityBin) + 1.0);
  metrics::Histogram histogram(low, high,
                               static_cast<int>(std::lround((high - low) / kVelocityBin)));
  histogram.add(velocities);
  return histogram;
}

/// D_r of one track from its heading's MSD at the given lags (in samples).
double rotational_diffusion_of(const metrics::Track& track, const std::vector<int>& lags) {
  const metrics::LagStatistics statistics = metrics::lag_statistics({track}, lags);
  return metrics::rotational_diffusion_fit(statistics.lag_time, statistics.heading_msd);
}

struct RodResult {
  metrics::Track track;
  std::vector<double> velocities;    ///< overlapping windows, one per sample
  std::vector<double> back_to_back;  ///< windows back to back
  metrics::Track roll;               ///< the track with its roll for heading; off-axis shapes only
  std::int64_t kicks = 0;
};

/// An off-axis shape's roll over the rods: per rod its steady rate, the diffusion about it and its
/// circular mean; the mean |rate|, the diffusion over rods, and the share of samples with the
/// off-axis part above the axis. Empty (NaN) for a straight rod.
struct RollSummary {
  std::vector<double> rates, diffusions, means;
  double mean_abs_rate = std::nan("");
  metrics::SampleStatistics diffusion{std::nan(""), std::nan(""), std::nan("")};
  double up_fraction = std::nan("");
  double rate(std::size_t r) const { return r < rates.size() ? rates[r] : std::nan(""); }
  double diffusion_of(std::size_t r) const {
    return r < diffusions.size() ? diffusions[r] : std::nan("");
  }
  double mean_of(std::size_t r) const { return r < means.size() ? means[r] : std::nan(""); }
};

/// The mean direction of angles[first, last) [rad], in (-pi, pi].
double circular_mean(const std::vector<double>& angles, std::size_t first, std::size_t last) {
  double sum_sin = 0.0, sum_cos = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    sum_sin += std::sin(angles[i]);
    sum_cos += std::cos(angles[i]);
  }
  return std::atan2(sum_sin, sum_cos);
}

RollSummary summarize_rolls(const std::vector<RodResult>& rods, const std::vector<int>& fit_lags) {
  RollSummary summary;
  long up = 0, samples = 0;
  double abs_rate = 0.0;
  for (const RodResult& rod : rods) {
    const double rate = metrics::turn_rate(rod.roll);
    summary.rates.push_back(rate);
    abs_rate += std::abs(rate);
    summary.diffusions.push_back(
        rotational_diffusion_of(metrics::without_steady_turn(rod.roll, rate), fit_lags));
    for (const double angle : rod.roll.heading) up += std::sin(angle) > 0.0 ? 1 : 0;
    summary.means.push_back(circular_mean(rod.roll.heading, 0, rod.roll.heading.size()));
    samples += static_cast<long>(rod.roll.heading.size());
  }
  if (rods.empty() || samples == 0) return summary;
  summary.mean_abs_rate = abs_rate / static_cast<double>(rods.size());
  summary.diffusion = metrics::sample_statistics(summary.diffusions);
  summary.up_fraction = static_cast<double>(up) / static_cast<double>(samples);
  return summary;
}

/// roll_windows.csv: each back-to-back window's mean roll (circular, over its samples) beside the
/// heading's turn over it and its V_x, for every rod: how the side on which the off-axis part lies
/// steers the rod (scripts/roll-states).
CsvTable roll_windows_table(const std::vector<RodResult>& rods, int window_samples) {
  CsvTable table;
  table.header = {"rod", "t_s", "roll_rad", "turn_rad", "vx_mm_s"};
  const std::size_t w = static_cast<std::size_t>(window_samples);
  for (std::size_t r = 0; r < rods.size(); ++r) {
    const metrics::Track& track = rods[r].track;
    const metrics::Track& roll = rods[r].roll;
    for (std::size_t k = 0; k < rods[r].back_to_back.size(); ++k) {
      table.rows.push_back({std::to_string(r), number(track.time[k * w]),
                            number(circular_mean(roll.heading, k * w, (k + 1) * w + 1)),
                            number(track.heading[(k + 1) * w] - track.heading[k * w]),
                            number(rods[r].back_to_back[k])});
    }
  }
  return table;
}

/// What the dt comparison reads of one study.
struct StudyNumbers {
  double dt = 0.0;
  double v0 = 0.0, v0_sem = 0.0;
  double diffusion = 0.0, diffusion_sem = 0.0;
  double running = 0.0, backward = 0.0;
};

int run_study(const SingleParticleRequest& request, std::ostream& out, std::ostream& err,
              StudyNumbers& numbers) {
  const scenarios::LoadResult loaded =
      scenarios::load_scenario_with_options(request.scenario, request.set_options);
  err << scenarios::format_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return kExitUsage;
  const scenarios::Scenario& scenario = *loaded.scenario;
  const engine::Model& model = scenario.model;

  int species = 0;
  if (!request.species.empty()) {
    species = -1;
    std::string names;
    for (std::size_t s = 0; s < model.species.size(); ++s) {
      if (model.species[s].name == request.species) species = static_cast<int>(s);
      names += (names.empty() ? "" : ", ") + model.species[s].name;
    }
    if (species < 0) {
      err << "rodsort: error: --species: no species '" << request.species << "' in "
          << request.scenario.string() << " (it has " << names << ")\n";
      return kExitUsage;
    }
  }
  const double window = scenario.metrics.window;
  const std::int64_t sample_steps = std::llround(request.sample_interval / model.dt);
  const int window_samples =
      static_cast<int>(std::lround(window / (static_cast<double>(sample_steps) * model.dt)));
  if (sample_steps < 1 || window_samples < 1 ||
      std::abs(static_cast<double>(window_samples * sample_steps) * model.dt - window) >
          1e-9 * window) {
    err << "rodsort: error: --sample " << request.sample_interval << ": must be a multiple of dt ("
        << model.dt << " s) that divides metrics.window (" << window << " s)\n";
    return kExitUsage;
  }
  if (request.duration < 2.0 * kFitMaxWindows * window) {
    err << "rodsort: error: --duration " << request.duration << ": must be at least "
        << 2.0 * kFitMaxWindows * window << " s (twice the lags of the D_r fit, " << kFitMaxWindows
        << " windows)\n";
    return kExitUsage;
  }
  const double longest_rod = scenario.species[static_cast<std::size_t>(species)].length;
  if (request.cell < 4.0 * longest_rod) {
    err << "rodsort: error: --cell " << request.cell << ": must be at least four rod lengths ("
        << 4.0 * longest_rod << " mm), or the rod meets its own image\n";
    return kExitUsage;
  }
  const double period = 1.0 / model.drive.frequency;
  const std::int64_t samples = std::llround(request.duration / request.sample_interval);
  const std::string& species_name = model.species[static_cast<std::size_t>(species)].name;
  const bool straight =
      engine::is_straight(model.species[static_cast<std::size_t>(species)].shape.spheres);

  std::vector<RodResult> rods;
  const double cpu_start = process_cpu_seconds();
  const double wall_start = wall_seconds();
  // Progress counts rod-seconds: the rods done times the measured time of each.
  ProgressReporter progress(stderr, isatty(fileno(stderr)) != 0);
  const auto progress_sample = [&](int rods_done) {
    ProgressSample sample;
    sample.simulated_s = request.duration * rods_done;
    sample.duration_s = request.duration * request.rods;
    sample.session_wall_s = wall_seconds() - wall_start;
    sample.session_cpu_s = process_cpu_seconds() - cpu_start;
    return sample;
  };
  for (int rod = 0; rod < request.rods; ++rod) {
    const double heading = 2.0 * std::numbers::pi * rod / request.rods;
    // A rod that is not straight starts with its off-axis part turned about the axis by another
    // fraction of the circle for each rod, in an order unrelated to the heading's.
    const double roll =
        straight ? 0.0 : 2.0 * std::numbers::pi * std::fmod(rod * kGoldenFraction, 1.0);
    engine::Simulation simulation(single_rod_model(model, species, request.cell, heading, roll,
                                                   model.seed + static_cast<std::uint64_t>(rod)));
    const double warmup = request.warmup + period * rod / request.rods;
    simulation.advance(std::llround(warmup / model.dt));
    const std::int64_t kicks_before = simulation.counters().kicks;
    std::vector<engine::Frame> frames{simulation.frame()};
    // The roll is not in a frame: it is read off the body's basis, for shapes where it matters.
    std::vector<double> rolls;
    const auto record_roll = [&] {
      if (!straight) rolls.push_back(metrics::roll_angle(simulation.state().rods[0].basis));
    };
    record_roll();
    for (std::int64_t s = 0; s < samples; ++s) {
      simulation.advance(sample_steps);
      frames.push_back(simulation.frame());
      record_roll();
    }
    RodResult result;
    result.track = metrics::track_of(frames, 0);
    if (!straight) result.roll = metrics::roll_track(result.track, rolls);
    result.velocities = metrics::axial_velocities(result.track, window_samples, 1);
    result.back_to_back = metrics::axial_velocities(result.track, window_samples, window_samples);
    result.kicks = simulation.counters().kicks - kicks_before;
    rods.push_back(std::move(result));
    progress.update(progress_sample(rod + 1));
  }
  progress.finish(progress_sample(request.rods));
  const double cpu = process_cpu_seconds() - cpu_start;

  // Per rod: v0, the spread of V_x, D_r from the heading's MSD over 1..10 windows, running.
  std::vector<int> fit_lags, all_lags;
  // lags.csv: every sample up to one window, then whole windows, as long as a track lasts.
  for (int s = 1; s < window_samples; ++s) all_lags.push_back(s);
  for (int w = 1; w <= kLagMaxWindows; ++w) {
    if (w <= kFitMaxWindows) fit_lags.push_back(w * window_samples);
    if (w * window_samples < samples) all_lags.push_back(w * window_samples);
  }
  std::vector<double> every_velocity, per_rod_speed, per_rod_deviation, per_rod_diffusion;
  // A rod that circles turns steadily: its turn rate, D_r about that turn, and whether it circles.
  std::vector<double> per_rod_turn_rate, per_rod_diffusion_about_turn;
  std::vector<bool> per_rod_circles;
  std::vector<std::vector<double>> series, boundary_headings;
  std::vector<metrics::Track> tracks;
  for (const RodResult& rod : rods) {
    every_velocity.insert(every_velocity.end(), rod.velocities.begin(), rod.velocities.end());
    const metrics::SampleStatistics speed = metrics::sample_statistics(rod.velocities);
    per_rod_speed.push_back(speed.mean);
    per_rod_deviation.push_back(speed.deviation);
    per_rod_diffusion.push_back(rotational_diffusion_of(rod.track, fit_lags));
    const double turn_rate = metrics::turn_rate(rod.track);
    const double diffusion_about_turn =
        rotational_diffusion_of(metrics::without_steady_turn(rod.track, turn_rate), fit_lags);
    per_rod_turn_rate.push_back(turn_rate);
    per_rod_diffusion_about_turn.push_back(diffusion_about_turn);
    per_rod_circles.push_back(metrics::circles(turn_rate, request.duration, diffusion_about_turn));
    series.push_back(rod.back_to_back);
    boundary_headings.push_back(metrics::window_boundary_headings(rod.track, window_samples));
    tracks.push_back(rod.track);
  }
  const RollSummary roll = straight ? RollSummary{} : summarize_rolls(rods, fit_lags);
  const double threshold = request.run_threshold >= 0.0
                               ? request.run_threshold
                               : 0.5 * metrics::quantile(every_velocity, 0.9);
  const metrics::RunsAndTumbles runs =
      metrics::runs_and_tumbles(series, window, threshold, boundary_headings);
  const metrics::SampleStatistics speed = metrics::sample_statistics(per_rod_speed);
  const metrics::SampleStatistics diffusion = metrics::sample_statistics(per_rod_diffusion);
  const metrics::SampleStatistics spread = metrics::sample_statistics(every_velocity);
  const double backward = metrics::backward_fraction(every_velocity);
  double mean_abs_turn_rate = 0.0;
  for (const double rate : per_rod_turn_rate) mean_abs_turn_rate += std::abs(rate);
  mean_abs_turn_rate /= static_cast<double>(per_rod_turn_rate.size());
  const metrics::SampleStatistics diffusion_about_turn =
      metrics::sample_statistics(per_rod_diffusion_about_turn);
  const long circling_rods = std::count(per_rod_circles.begin(), per_rod_circles.end(), true);
  std::int64_t kicks = 0;
  for (const RodResult& rod : rods) kicks += rod.kicks;
  const metrics::Histogram histogram = velocity_histogram(every_velocity);
  const std::vector<double> density = histogram.density();
  std::vector<double> bin_centre;
  for (std::size_t b = 0; b < density.size(); ++b) {
    bin_centre.push_back(histogram.bin_center(static_cast<int>(b)));
  }
  const metrics::TwoPeaks peaks = metrics::two_peaks(bin_centre, density);
  const double measured = request.duration * request.rods;
  const double thin_end_down = metrics::thin_end_down_fraction(tracks);
  numbers = {model.dt,
             speed.mean,
             speed.standard_error,
             diffusion.mean,
             diffusion.standard_error,
             runs.running_fraction,
             backward};

  char line[512];
  out << "species " << species_name << ": " << request.rods << " rods x " << request.duration
      << " s, V_x over " << window << " s\n";
  std::snprintf(line, sizeof line,
                "  v0        %.3f +- %.3f mm/s (mean over rods +- standard error)\n"
                "  V_x       sd %.3f mm/s over windows, sd %.3f mm/s between rods' means\n",
                speed.mean, speed.standard_error, spread.deviation, speed.deviation);
  out << line;
  std::snprintf(line, sizeof line,
                "  D_r       %.4f +- %.4f rad^2/s (lags %g..%g s); persistence time 1/D_r %.3g s, "
                "length v0/D_r %.3g mm\n",
                diffusion.mean, diffusion.standard_error, window, window * kFitMaxWindows,
                1.0 / diffusion.mean, speed.mean / diffusion.mean);
  out << line;
  std::snprintf(line, sizeof line,
                "  turning   %ld of %d rods circle (net turn above one turn and 5 sqrt(2 D T)); "
                "mean |turn rate| %.3g rad/s; D_r about the turn %.4f +- %.4f rad^2/s\n",
                circling_rods, request.rods, mean_abs_turn_rate, diffusion_about_turn.mean,
                diffusion_about_turn.standard_error);
  out << line;
  if (circling_rods > 0) {
    out << "            (D_r above counts the circling rods' steady turn as diffusion; D_r about "
           "the turn does not)\n";
  }
  std::snprintf(line, sizeof line,
                "  running   %.3f of windows (V_x > %.3g mm/s); mean run %.3g s, mean tumble "
                "%.3g s (%ld runs, %ld tumbles)\n"
                "  backward  %.3f of windows (V_x < -%g mm/s)\n",
                runs.running_fraction, threshold, runs.mean_run, runs.mean_tumble, runs.runs,
                runs.tumbles, backward, metrics::kBackwardSpeed);
  out << line;
  std::snprintf(line, sizeof line,
                "  turns     %.1f deg RMS over a run, %.1f deg RMS over a tumble (a new direction "
                "at random: 103.9)\n",
                runs.run_turn_rms * 180.0 / std::numbers::pi,
                runs.tumble_turn_rms * 180.0 / std::numbers::pi);
  out << line;
  std::snprintf(line, sizeof line, "  tilt      thin end down in %.3f of frames\n", thin_end_down);
  out << line;
  if (!straight) {
    std::snprintf(line, sizeof line,
                  "  roll      about its axis: mean |rate| %.3g rad/s; D about the rate %.4f +- "
                  "%.4f rad^2/s; off-axis part above the axis in %.3f of frames\n",
                  roll.mean_abs_rate, roll.diffusion.mean, roll.diffusion.standard_error,
                  roll.up_fraction);
    out << line;
  }
  std::snprintf(line, sizeof line,
                "  P(V_x)    %s: main peak %.3g mm/s; second peak %.3g mm/s, %.2f as high, "
                "valley %.2f of it\n"
                "  kicks     %.0f per s; cost %.3g CPU-s for %.0f rod-seconds\n",
                peaks.bimodal() ? "bimodal" : "unimodal", peaks.main, peaks.second,
                peaks.second_height, peaks.valley, static_cast<double>(kicks) / measured, cpu,
                measured);
  out << line;

  if (request.output.empty()) return kExitOk;
  try {
    std::filesystem::create_directories(request.output);
    write_file_atomically(request.output / "scenario.resolved.yaml",
                          scenarios::resolved_yaml(scenario));
    CsvTable summary;
    summary.header = {"species",
                      "rods",
                      "duration_s",
                      "window_s",
                      "v0_mm_s",
                      "v0_sem_mm_s",
                      "vx_sd_mm_s",
                      "v0_rod_sd_mm_s",
                      "Dr_rad2_s",
                      "Dr_sem_rad2_s",
                      "persistence_time_s",
                      "persistence_length_mm",
                      "run_threshold_mm_s",
                      "running_fraction",
                      "mean_run_s",
                      "mean_tumble_s",
                      "runs",
                      "tumbles",
                      "bimodal",
                      "main_peak_mm_s",
                      "second_peak_mm_s",
                      "second_peak_height",
                      "valley",
                      "thin_end_down_fraction",
                      "kicks_per_s",
                      "cpu_s",
                      "turn_rate_abs_rad_s",
                      "Dr_about_turn_rad2_s",
                      "circling_rods",
                      "run_turn_rms_rad",
                      "tumble_turn_rms_rad",
                      "backward_fraction",
                      "roll_rate_abs_rad_s",
                      "Droll_rad2_s",
                      "Droll_sem_rad2_s",
                      "offset_up_fraction"};
    summary.rows.push_back({species_name,
                            std::to_string(request.rods),
                            number(request.duration),
                            number(window),
                            number(speed.mean),
                            number(speed.standard_error),
                            number(spread.deviation),
                            number(speed.deviation),
                            number(diffusion.mean),
                            number(diffusion.standard_error),
                            number(1.0 / diffusion.mean),
                            number(speed.mean / diffusion.mean),
                            number(threshold),
                            number(runs.running_fraction),
                            number(runs.mean_run),
                            number(runs.mean_tumble),
                            std::to_string(runs.runs),
                            std::to_string(runs.tumbles),
                            peaks.bimodal() ? "1" : "0",
                            number(peaks.main),
                            number(peaks.second),
                            number(peaks.second_height),
                            number(peaks.valley),
                            number(thin_end_down),
                            number(static_cast<double>(kicks) / measured),
                            number(cpu),
                            number(mean_abs_turn_rate),
                            number(diffusion_about_turn.mean),
                            std::to_string(circling_rods),
                            number(runs.run_turn_rms),
                            number(runs.tumble_turn_rms),
                            number(backward),
                            number(roll.mean_abs_rate),
                            number(roll.diffusion.mean),
                            number(roll.diffusion.standard_error),
                            number(roll.up_fraction)});
    write_file_atomically(request.output / "summary.csv", csv_text(summary));

    CsvTable per_rod;
    per_rod.header = {"rod",
                      "seed",
                      "v0_mm_s",
                      "vx_sd_mm_s",
                      "Dr_rad2_s",
                      "turn_rate_rad_s",
                      "Dr_about_turn_rad2_s",
                      "circles",
                      "roll_rate_rad_s",
                      "Droll_rad2_s",
                      "roll_mean_rad"};
    for (std::size_t r = 0; r < rods.size(); ++r) {
      per_rod.rows.push_back(
          {std::to_string(r), std::to_string(model.seed + r), number(per_rod_speed[r]),
           number(per_rod_deviation[r]), number(per_rod_diffusion[r]), number(per_rod_turn_rate[r]),
           number(per_rod_diffusion_about_turn[r]), per_rod_circles[r] ? "1" : "0",
           number(roll.rate(r)), number(roll.diffusion_of(r)), number(roll.mean_of(r))});
    }
    write_file_atomically(request.output / "per_rod.csv", csv_text(per_rod));

    CsvTable distribution;
    distribution.header = {"vx_mm_s", "density_s_mm"};
    for (std::size_t b = 0; b < density.size(); ++b) {
      distribution.rows.push_back({number(bin_centre[b]), number(density[b])});
    }
    write_file_atomically(request.output / "axial_velocity.csv", csv_text(distribution));

    if (!straight) {
      write_file_atomically(request.output / "roll_windows.csv",
                            csv_text(roll_windows_table(rods, window_samples)));
    }

    const metrics::LagStatistics lags = metrics::lag_statistics(tracks, all_lags);
    CsvTable lag_table;
    lag_table.header = {"lag_s", "position_msd_mm2", "heading_msd_rad2", "orientation_correlation"};
    for (std::size_t l = 0; l < lags.lag_time.size(); ++l) {
      lag_table.rows.push_back({number(lags.lag_time[l]), number(lags.position_msd[l]),
                                number(lags.heading_msd[l]),
                                number(lags.orientation_correlation[l])});
    }
    write_file_atomically(request.output / "lags.csv", csv_text(lag_table));
  } catch (const std::exception& error) {
    err << "rodsort: error: " << error.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

/// Whether two studies at successive steps agree: v0 within 5% or three standard errors (at least
/// 0.1 mm/s), the shares of running and backward windows within 0.05, D_r within 25% or three
/// standard errors (at least 0.005 rad^2/s). Returns what moved, empty when nothing did.
std::string what_moved(const StudyNumbers& coarse, const StudyNumbers& fine) {
  char text[160];
  std::string moved;
  const auto add = [&](const char* format, double a, double b) {
    std::snprintf(text, sizeof text, format, a, b);
    moved += (moved.empty() ? "" : "; ") + std::string(text);
  };
  const double v0_tolerance =
      std::max({0.05 * std::abs(fine.v0), 3.0 * std::hypot(coarse.v0_sem, fine.v0_sem), 0.1});
  if (std::abs(fine.v0 - coarse.v0) > v0_tolerance) add("v0 %.3g -> %.3g mm/s", coarse.v0, fine.v0);
  const double diffusion_tolerance =
      std::max({0.25 * std::abs(fine.diffusion),
                3.0 * std::hypot(coarse.diffusion_sem, fine.diffusion_sem), 0.005});
  if (std::abs(fine.diffusion - coarse.diffusion) > diffusion_tolerance) {
    add("D_r %.3g -> %.3g rad^2/s", coarse.diffusion, fine.diffusion);
  }
  if (std::abs(fine.running - coarse.running) > 0.05) {
    add("running %.3f -> %.3f of windows", coarse.running, fine.running);
  }
  if (std::abs(fine.backward - coarse.backward) > 0.05) {
    add("backward %.3f -> %.3f of windows", coarse.backward, fine.backward);
  }
  return moved;
}

}  // namespace

int run_single_particle(const SingleParticleRequest& request, std::ostream& out,
                        std::ostream& err) {
  StudyNumbers numbers;
  if (request.dt_halvings <= 0) return run_study(request, out, err, numbers);
  const scenarios::LoadResult loaded =
      scenarios::load_scenario_with_options(request.scenario, request.set_options);
  if (!loaded.ok()) {
    err << scenarios::format_diagnostics(loaded.diagnostics);
    return kExitUsage;
  }
  const double dt = loaded.scenario->model.dt;
  std::vector<StudyNumbers> studies;
  for (int halving = 0; halving <= request.dt_halvings; ++halving) {
    SingleParticleRequest step = request;
    step.dt_halvings = 0;
    const std::string step_dt = number(dt / std::ldexp(1.0, halving));
    step.set_options.push_back("run.dt=" + step_dt);
    if (!request.output.empty()) step.output = request.output / ("dt-" + step_dt);
    out << "at run.dt = " << step_dt << " s:\n";
    const int status = run_study(step, out, err, numbers);
    if (status != kExitOk) return status;
    studies.push_back(numbers);
  }
  char line[256];
  out << "\nrun.dt [s]   v0 [mm/s]          D_r [rad^2/s]        running  backward\n";
  CsvTable table;
  table.header = {"dt_s",          "v0_mm_s",          "v0_sem_mm_s",      "Dr_rad2_s",
                  "Dr_sem_rad2_s", "running_fraction", "backward_fraction"};
  for (const StudyNumbers& study : studies) {
    std::snprintf(line, sizeof line, "%-11s  %8.3f +- %-6.3f  %8.4f +- %-7.4f  %7.3f  %8.3f\n",
                  number(study.dt).c_str(), study.v0, study.v0_sem, study.diffusion,
                  study.diffusion_sem, study.running, study.backward);
    out << line;
    table.rows.push_back({number(study.dt), number(study.v0), number(study.v0_sem),
                          number(study.diffusion), number(study.diffusion_sem),
                          number(study.running), number(study.backward)});
  }
  const StudyNumbers& coarse = studies[studies.size() - 2];
  const StudyNumbers& fine = studies.back();
  const std::string moved = what_moved(coarse, fine);
  out << (moved.empty() ? "settled" : "not settled") << " between run.dt = " << number(coarse.dt)
      << " and " << number(fine.dt) << " s"
      << (moved.empty() ? " (v0 within 5%, D_r within 25%, running and backward within 0.05)"
                        : ": " + moved)
      << "\n";
  if (request.output.empty()) return kExitOk;
  try {
    write_file_atomically(request.output / "dt_convergence.csv", csv_text(table));
  } catch (const std::exception& error) {
    err << "rodsort: error: " << error.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace rodsort::runner
