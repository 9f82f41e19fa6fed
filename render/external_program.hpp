#pragma once
// Pictures lean on two programs rodsort does not link: ffmpeg, which encodes movies, and python3
// with matplotlib, which draws the plots. They are found on PATH and run with an argument vector
// (no shell, so no quoting of paths), their output captured for the message when they fail.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rodsort::render {

/// The executable `name` found on PATH; a name with a '/' is taken as a path. Nothing when there
/// is no such executable file.
std::optional<std::filesystem::path> find_program(const std::string& name);

struct ProgramOutput {
  int exit_status = 0;  ///< the program's exit status; 128 + N when killed by signal N
  std::string output;   ///< its standard output and standard error, interleaved
};

/// Runs arguments[0] (a path) with the rest as its arguments, and waits for it. Throws
/// std::runtime_error naming the program when it cannot be started.
ProgramOutput run_program(const std::vector<std::string>& arguments);

/// The last `lines` lines of a program's output, for a message.
std::string last_lines(const std::string& output, int lines);

}  // namespace rodsort::render
