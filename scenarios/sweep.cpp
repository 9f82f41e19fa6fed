#include "scenarios/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "scenarios/key_check.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/schema.hpp"
#include "scenarios/section_reader.hpp"

namespace rodsort::scenarios {
namespace {

/// Points a sweep may have; a typo in a range (step 0.001 for 0.1) should not make millions.
constexpr std::size_t kMaxPoints = 100000;

struct Axis {
  std::vector<std::string> keys;
  std::vector<SourceLocation> key_where;
  std::vector<std::vector<SourceNode>> values;  ///< values[k]: the list of keys[k]
};

/// Text fit for a directory name: letters, digits, '.', '_', '-'; brackets dropped.
std::string plain(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '[' || c == ']' || c == ' ' || c == '"') continue;
    out += is_plain_name(std::string_view(&c, 1)) ? c : '_';
  }
  return out;
}

std::string value_label(const SourceNode& value) {
  if (value.is_sequence()) {
    std::string text;
    for (const SourceNode& item : value.items)
      text += (text.empty() ? "" : "x") + value_label(item);
    return text;
  }
  return plain(value.is_scalar() ? value.scalar : value.describe());
}

/// The last `count` segments of a key path: ("species[0].noise.kick_eps", 2) -> "noise.kick_eps".
std::string tail(const std::string& path, std::size_t count) {
  std::size_t start = path.size();
  for (std::size_t i = 0; i < count && start != std::string::npos && start > 0; ++i) {
    start = path.rfind('.', start - 1);
  }
  return start == std::string::npos || start == 0 ? path : path.substr(start + 1);
}

/// The shortest tails of the key paths that tell them apart: trap.angle -> "angle".
std::vector<std::string> key_labels(const std::vector<std::string>& keys) {
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    for (std::size_t count = 1;; ++count) {
      const std::string mine = tail(keys[i], count);
      const bool unique =
          mine == keys[i] || std::none_of(keys.begin(), keys.end(), [&](const auto& other) {
            return &other != &keys[i] && tail(other, count) == mine;
          });
      if (unique) {
        labels.push_back(plain(mine));
        break;
      }
    }
  }
  return labels;
}

/// {from, to, step}, both ends included.
std::optional<std::vector<SourceNode>> expand_range(const SourceNode& range, const std::string& key,
                                                    Diagnostics& diagnostics) {
  std::optional<double> bounds[3];
  const char* names[3] = {"from", "to", "step"};
  bool ok = true;
  for (const SourceNode::Entry& entry : range.entries) {
    if (std::find(std::begin(names), std::end(names), entry.key) == std::end(names)) {
      diagnostics.error(entry.key_where, key,
                        unknown_word_message("key", entry.key, {"from", "to", "step"}));
      ok = false;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const SourceNode* value = range.find(names[i]);
    if (value == nullptr) {
      diagnostics.error(
          range.where, key,
          std::string("a range needs from, to and step; ") + names[i] + " is missing");
      ok = false;
      continue;
    }
    if (value->is_scalar() && !value->quoted) bounds[i] = parse_real(value->scalar);
    if (!bounds[i]) {
      diagnostics.error(value->where, key,
                        std::string(names[i]) + ": expected a number, got " + value->describe());
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  const double from = *bounds[0], to = *bounds[1], step = *bounds[2];
  if (!(step > 0.0) || to < from) {
    diagnostics.error(range.where, key,
                      "a range needs step > 0 and to >= from, got " + range.describe());
    return std::nullopt;
  }
  const double intervals = std::floor((to - from) / step + 1e-9);
  if (intervals + 1 > static_cast<double>(kMaxPoints)) {
    diagnostics.error(range.where, key,
                      "the range has more than " + std::to_string(kMaxPoints) + " values");
    return std::nullopt;
  }
  std::vector<SourceNode> values;
  for (int i = 0; i <= static_cast<int>(intervals); ++i) {
    // %.12g drops the last bits of from + i step (0.30000000000000004 -> 0.3).
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", from + i * step);
    SourceNode value;
    value.kind = SourceNode::Kind::scalar;
    value.scalar = format_real(*parse_real(text));
    value.where = range.where;
    values.push_back(std::move(value));
  }
  return values;
}

std::optional<Axis> read_axis(const SourceNode& node, std::size_t index, Diagnostics& diagnostics) {
  const std::string path = "grid[" + std::to_string(index) + "]";
  if (!node.is_map() || node.entries.empty()) {
    diagnostics.error(node.where, path,
                      "expected a map from key paths to lists of values (e.g. trap.angle: [110, "
                      "120]), got " +
                          node.describe());
    return std::nullopt;
  }
  Axis axis;
  bool ok = true;
  for (const SourceNode::Entry& entry : node.entries) {
    std::optional<std::vector<SourceNode>> values;
    if (entry.value.is_sequence() && !entry.value.items.empty()) {
      values = entry.value.items;
    } else if (entry.value.is_map()) {
      values = expand_range(entry.value, entry.key, diagnostics);
    } else {
      diagnostics.error(
          entry.value.where, entry.key,
          "expected a list of values or {from, to, step}, got " + entry.value.describe());
    }
    if (!values) {
      ok = false;
      continue;
    }
    axis.keys.push_back(entry.key);
    axis.key_where.push_back(entry.key_where);
    axis.values.push_back(std::move(*values));
  }
  if (!ok) return std::nullopt;
  for (std::size_t k = 1; k < axis.keys.size(); ++k) {
    if (axis.values[k].size() != axis.values[0].size()) {
      diagnostics.error(axis.key_where[k], axis.keys[k],
                        "has " + std::to_string(axis.values[k].size()) + " values but " +
                            axis.keys[0] + " has " + std::to_string(axis.values[0].size()) +
                            "; keys in one axis change together and need lists of one length");
      return std::nullopt;
    }
  }
  return axis;
}

std::vector<SweepPoint> expand(const std::vector<Axis>& axes) {
  std::vector<std::string> keys;
  for (const Axis& axis : axes) keys.insert(keys.end(), axis.keys.begin(), axis.keys.end());
  const std::vector<std::string> labels = key_labels(keys);
  std::size_t total = 1;
  for (const Axis& axis : axes) total *= axis.values[0].size();
  std::vector<SweepPoint> points;
  std::set<std::string> names;
  for (std::size_t index = 0; index < total; ++index) {
    SweepPoint point;
    point.index = index;
    std::size_t rest = index;
    std::vector<std::size_t> position(axes.size());
    for (std::size_t a = axes.size(); a-- > 0;) {
      position[a] = rest % axes[a].values[0].size();
      rest /= axes[a].values[0].size();
    }
    std::size_t label = 0;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      for (std::size_t k = 0; k < axes[a].keys.size(); ++k, ++label) {
        const SourceNode& value = axes[a].values[k][position[a]];
        point.overrides.push_back({axes[a].keys[k], value, axes[a].key_where[k]});
        point.name += (point.name.empty() ? "" : "_") + labels[label] + "-" + value_label(value);
      }
    }
    if (!names.insert(point.name).second) point.name += "_" + std::to_string(index);
    names.insert(point.name);
    points.push_back(std::move(point));
  }
  return points;
}

std::string default_name_of(const std::filesystem::path& path) {
  const std::string stem = plain(path.stem().string());
  return stem.empty() ? "sweep" : stem;
}

}  // namespace

SweepLoadResult load_sweep(const std::filesystem::path& path, bool check_points,
                           const std::vector<std::string>& set_options) {
  Diagnostics diagnostics;
  SweepLoadResult result;
  const std::optional<SourceNode> root = read_yaml_file(path, diagnostics);
  if (!root) return {std::nullopt, diagnostics.all()};
  const Schema& schema = sweep_schema();
  check_keys(*root, schema, diagnostics);
  if (!root->is_map()) {
    diagnostics.error(root->where, "",
                      "expected a map with base and grid, got " + root->describe());
    return {std::nullopt, diagnostics.all()};
  }
  SectionReader top(schema, &*root, "", "", root->where, diagnostics);

  Sweep sweep;
  sweep.file = path;
  const Sourced<std::string> name = top.text("name");
  sweep.name = name.given ? name.value : default_name_of(path);

  const SourceNode* base = top.node("base");
  if (base == nullptr) {
    diagnostics.error(root->where, "base",
                      "missing; give the base scenario's file, or its keys inline");
  } else if (base->is_scalar()) {
    sweep.base_file = path.parent_path() / base->scalar;
    if (auto tree = read_yaml_file(sweep.base_file, diagnostics)) sweep.base = std::move(*tree);
  } else if (base->is_map()) {
    sweep.base = *base;
  } else {
    diagnostics.error(base->where, "base",
                      "expected a file path or a map of scenario keys, got " + base->describe());
  }

  if (const SourceNode* set = top.node("set")) {
    if (set->is_map()) {
      for (const SourceNode::Entry& entry : set->entries) {
        sweep.fixed.push_back({entry.key, entry.value, entry.key_where});
      }
    } else {
      diagnostics.error(set->where, "set",
                        "expected a map from key paths to values, got " + set->describe());
    }
  }

  std::vector<Axis> axes;
  const SourceNode* grid = top.node("grid");
  if (grid == nullptr || !grid->is_sequence() || grid->items.empty()) {
    diagnostics.error(grid ? grid->where : root->where, "grid",
                      "expected a list of axes, e.g.\n  grid:\n    - trap.angle: [110, 120, 130]");
  } else {
    for (std::size_t i = 0; i < grid->items.size(); ++i) {
      if (auto axis = read_axis(grid->items[i], i, diagnostics)) axes.push_back(std::move(*axis));
    }
  }
  std::size_t total = 1;
  for (const Axis& axis : axes) {
    sweep.keys.insert(sweep.keys.end(), axis.keys.begin(), axis.keys.end());
    total *= axis.values[0].size();
    if (total > kMaxPoints) {
      diagnostics.error(grid->where, "grid",
                        "has more than " + std::to_string(kMaxPoints) + " points");
      break;
    }
  }
  for (std::size_t i = 0; i < sweep.keys.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (sweep.keys[i] == sweep.keys[j]) {
        diagnostics.error(grid->where, sweep.keys[i], "is swept twice in the grid");
      }
    }
  }
  for (const std::string& option : set_options) {
    std::optional<Override> parsed = parse_set_option(option, diagnostics);
    if (!parsed) continue;
    if (std::find(sweep.keys.begin(), sweep.keys.end(), parsed->path) != sweep.keys.end()) {
      diagnostics.error(parsed->where, parsed->path,
                        "is swept by the grid; --set changes keys every point shares");
      continue;
    }
    sweep.fixed.push_back(std::move(*parsed));
  }
  if (diagnostics.has_errors()) return {std::nullopt, diagnostics.all()};
  sweep.points = expand(axes);

  if (check_points) {
    std::set<std::string> seen;
    for (const SweepPoint& point : sweep.points) {
      for (const Diagnostic& diagnostic : load_sweep_point(sweep, point).diagnostics) {
        if (seen.insert(diagnostic.to_string()).second) {
          Diagnostic copy = diagnostic;
          copy.message += " [point " + point.name + "]";
          diagnostics.add(std::move(copy));
        }
      }
    }
  }
  if (diagnostics.has_errors()) return {std::nullopt, diagnostics.all()};
  result.sweep = std::move(sweep);
  result.diagnostics = diagnostics.all();
  return result;
}

LoadResult load_sweep_point(const Sweep& sweep, const SweepPoint& point) {
  std::vector<Override> overrides = sweep.fixed;
  overrides.insert(overrides.end(), point.overrides.begin(), point.overrides.end());
  const auto named = [](const std::vector<Override>& list) {
    return std::find_if(list.begin(), list.end(),
                        [](const Override& o) { return o.path == "name"; });
  };
  if (named(point.overrides) == point.overrides.end()) {
    std::string base_name = sweep.name;
    if (const SourceNode* name = sweep.base.find("name"); name && name->is_scalar()) {
      base_name = name->scalar;
    }
    if (const auto fixed = named(sweep.fixed); fixed != sweep.fixed.end()) {
      base_name = fixed->value.scalar;
    }
    SourceNode name;
    name.kind = SourceNode::Kind::scalar;
    name.scalar = base_name + "_" + point.name;
    name.where = {sweep.file.string(), 0, 0};
    overrides.push_back({"name", name, name.where});
  }
  LoadResult result = load_scenario_tree(sweep.base, sweep.name, overrides);
  if (result.scenario) result.scenario->source = sweep.base_file;
  return result;
}

}  // namespace rodsort::scenarios
