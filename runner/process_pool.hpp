#pragma once
// Runs independent commands side by side, at most N at a time: how a sweep uses every core, since
// one simulation uses one. Each child gets its own process group, so a Ctrl-C on the terminal
// reaches only this driver, which passes exactly one SIGINT/SIGTERM on to every child (a second
// one would kill a child before it has written its checkpoint). Children also receive SIGTERM if
// the driver dies, so none is left running unattended.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rodsort::runner {

struct Job {
  std::vector<std::string> argv;  ///< argv[0] is the program's path
  std::filesystem::path log;      ///< receives the child's stdout and stderr (appended)
};

struct JobResult {
  bool started = false;
  int exit_code = -1;  ///< when it exited; -1 otherwise
  int signal = 0;      ///< the signal that killed it; 0 otherwise
};

struct PoolCallbacks {
  std::function<void(std::size_t job)> on_start;
  std::function<void(std::size_t job, const JobResult& result)> on_finish;
};

/// Runs `jobs` in order, at most `parallel` at once, and waits for all of them. Once a SIGINT or
/// SIGTERM arrives (see InterruptGuard, which must be installed), starts no more and forwards the
/// signal once to the running children. Throws std::runtime_error when it cannot fork.
std::vector<JobResult> run_jobs(const std::vector<Job>& jobs, int parallel,
                                const PoolCallbacks& callbacks = {});

}  // namespace rodsort::runner
