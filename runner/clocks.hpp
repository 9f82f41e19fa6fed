#pragma once
// The two clocks a run's cost is measured with: wall time (what the user waits) and the CPU time
// of this process (what the run costs, the unit of docs/performance.md).

namespace rodsort::runner {

/// Seconds on a monotonic clock, from an arbitrary origin.
double wall_seconds();
/// CPU seconds used by this process so far (all threads).
double process_cpu_seconds();

}  // namespace rodsort::runner
