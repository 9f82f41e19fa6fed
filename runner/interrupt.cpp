#include "runner/interrupt.hpp"

#include <csignal>
#include <ctime>

namespace rodsort::runner {
namespace {

// A repeat closer than this to the first signal is taken as the same request (see interrupt.hpp).
constexpr double kSameRequestS = 1.0;

volatile std::sig_atomic_t g_received = 0;
// When the first signal came, on CLOCK_MONOTONIC; written only by the handler.
timespec g_first_at{};
struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

// Only async-signal-safe calls: clock_gettime, signal, raise.
extern "C" void record_signal(int signal_number) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (g_received == 0) {
    g_first_at = now;
    g_received = signal_number;
    return;
  }
  const double since_first_s = static_cast<double>(now.tv_sec - g_first_at.tv_sec) +
                               1e-9 * static_cast<double>(now.tv_nsec - g_first_at.tv_nsec);
  if (since_first_s < kSameRequestS) return;
  signal(signal_number, SIG_DFL);
  raise(signal_number);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_received = 0;
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  // No SA_RESTART: a blocking call returns EINTR so the caller notices promptly.
  action.sa_flags = 0;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  // After a signal the process is on its way out with status 130; a repeat that comes while it
  // exits (after the checkpoint, during the sanitizers' exit checks, say) is still the same
  // request, so the handler stays.
  if (g_received != 0) return;
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int InterruptGuard::received() { return g_received; }

}  // namespace rodsort::runner
