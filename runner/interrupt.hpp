#pragma once
// SIGINT and SIGTERM stop a run cleanly: the handler only records the signal, and the run loop (or
// the sweep driver) looks at it between steps, writes a checkpoint and exits with status 130.
// A second signal of the same kind gets the default action, so a stuck process can still be
// stopped with a second Ctrl-C.

namespace rodsort::runner {

class InterruptGuard {
 public:
  /// Installs the handlers; the previous ones come back when the guard is destroyed.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The signal received since the guard was installed, 0 when none.
  static int received();
};

}  // namespace rodsort::runner
