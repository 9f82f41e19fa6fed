#pragma once
// Runs the built rodsort program from a test, with its output captured.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "runner/atomic_file.hpp"

namespace rodsort::runner::testing {

inline const std::string kRodsortProgram = RODSORT_BINARY_DIR "/rodsort";

/// Starts the program argv[0] with `argv`, stdout and stderr into the files given; returns its pid.
inline pid_t start_program(std::vector<std::string> argv_strings, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  std::vector<char*> argv;
  for (std::string& argument : argv_strings) argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) throw std::runtime_error("cannot start " + argv_strings[0]);
  return pid;
}

/// Starts rodsort with `arguments`, stdout and stderr into the files given; returns its pid.
inline pid_t start_rodsort(const std::vector<std::string>& arguments,
                           const std::filesystem::path& out, const std::filesystem::path& err) {
  std::vector<std::string> argv = {kRodsortProgram};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return start_program(std::move(argv), out, err);
}

/// The exit status of a process started by start_program or start_rodsort; 128 + signal when
/// killed.
inline int wait_rodsort(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

struct ProgramResult {
  int status;
  std::string out;
  std::string err;
};

/// Runs the program argv[0] to its end; `scratch` holds the captured output files.
inline ProgramResult run_program(const std::vector<std::string>& argv,
                                 const std::filesystem::path& scratch) {
  const auto out = scratch / "stdout.txt";
  const auto err = scratch / "stderr.txt";
  const int status = wait_rodsort(start_program(argv, out, err));
  return {status, read_file(out), read_file(err)};
}

/// Runs rodsort to its end; `scratch` holds the captured output files.
inline ProgramResult run_rodsort(const std::vector<std::string>& arguments,
                                 const std::filesystem::path& scratch) {
  std::vector<std::string> argv = {kRodsortProgram};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv, scratch);
}

}  // namespace rodsort::runner::testing
