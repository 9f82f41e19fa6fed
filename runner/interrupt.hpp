#pragma once
// SIGINT and SIGTERM stop a run cleanly: the handler only records the signal, and the run loop (or
// the sweep driver) looks at it between steps, writes a checkpoint and exits with status 130.
// A second signal at least a second after the first gets the default action, so a stuck process
// can still be stopped with a second Ctrl-C. Signals that follow the first more closely are the
// same request, sent again: `timeout` signals its child and then the child's process group, and
// Slurm, a shell or a process manager may do likewise; they must not kill the run before its
// checkpoint is written.

namespace rodsort::runner {

class InterruptGuard {
 public:
  /// Installs the handlers; the previous ones come back when the guard is destroyed, unless a
  /// signal came (the handlers then stay, so that a repeat during the exit changes nothing).
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received since the guard was installed, 0 when none.
  static int received();
};

}  // namespace rodsort::runner
