#include "render/plot_script.hpp"

#include <cstdlib>
#include <stdexcept>

namespace rodsort::render {
namespace {

std::optional<std::filesystem::path> environment_path(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::filesystem::path(value);
}

std::filesystem::path executable_directory() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : executable.parent_path();
}

}  // namespace

std::optional<std::filesystem::path> find_plot_script() {
  std::vector<std::filesystem::path> candidates;
  if (const auto given = environment_path("RODSORT_PLOT_SCRIPT")) candidates.push_back(*given);
  const std::filesystem::path here = executable_directory();
  if (!here.empty()) {
    candidates.push_back(here / kPlotScriptName);
    candidates.push_back(here.parent_path() / "share" / "rodsort" / kPlotScriptName);
  }
  candidates.push_back(std::filesystem::path(RODSORT_SOURCE_TOOLS_DIR) / kPlotScriptName);
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

PythonLookup find_plot_python() {
  std::vector<std::string> names;
  if (const auto given = environment_path("RODSORT_PYTHON")) names.push_back(given->string());
  names.push_back("python3");
  names.push_back("/usr/bin/python3");
  PythonLookup lookup;
  std::string tried;
  for (const std::string& name : names) {
    const std::optional<std::filesystem::path> python = find_program(name);
    if (!python) {
      tried += "\n  " + name + ": not found";
      continue;
    }
    const ProgramOutput probe = run_program({python->string(), "-c", "import matplotlib, numpy"});
    if (probe.exit_status == 0) {
      lookup.python = python;
      return lookup;
    }
    tried += "\n  " + python->string() + ": " + last_lines(probe.output, 1);
  }
  lookup.error =
      "no python 3 with matplotlib and numpy; install Debian's python3-matplotlib and "
      "python3-numpy (scripts/install-deps does), or set RODSORT_PYTHON to a python that has "
      "them. Tried:" +
      tried;
  return lookup;
}

ProgramOutput run_plot_script(const std::vector<std::string>& arguments) {
  const std::optional<std::filesystem::path> script = find_plot_script();
  if (!script) {
    throw std::runtime_error(std::string("cannot find ") + kPlotScriptName +
                             " beside the rodsort executable, nor in " + RODSORT_SOURCE_TOOLS_DIR +
                             "; set RODSORT_PLOT_SCRIPT to its path");
  }
  const PythonLookup lookup = find_plot_python();
  if (!lookup.python) throw std::runtime_error(lookup.error);
  std::vector<std::string> command = {lookup.python->string(), script->string()};
  command.insert(command.end(), arguments.begin(), arguments.end());
  return run_program(command);
}

}  // namespace rodsort::render
