#include "scenarios/override.hpp"

#include <cctype>
#include <variant>

#include "scenarios/number_text.hpp"
#include "scenarios/schema.hpp"

namespace rodsort::scenarios {
namespace {

using Segment = std::variant<std::string, std::size_t>;  // a map key, or a list index

/// Splits "species[0].noise.kick_eps"; nullopt when malformed.
std::optional<std::vector<Segment>> split_path(std::string_view path) {
  std::vector<Segment> segments;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == i) return std::nullopt;
    segments.emplace_back(std::string(path.substr(i, end - i)));
    i = end;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos) return std::nullopt;
      const auto index = parse_integer(path.substr(i + 1, close - i - 1));
      if (!index || *index < 0) return std::nullopt;
      segments.emplace_back(static_cast<std::size_t>(*index));
      i = close + 1;
    }
    if (i < path.size()) {
      if (path[i] != '.' || i + 1 == path.size()) return std::nullopt;
      ++i;
    }
  }
  if (segments.empty()) return std::nullopt;
  return segments;
}

/// A list left out of the file holds its schema default, e.g. the one paper species.
void materialize_default(SourceNode& node, const std::string& pattern,
                         const SourceLocation& where) {
  const KeyInfo* row = scenario_schema().find(pattern);
  if (row == nullptr || row->type != ValueType::section_list || row->default_value.empty()) return;
  Diagnostics ignored;
  if (auto parsed = parse_yaml(row->default_value, where.source, ignored)) {
    relocate(*parsed, where);
    node = std::move(*parsed);
  }
}

void apply(SourceNode& root, const Override& override_, Diagnostics& diagnostics) {
  const auto segments = split_path(override_.path);
  if (!segments) {
    diagnostics.error(override_.where, override_.path,
                      "malformed key path; expected keys joined by '.', with [i] for a list item "
                      "(e.g. species[0].noise.kick_eps)");
    return;
  }
  SourceNode* node = &root;
  std::string pattern;
  std::string walked;
  for (std::size_t s = 0; s < segments->size(); ++s) {
    const bool last = s + 1 == segments->size();
    if (const auto* key = std::get_if<std::string>(&(*segments)[s])) {
      if (node->is_sequence()) {
        diagnostics.error(override_.where, override_.path,
                          walked + " is a list; select an item with " + walked + "[i]");
        return;
      }
      if (!node->is_map()) {
        // A section left out, written empty, or a word such as `trap: none`, becomes a section.
        node->kind = SourceNode::Kind::map;
        node->scalar.clear();
        node->where = override_.where;
      }
      pattern = join_path(pattern, *key);
      walked = join_path(walked, *key);
      if (last) {
        if (override_.value.is_null()) {
          node->erase(*key);
          return;
        }
        if (SourceNode* existing = node->find(*key)) {
          *existing = override_.value;
        } else {
          node->entries.push_back({*key, override_.where, override_.value});
        }
        return;
      }
      SourceNode* child = node->find(*key);
      if (child == nullptr) {
        node->entries.push_back({*key, override_.where, SourceNode{}});
        child = &node->entries.back().value;
        child->where = override_.where;
      }
      node = child;
    } else {
      const std::size_t index = std::get<std::size_t>((*segments)[s]);
      if (node->is_null()) materialize_default(*node, pattern, override_.where);
      if (!node->is_sequence()) {
        diagnostics.error(override_.where, override_.path, walked + " is not a list");
        return;
      }
      pattern += "[]";
      if (index > node->items.size()) {
        diagnostics.error(override_.where, override_.path,
                          walked + " has " + std::to_string(node->items.size()) +
                              " items; the index may be at most " +
                              std::to_string(node->items.size()) + " (a new item)");
        return;
      }
      // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + std::to_string(i).
      walked.append("[").append(std::to_string(index)).append("]");
      if (index == node->items.size()) {
        SourceNode item;
        item.kind = SourceNode::Kind::map;
        item.where = override_.where;
        node->items.push_back(std::move(item));
      }
      if (last) {
        node->items[index] = override_.value;
        return;
      }
      node = &node->items[index];
    }
  }
}

}  // namespace

std::optional<Override> parse_set_option(std::string_view text, Diagnostics& diagnostics) {
  const SourceLocation where{"--set " + std::string(text), 0, 0};
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    diagnostics.error(where, "", "expected key.path=value, e.g. --set trap.angle=130");
    return std::nullopt;
  }
  Override out;
  out.path = std::string(text.substr(0, equals));
  out.where = where;
  auto value = parse_yaml(text.substr(equals + 1), where.source, diagnostics);
  if (!value) return std::nullopt;
  relocate(*value, where);
  out.value = std::move(*value);
  return out;
}

void apply_overrides(SourceNode& root, const std::vector<Override>& overrides,
                     Diagnostics& diagnostics) {
  for (const Override& override_ : overrides) apply(root, override_, diagnostics);
}

}  // namespace rodsort::scenarios
