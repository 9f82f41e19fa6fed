#pragma once
// The exit status of every rodsort command, documented in docs/cli.md. Scripts and the sweep
// driver rely on these values, so they never change meaning.

namespace rodsort::runner {

enum ExitCode : int {
  kExitOk = 0,       ///< the command did what it was asked
  kExitFailure = 1,  ///< a runtime failure: I/O error, a broken run directory, a point that failed
  kExitUsage = 2,    ///< bad arguments or a refused scenario; nothing was written
  kExitInterrupted = 130  ///< stopped by SIGINT/SIGTERM after writing a checkpoint; resume it
};

}  // namespace rodsort::runner
