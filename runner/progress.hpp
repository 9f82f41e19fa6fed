#pragma once
// What a long run tells the person waiting for it. On a terminal, one line redrawn in place a few
// times a second; in a log file (a cluster job, a sweep point), a line every tenth of the run or
// every minute, whichever comes first, so that the log stays short but never goes silent.

#include <cstdio>
#include <string>

namespace rodsort::runner {

/// Where a run stands. Wall and CPU seconds count from the start of this process's part of the
/// run, with the simulated time it started from, so that rates stay right after a resume.
struct ProgressSample {
  double simulated_s = 0.0;      ///< simulated time reached [s]
  double duration_s = 0.0;       ///< simulated time the run ends at [s]
  double session_start_s = 0.0;  ///< simulated time this process started from [s]
  double session_wall_s = 0.0;   ///< wall seconds this process has run
  double session_cpu_s = 0.0;    ///< CPU seconds this process has used
};

/// Durations for humans: 45s, 3m12s, 2h05m.
std::string format_duration(double seconds);

/// Wall seconds of a process before its progress lines give an ETA and a rate.
inline constexpr double kProgressSettleWallS = 5.0;

/// One progress line, e.g. " 42.0%  t = 12.60 / 30.00 s  ETA 3m12s  8.31 CPU-s per sim-s".
/// ETA and the rate are left out until the process has run kProgressSettleWallS and some
/// simulated time has passed, except on the `final` line.
std::string format_progress(const ProgressSample& sample, bool final = false);

class ProgressReporter {
 public:
  /// `terminal`: redraw one line in place (isatty); otherwise print occasional whole lines.
  ProgressReporter(std::FILE* out, bool terminal);

  /// Prints if it is time to; cheap to call often.
  void update(const ProgressSample& sample);
  /// Ends the live line (terminal) or prints the last line (log).
  void finish(const ProgressSample& sample);

  /// Whether a sample, seen after the last printed one, deserves a line. Exposed for tests.
  bool due(const ProgressSample& sample) const;

  static constexpr double kTerminalRedrawWallS = 0.25;
  static constexpr double kLogIntervalWallS = 60.0;
  static constexpr double kLogIntervalFraction = 0.1;

 private:
  void print(const ProgressSample& sample, bool final = false);

  std::FILE* out_;
  bool terminal_;
  bool printed_any_ = false;
  double last_wall_s_ = 0.0;
  double last_fraction_ = 0.0;
  std::size_t last_width_ = 0;
};

}  // namespace rodsort::runner
