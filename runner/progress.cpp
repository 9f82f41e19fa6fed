#include "runner/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rodsort::runner {
namespace {

double fraction_done(const ProgressSample& sample) {
  if (sample.duration_s <= 0.0) return 1.0;
  return std::clamp(sample.simulated_s / sample.duration_s, 0.0, 1.0);
}

}  // namespace

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  const long hours = total / 3600;
  const long minutes = (total % 3600) / 60;
  const long secs = total % 60;
  char text[64];
  if (hours > 0) {
    std::snprintf(text, sizeof text, "%ldh%02ldm", hours, minutes);
  } else if (minutes > 0) {
    std::snprintf(text, sizeof text, "%ldm%02lds", minutes, secs);
  } else {
    std::snprintf(text, sizeof text, "%lds", secs);
  }
  return text;
}

std::string format_progress(const ProgressSample& sample, bool final) {
  char text[160];
  int length = std::snprintf(text, sizeof text, "%5.1f%%  t = %.2f / %.2f s",
                             100.0 * fraction_done(sample), sample.simulated_s, sample.duration_s);
  const double simulated_this_session = sample.simulated_s - sample.session_start_s;
  // The first seconds of a process (placement, the first checkpoint, a cold cache) say little
  // about its pace: no ETA or rate from them, except on the last line.
  const bool settled = final || sample.session_wall_s >= kProgressSettleWallS;
  if (settled && simulated_this_session > 0.0 && length > 0) {
    const double remaining_s = std::max(0.0, sample.duration_s - sample.simulated_s);
    const double eta_s = remaining_s * sample.session_wall_s / simulated_this_session;
    const double cpu_per_sim = sample.session_cpu_s / simulated_this_session;
    std::snprintf(text + length, sizeof text - static_cast<std::size_t>(length),
                  "  ETA %s  %.3g CPU-s per sim-s", format_duration(eta_s).c_str(), cpu_per_sim);
  }
  return text;
}

ProgressReporter::ProgressReporter(std::FILE* out, bool terminal)
    : out_(out), terminal_(terminal) {}

bool ProgressReporter::due(const ProgressSample& sample) const {
  if (!printed_any_) return true;
  const double since_wall_s = sample.session_wall_s - last_wall_s_;
  if (terminal_) return since_wall_s >= kTerminalRedrawWallS;
  const double fraction = fraction_done(sample);
  const bool crossed_tenth = std::floor(fraction / kLogIntervalFraction + 1e-9) >
                             std::floor(last_fraction_ / kLogIntervalFraction + 1e-9);
  return crossed_tenth || since_wall_s >= kLogIntervalWallS;
}

void ProgressReporter::update(const ProgressSample& sample) {
  if (due(sample)) print(sample);
}

void ProgressReporter::finish(const ProgressSample& sample) {
  const bool already_shown = printed_any_ && !terminal_ &&
                             last_fraction_ == fraction_done(sample) &&
                             last_wall_s_ >= kProgressSettleWallS;
  if (!already_shown) print(sample, true);
  if (terminal_) std::fputc('\n', out_);
  std::fflush(out_);
}

void ProgressReporter::print(const ProgressSample& sample, bool final) {
  const std::string line = format_progress(sample, final);
  if (terminal_) {
    // Pad over the previous line instead of an escape sequence, which some terminals ignore.
    const std::size_t pad = last_width_ > line.size() ? last_width_ - line.size() : 0;
    std::fprintf(out_, "\r%s%*s", line.c_str(), static_cast<int>(pad), "");
    last_width_ = line.size();
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
  printed_any_ = true;
  last_wall_s_ = sample.session_wall_s;
  last_fraction_ = fraction_done(sample);
}

}  // namespace rodsort::runner
