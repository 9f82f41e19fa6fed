#include "runner/process_pool.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <map>
#include <stdexcept>

#include "runner/interrupt.hpp"

namespace rodsort::runner {
namespace {

/// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void exec_child(const Job& job, const std::vector<char*>& argv, pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(128 + SIGTERM);
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) dup2(null_in, STDIN_FILENO);
  const int log = open(job.log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (log >= 0) {
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
  }
  execv(argv[0], argv.data());
  const char message[] = "rodsort: cannot execute the command\n";
  [[maybe_unused]] const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(127);
}

pid_t start(const Job& job) {
  std::vector<char*> argv;
  for (const std::string& argument : job.argv) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
  if (pid == 0) exec_child(job, argv, parent);
  return pid;
}

JobResult result_of(int status) {
  JobResult result;
  result.started = true;
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

}  // namespace

std::vector<JobResult> run_jobs(const std::vector<Job>& jobs, int parallel,
                                const PoolCallbacks& callbacks) {
  std::vector<JobResult> results(jobs.size());
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0;
  int forwarded = 0;
  while (next < jobs.size() || !running.empty()) {
    const int signal_received = InterruptGuard::received();
    if (signal_received != 0 && forwarded == 0) {
      forwarded = signal_received;
      for (const auto& [pid, job] : running) kill(pid, signal_received);
    }
    while (forwarded == 0 && next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      running[start(jobs[next])] = next;
      if (callbacks.on_start) callbacks.on_start(next);
      ++next;
    }
    if (forwarded != 0) next = jobs.size();
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid > 0) {
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const std::size_t job = it->second;
      running.erase(it);
      results[job] = result_of(status);
      if (callbacks.on_finish) callbacks.on_finish(job, results[job]);
      continue;
    }
    if (pid < 0 && errno != EINTR) throw std::runtime_error("waitpid failed");
    // Polling keeps a signal that lands between the check above and a blocking wait from going
    // unnoticed; a tenth of a second is nothing next to a simulation.
    const timespec pause{0, 100'000'000};
    nanosleep(&pause, nullptr);
  }
  return results;
}

}  // namespace rodsort::runner
