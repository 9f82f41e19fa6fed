#include "runner/self_program.hpp"

#include <sys/auxv.h>

#include <fstream>
#include <system_error>

namespace rodsort::runner {
namespace {

std::filesystem::path proc_self_exe() { return std::filesystem::read_symlink("/proc/self/exe"); }

std::string exec_name() {
  const auto name = reinterpret_cast<const char*>(getauxval(AT_EXECFN));
  return name != nullptr ? std::string(name) : std::string();
}

/// No interpreter ran before the program: either a static program or one that a loader, run as
/// the executable itself, mapped.
bool started_by_loader() { return getauxval(AT_BASE) == 0; }

std::vector<std::string> command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> words;
  std::string word;
  while (std::getline(in, word, '\0')) words.push_back(word);
  return words;
}

/// Whether `exec_name` names another file than `executable`: the program was mapped by a loader.
bool names_another_file(const std::filesystem::path& executable, const std::string& exec_name) {
  if (exec_name.empty()) return false;
  std::error_code error;
  const bool same = std::filesystem::equivalent(executable, exec_name, error);
  return !error && !same;
}

}  // namespace

std::vector<std::string> program_command_from(const std::filesystem::path& executable,
                                              const std::string& exec_name, bool started_by_loader,
                                              const std::vector<std::string>& command_line) {
  if (!started_by_loader || !names_another_file(executable, exec_name)) {
    return {executable.string()};
  }
  // The loader's command line: the loader, its options, then the program as AT_EXECFN gives it.
  for (std::size_t i = 1; i < command_line.size(); ++i) {
    if (command_line[i] != exec_name) continue;
    std::vector<std::string> command = {executable.string()};
    command.insert(command.end(), command_line.begin() + 1,
                   command_line.begin() + static_cast<std::ptrdiff_t>(i));
    command.push_back(std::filesystem::absolute(exec_name).string());
    return command;
  }
  return {executable.string()};
}

std::filesystem::path program_file() { return program_command().back(); }

std::vector<std::string> program_command() {
  static const std::vector<std::string> command =
      program_command_from(proc_self_exe(), exec_name(), started_by_loader(), command_line());
  return command;
}

}  // namespace rodsort::runner
