#include "runner/progress.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

using namespace rodsort::runner;

namespace {

ProgressSample sample_at(double simulated_s, double wall_s) {
  ProgressSample sample;
  sample.simulated_s = simulated_s;
  sample.duration_s = 100.0;
  sample.session_wall_s = wall_s;
  sample.session_cpu_s = wall_s;
  return sample;
}

/// Everything a reporter printed to a memory stream.
std::string captured(std::FILE* stream) {
  std::fflush(stream);
  std::rewind(stream);
  std::string text;
  for (int c = std::fgetc(stream); c != EOF; c = std::fgetc(stream)) text += static_cast<char>(c);
  return text;
}

}  // namespace

TEST_CASE("durations read as seconds, minutes or hours", "[runner][progress]") {
  CHECK(format_duration(0.4) == "0s");
  CHECK(format_duration(45) == "45s");
  CHECK(format_duration(192) == "3m12s");
  CHECK(format_duration(7500) == "2h05m");
  CHECK(format_duration(-3) == "0s");
}

TEST_CASE("a progress line shows percentage, time, ETA and cost", "[runner][progress]") {
  ProgressSample sample;
  sample.simulated_s = 12.6;
  sample.duration_s = 30.0;
  sample.session_start_s = 2.6;
  sample.session_wall_s = 50.0;  // 10 simulated s in 50 wall s: 17.4 s left take 87 s
  sample.session_cpu_s = 83.1;
  CHECK(format_progress(sample) == " 42.0%  t = 12.60 / 30.00 s  ETA 1m27s  8.31 CPU-s per sim-s");
}

TEST_CASE("a progress line leaves out rates before any time has passed", "[runner][progress]") {
  ProgressSample sample;
  sample.simulated_s = 5.0;
  sample.session_start_s = 5.0;
  sample.duration_s = 10.0;
  CHECK(format_progress(sample) == " 50.0%  t = 5.00 / 10.00 s");
}

TEST_CASE("a progress line gives no ETA from the first, cold seconds of a process",
          "[runner][progress]") {
  ProgressSample sample;
  sample.simulated_s = 0.2;
  sample.duration_s = 300.0;
  sample.session_wall_s = 1.0;  // placement and the first checkpoint: 20 CPU-s per sim-s
  sample.session_cpu_s = 4.0;
  CHECK(format_progress(sample) == "  0.1%  t = 0.20 / 300.00 s");
  // The last line of a short run still says what it cost.
  CHECK(format_progress(sample, true) ==
        "  0.1%  t = 0.20 / 300.00 s  ETA 24m59s  20 CPU-s per sim-s");
  sample.session_wall_s = kProgressSettleWallS;
  CHECK_THAT(format_progress(sample), Catch::Contains("ETA"));
}

TEST_CASE("off a terminal, progress is printed every tenth or every minute", "[runner][progress]") {
  std::FILE* stream = std::tmpfile();
  REQUIRE(stream != nullptr);
  ProgressReporter reporter(stream, false);
  CHECK(reporter.due(sample_at(0.0, 0.0)));
  reporter.update(sample_at(0.0, 0.0));
  CHECK_FALSE(reporter.due(sample_at(5.0, 10.0)));
  CHECK(reporter.due(sample_at(10.0, 10.0)));  // crossed 10%
  CHECK(reporter.due(sample_at(5.0, 61.0)));   // a minute of silence
  for (int i = 1; i <= 100; ++i) reporter.update(sample_at(i, 0.5 * i));
  reporter.finish(sample_at(100.0, 50.0));
  const std::string text = captured(stream);
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n';
  CHECK(lines == 11);  // 0%, 10%, ..., 100%, and no repeat of the last one
  CHECK(text.find('\r') == std::string::npos);
  std::fclose(stream);
}

TEST_CASE("on a terminal, progress redraws one line in place", "[runner][progress]") {
  std::FILE* stream = std::tmpfile();
  REQUIRE(stream != nullptr);
  ProgressReporter reporter(stream, true);
  reporter.update(sample_at(0.0, 0.0));
  CHECK_FALSE(reporter.due(sample_at(0.1, 0.1)));
  CHECK(reporter.due(sample_at(0.3, 0.3)));
  reporter.update(sample_at(50.0, 10.0));
  reporter.finish(sample_at(100.0, 20.0));
  const std::string text = captured(stream);
  CHECK(text.rfind("\r100.0%", std::string::npos) != std::string::npos);
  CHECK(text.back() == '\n');
  CHECK(std::count(text.begin(), text.end(), '\n') == 1);
  std::fclose(stream);
}
