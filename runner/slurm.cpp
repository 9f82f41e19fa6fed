#include "runner/slurm.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace rodsort::runner {

std::string array_ranges(const std::vector<std::size_t>& indices) {
  std::string text;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    if (!text.empty()) text += ',';
    text += std::to_string(indices[i]);
    if (j > i) text += '-' + std::to_string(indices[j]);
    i = j + 1;
  }
  return text;
}

std::string shell_quote(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=./,:@%") == std::string::npos;
  if (safe) return word;
  std::string quoted = "'";
  for (const char c : word) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string sbatch_script(const SlurmArray& array, const SlurmOptions& options) {
  std::ostringstream script;
  const std::filesystem::path logs = array.directory / "logs";
  script << "#!/bin/bash\n"
         << "# Written by `rodsort sweep --slurm` for the sweep " << array.sweep_name
         << ": one task per point still to run.\n"
         << "# Submit it again with the same `rodsort sweep --slurm` command, which skips the "
            "points that are done.\n"
         << "#SBATCH --job-name=" << shell_quote("rodsort-" + array.sweep_name) << '\n'
         << "#SBATCH --array=" << array_ranges(array.points);
  if (options.throttle > 0) script << '%' << options.throttle;
  script << '\n'
         << "#SBATCH --ntasks=1\n"
         << "#SBATCH --cpus-per-task=1\n"
         << "#SBATCH --output=" << (logs / "slurm-%A_%a.out").string() << '\n'
         << "#SBATCH --signal=B:TERM@" << options.signal_seconds << '\n';
  if (!options.partition.empty()) script << "#SBATCH --partition=" << options.partition << '\n';
  if (!options.time_limit.empty()) script << "#SBATCH --time=" << options.time_limit << '\n';
  if (!options.memory.empty()) script << "#SBATCH --mem=" << options.memory << '\n';
  if (!options.account.empty()) script << "#SBATCH --account=" << options.account << '\n';
  for (const std::string& line : options.extra_lines) script << "#SBATCH " << line << '\n';
  // exec: the run is the batch shell itself, so Slurm's SIGTERM (from --signal, scancel or the
  // time limit) reaches it exactly once and it writes its checkpoint before it stops.
  script << "exec";
  for (const std::string& word : array.program) script << ' ' << shell_quote(word);
  script << " sweep " << shell_quote(array.sweep_file.string()) << " -o "
         << shell_quote(array.directory.string()) << " --point \"$SLURM_ARRAY_TASK_ID\"";
  for (const std::string& option : array.set_options) script << " --set " << shell_quote(option);
  if (array.any_build) script << " --any-build";
  script << '\n';
  return script.str();
}

std::string submit_sbatch(const std::filesystem::path& script) {
  const std::string command = "sbatch --parsable " + shell_quote(script.string()) + " 2>&1";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run sbatch");
  std::string output;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
    output += buffer.data();
  }
  const int status = ::pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
      throw std::runtime_error(
          "sbatch not found: is this a Slurm login node? (`--slurm --no-submit` "
          "writes the script only)");
    }
    throw std::runtime_error("sbatch refused " + script.string() + ": " + output);
  }
  // --parsable prints "jobid" or "jobid;cluster".
  return output.substr(0, output.find(';'));
}

}  // namespace rodsort::runner
