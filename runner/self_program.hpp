#pragma once
// This program as a file and as a command: what a build's fingerprint hashes and what a sweep
// starts for each of its points. Usually both are /proc/self/exe. A build carried to a machine
// without its libraries runs through the dynamic loader that came with it,
//   ld-linux-x86-64.so.2 --library-path LIB rodsort sweep ...
// and then /proc/self/exe is the loader: the program is the file the loader was given, and
// starting rodsort again means starting the loader again with the same options.

#include <filesystem>
#include <string>
#include <vector>

namespace rodsort::runner {

/// The file of the running rodsort program, absolute (not the loader that may have started it).
std::filesystem::path program_file();

/// The command that starts this program again, arguments to follow: {program_file()}, or the
/// loader, the loader's options and program_file() when it was started through a loader.
std::vector<std::string> program_command();

/// What program_command() is, given what the process knows of itself: `executable` is
/// /proc/self/exe, `exec_name` the file the loader mapped as the program (AT_EXECFN; empty when
/// unknown), `started_by_loader` true when no interpreter ran before the program (AT_BASE = 0) and
/// `command_line` is /proc/self/cmdline as words.
std::vector<std::string> program_command_from(const std::filesystem::path& executable,
                                              const std::string& exec_name, bool started_by_loader,
                                              const std::vector<std::string>& command_line);

}  // namespace rodsort::runner
