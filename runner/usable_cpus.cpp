#include "runner/usable_cpus.hpp"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <thread>

namespace rodsort::runner {
namespace {

/// A positive whole number, or nullopt.
std::optional<int> positive(std::optional<std::string_view> text) {
  if (!text) return std::nullopt;
  int value = 0;
  const auto result = std::from_chars(text->data(), text->data() + text->size(), value);
  if (result.ec != std::errc() || result.ptr != text->data() + text->size() || value <= 0) {
    return std::nullopt;
  }
  return value;
}

std::optional<std::string_view> environment(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr) return std::nullopt;
  return std::string_view(value);
}

}  // namespace

int usable_cpus(int affinity_count, std::optional<std::string_view> slurm_cpus_per_task,
                std::optional<std::string_view> slurm_cpus_on_node) {
  int cpus = std::max(1, affinity_count);
  if (const auto per_task = positive(slurm_cpus_per_task)) {
    cpus = std::min(cpus, *per_task);
  } else if (const auto on_node = positive(slurm_cpus_on_node)) {
    cpus = std::min(cpus, *on_node);
  }
  return cpus;
}

int usable_cpus() {
  int affinity_count = 0;
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) == 0) {
    affinity_count = CPU_COUNT(&mask);
  } else {
    affinity_count = static_cast<int>(std::thread::hardware_concurrency());
  }
  return usable_cpus(affinity_count, environment("SLURM_CPUS_PER_TASK"),
                     environment("SLURM_CPUS_ON_NODE"));
}

}  // namespace rodsort::runner
