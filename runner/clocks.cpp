#include "runner/clocks.hpp"

#include <time.h>

namespace rodsort::runner {
namespace {

double read(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

double wall_seconds() { return read(CLOCK_MONOTONIC); }
double process_cpu_seconds() { return read(CLOCK_PROCESS_CPUTIME_ID); }

}  // namespace rodsort::runner
