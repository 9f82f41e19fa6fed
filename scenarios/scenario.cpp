#include "scenarios/scenario.hpp"

#include <algorithm>

#include "scenarios/compile.hpp"
#include "scenarios/section_reader.hpp"
#include "trap/obstacle.hpp"

namespace rodsort::scenarios {
namespace {

/// The file's stem, with characters unfit for a directory name replaced.
std::string default_name_of(const std::string& source) {
  std::string stem = std::filesystem::path(source).stem().string();
  std::replace_if(
      stem.begin(), stem.end(), [](char c) { return !is_plain_name(std::string_view(&c, 1)); },
      '_');
  return stem.empty() ? "scenario" : stem;
}

LoadResult finish(std::optional<SourceNode> tree, const std::string& default_name,
                  const std::vector<Override>& overrides, Diagnostics& diagnostics) {
  LoadResult result;
  if (tree) {
    apply_overrides(*tree, overrides, diagnostics);
    if (!diagnostics.has_errors()) {
      const ScenarioSpec spec = read_scenario_spec(*tree, default_name, diagnostics);
      if (!diagnostics.has_errors()) result.scenario = compile(spec, diagnostics);
    }
  }
  if (diagnostics.has_errors()) result.scenario.reset();
  result.diagnostics = diagnostics.all();
  return result;
}

}  // namespace

LoadResult load_scenario(const std::filesystem::path& path,
                         const std::vector<Override>& overrides) {
  Diagnostics diagnostics;
  LoadResult result = finish(read_yaml_file(path, diagnostics), default_name_of(path.string()),
                             overrides, diagnostics);
  if (result.scenario) result.scenario->source = path;
  return result;
}

LoadResult load_scenario_with_options(const std::filesystem::path& path,
                                      const std::vector<std::string>& set_options) {
  Diagnostics diagnostics;
  std::vector<Override> overrides;
  for (const std::string& option : set_options) {
    if (auto parsed = parse_set_option(option, diagnostics))
      overrides.push_back(std::move(*parsed));
  }
  if (diagnostics.has_errors()) return {std::nullopt, diagnostics.all()};
  return load_scenario(path, overrides);
}

LoadResult load_scenario_text(std::string_view yaml, const std::string& source,
                              const std::vector<Override>& overrides) {
  Diagnostics diagnostics;
  return finish(parse_yaml(yaml, source, diagnostics), default_name_of(source), overrides,
                diagnostics);
}

LoadResult load_scenario_tree(SourceNode tree, const std::string& default_name,
                              const std::vector<Override>& overrides) {
  Diagnostics diagnostics;
  return finish(std::move(tree), default_name, overrides, diagnostics);
}

}  // namespace rodsort::scenarios
