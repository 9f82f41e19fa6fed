#include "runner/process_pool.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <vector>

#include "runner/atomic_file.hpp"
#include "runner/interrupt.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

TEST_CASE("jobs run with their exit status and their output in their log",
          "[runner][process_pool]") {
  TempDirectory directory;
  std::vector<Job> jobs;
  for (int i = 0; i < 5; ++i) {
    jobs.push_back(
        {{"/bin/sh", "-c", "echo job " + std::to_string(i) + "; exit " + std::to_string(i)},
         directory / ("job" + std::to_string(i) + ".log")});
  }
  jobs.push_back({{"/bin/sh", "-c", "kill -KILL $$"}, directory / "killed.log"});
  jobs.push_back({{"/nonexistent/program"}, directory / "missing.log"});
  std::vector<std::size_t> started;
  std::vector<std::size_t> finished;
  const PoolCallbacks callbacks{
      [&](std::size_t job) { started.push_back(job); },
      [&](std::size_t job, const JobResult&) { finished.push_back(job); }};
  const std::vector<JobResult> results = run_jobs(jobs, 2, callbacks);
  REQUIRE(results.size() == jobs.size());
  for (int i = 0; i < 5; ++i) {
    CHECK(results[i].started);
    CHECK(results[i].exit_code == i);
    CHECK(read_file(directory / ("job" + std::to_string(i) + ".log")) ==
          "job " + std::to_string(i) + "\n");
  }
  CHECK(results[5].signal == SIGKILL);
  CHECK(results[6].exit_code == 127);
  CHECK_THAT(read_file(directory / "missing.log"), Catch::Contains("cannot execute"));
  CHECK(started == std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6});
  CHECK(finished.size() == jobs.size());
}

TEST_CASE("an interrupt starts no more jobs and is passed on once to running ones",
          "[runner][process_pool]") {
  TempDirectory directory;
  const InterruptGuard guard;
  // The first job interrupts the pool; the second reports the signal it receives.
  const std::string trap_and_wait =
      "trap 'echo got TERM; exit 42' TERM; kill -TERM $PPID; while true; do sleep 0.05; done";
  std::vector<Job> jobs = {
      {{"/bin/sh", "-c", trap_and_wait}, directory / "first.log"},
      {{"/bin/sh", "-c", "echo never"}, directory / "never.log"},
  };
  const std::vector<JobResult> results = run_jobs(jobs, 1);
  CHECK(InterruptGuard::received() == SIGTERM);
  CHECK(results[0].exit_code == 42);
  CHECK(read_file(directory / "first.log") == "got TERM\n");
  CHECK_FALSE(results[1].started);
}
