#pragma once
// Overrides change a scenario's tree before it is checked: `--set key.path=value` on the command
// line, and the values of a sweep point. They are applied to the SourceNode tree, not to the
// ScenarioSpec, so that an overridden value goes through exactly the same checks as a written one,
// and its messages name where it came from (`--set trap.angle=190: trap.angle: ...`).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/diagnostic.hpp"
#include "scenarios/source_node.hpp"

namespace rodsort::scenarios {

struct Override {
  std::string path;      ///< "trap.angle", "species[0].noise.kick_eps"
  SourceNode value;      ///< any YAML; null removes the key (its default applies again)
  SourceLocation where;  ///< of the override itself, for errors about its path

  /// The value as text, e.g. "120" or "[100, 100]".
  std::string value_text() const { return value.describe(); }
};

/// Parses one `--set` argument, "key.path=value"; the value is YAML ("130", "[100, 100]", "none",
/// "null"). Reports a malformed argument and returns std::nullopt.
std::optional<Override> parse_set_option(std::string_view text, Diagnostics& diagnostics);

/// Applies overrides in order. A missing section along the path is created; an index into a list
/// may be one past its end (a new item). Problems are reported at the override's location.
void apply_overrides(SourceNode& root, const std::vector<Override>& overrides,
                     Diagnostics& diagnostics);

}  // namespace rodsort::scenarios
