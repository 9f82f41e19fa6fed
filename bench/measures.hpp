#pragma once
// Small tools every part of the benchmark uses: the process's CPU clock and one number printed.

#include <string>

namespace rodsort::bench {

/// CPU seconds this process has used (CLOCK_PROCESS_CPUTIME_ID) [s].
double process_cpu_seconds();

/// `value` printed with the printf `pattern`, which takes one double.
std::string format(const char* pattern, double value);

}  // namespace rodsort::bench
