#pragma once
// `rodsort plot` draws with matplotlib, in tools/rodsort_plot.py, run by a python 3 that has
// matplotlib and numpy (Debian's python3-matplotlib, python3-numpy; scripts/install-deps installs
// them). A python3 first on PATH may lack them (a pyenv or a virtual environment), so each
// candidate is asked to import them before it is used.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/external_program.hpp"

namespace rodsort::render {

/// The plot script's name, beside the rodsort executable (the build copies it there) and in tools/.
inline constexpr const char* kPlotScriptName = "rodsort_plot.py";

/// Where the plot script is, trying in order: $RODSORT_PLOT_SCRIPT; beside the running executable;
/// ../share/rodsort/ from it; tools/ of the source tree this program was built from.
std::optional<std::filesystem::path> find_plot_script();

struct PythonLookup {
  std::optional<std::filesystem::path> python;  ///< a python that imports matplotlib and numpy
  std::string error;                            ///< what was tried and how to fix it, otherwise
};

/// Tries, in order: $RODSORT_PYTHON; python3 on PATH; /usr/bin/python3.
PythonLookup find_plot_python();

/// Runs the plot script with `arguments` (see tools/rodsort_plot.py). Throws std::runtime_error
/// when the script or a suitable python cannot be found.
ProgramOutput run_plot_script(const std::vector<std::string>& arguments);

}  // namespace rodsort::render
