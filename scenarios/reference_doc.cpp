#include "scenarios/reference_doc.hpp"

#include "scenarios/schema.hpp"

namespace rodsort::scenarios {
namespace {

std::string code(std::string_view text) { return "`" + std::string(text) + "`"; }

std::string alternatives(const std::vector<std::string_view>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
    text += code(words[i]);
  }
  return text;
}

std::string type_name(const KeyInfo& row) {
  std::string words = row.keywords.empty() ? "" : alternatives(row.keywords) + " or ";
  switch (row.type) {
    case ValueType::section:
      return "section";
    case ValueType::section_list:
      return "list of sections";
    case ValueType::section_or_none:
      return "section or `none`";
    case ValueType::free_map:
      return "map";
    case ValueType::real:
      return words + "number";
    case ValueType::integer:
      return words + "whole number";
    case ValueType::text:
      return "name";
    case ValueType::choice:
      return alternatives(row.keywords);
    case ValueType::real_pair:
      return "[x, y] or number";
    case ValueType::real_list:
      return "list of numbers";
    case ValueType::sphere_list:
      return "list of [axial, radius] or [axial, radius, lateral]";
    case ValueType::any:
      return "see description";
  }
  return "";
}

std::string default_text(const KeyInfo& row) {
  if (!row.default_note.empty()) return std::string(row.default_note);
  if (row.default_value.empty()) {
    return row.type == ValueType::section || row.type == ValueType::section_list ? "" : "required";
  }
  return code(row.default_value);
}

std::string table(const Schema& schema) {
  std::string text =
      "| key | type | unit | default | allowed | description |\n"
      "|---|---|---|---|---|---|\n";
  for (const KeyInfo& row : schema.keys()) {
    const bool numeric = row.type == ValueType::real || row.type == ValueType::integer ||
                         row.type == ValueType::real_pair || row.type == ValueType::real_list;
    text += "| " + code(row.path) + " | " + type_name(row) + " | " + std::string(row.unit) + " | " +
            default_text(row) + " | " + (numeric ? row.range.describe() : "") + " | " +
            std::string(row.doc) + " |\n";
  }
  return text;
}

constexpr const char* kIntroduction = R"(# Scenario reference

<!-- Generated from scenarios/schema.cpp; do not edit by hand. Regenerate with
     cmake --build build --target scenario-reference
     (which runs RODSORT_UPDATE_REFERENCE=1 build/tests/scenarios_tests "[reference]"). -->

A scenario is a YAML file that describes one simulation: the cell, the drive, the rods, the trap,
how long to run and what to write. Every key has a default (the values of Kumar et al., "Sorting
motile rods by activity") except where the table says *required*, so a scenario lists only what
differs from the paper. `rodsort validate FILE` prints the scenario with every default explicit.

Units: millimetre, gram, second; angles in degrees. Paths below join nested keys with `.`, and
`species[]` stands for every item of the species list; on the command line,
`--set species[0].noise.kick_eps=0.02` sets one value (a YAML value; `null` restores the
default) before the file is checked.

Every problem of a file is reported at once, each with `file:line:col`, the key, the value found
and what was expected, for example
`fig2.yaml:14:7: trap.angle: must be in (0, 180) degrees, got 190`. A misspelt key is an error
that proposes the nearest known key. Setups that cannot work are refused with the reason: a rod
thicker than the gap or short enough to stand on end in it, a trap that does not fit in the cell,
more rods than random placement can fit (40% of the area), fewer than 20 time steps per drive
period.

Rod counts: `count: auto` is the paper's rule N = round(r A_t / a), with r =
`population.trap_area_ratio` (1.2), A_t = L^2 sin(theta) / 2 the trap's area and a the area of the
rod's projection on the plate. In a mixture the species counted `auto` share r A_t in proportion
to their number `fraction`s. Without a trap, `count: auto` needs `population.area_fraction`.
Initial rods are placed at random, without overlapping each other or the walls, from `seed`.

Examples: `scenarios/quickstart.yaml`, and `scenarios/library/`, which holds the paper's system
(`paper.yaml`) and one scenario or sweep per simulation figure of the paper.
)";

constexpr const char* kSweepIntroduction = R"(
A sweep file runs one base scenario over a grid of values, one run directory per point:

```yaml
# theta_c against the collision-kick noise (Fig. 2b, inset)
base: paper.yaml                             # or the scenario's keys inline
set:                                         # the same for every point
  run.duration: 600
grid:
  - trap.angle: {from: 90, to: 150, step: 5}
  - species[0].noise.kick_eps: [0.005, 0.01, 0.015, 0.02]
  - seed: [1, 2]
```

The points are every combination of one value per axis (here 13 x 4 x 2). Keys listed in one axis
change together:

```yaml
grid:
  - trap.angle: [125, 130, 135]
  - box.size: [86.85, 130.275, 173.7]        # the cell and the trap grow together
    trap.arm_length: [45, 67.5, 90]
```

Each point is named from its values (`angle-125_size-86.85_arm_length-45`) and checked like a
scenario with `--set` overrides; errors name the line of the sweep file that set the value.

)";

}  // namespace

std::string scenario_reference_markdown() {
  return std::string(kIntroduction) + "\n## " + std::string(scenario_schema().title()) + "\n\n" +
         table(scenario_schema()) + "\n## " + std::string(sweep_schema().title()) + "\n" +
         kSweepIntroduction + table(sweep_schema());
}

}  // namespace rodsort::scenarios
