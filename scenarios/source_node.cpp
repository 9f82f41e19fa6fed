#include "scenarios/source_node.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace rodsort::scenarios {
namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& source,
                           const SourceLocation& fallback) {
  if (mark.is_null()) return fallback;
  return {source, mark.line + 1, mark.column + 1};
}

SourceNode convert(const YAML::Node& node, const std::string& source,
                   const SourceLocation& fallback, Diagnostics& diagnostics) {
  SourceNode out;
  out.where = location_of(node.Mark(), source, fallback);
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      out.kind = SourceNode::Kind::null;
      break;
    case YAML::NodeType::Scalar:
      out.kind = SourceNode::Kind::scalar;
      out.scalar = node.Scalar();
      // yaml-cpp tags plain scalars "?" and quoted ones "!".
      out.quoted = node.Tag() == "!";
      break;
    case YAML::NodeType::Sequence:
      out.kind = SourceNode::Kind::sequence;
      for (const YAML::Node& item : node) {
        out.items.push_back(convert(item, source, out.where, diagnostics));
      }
      break;
    case YAML::NodeType::Map: {
      out.kind = SourceNode::Kind::map;
      std::set<std::string> seen;
      for (const auto& pair : node) {
        SourceNode::Entry entry;
        entry.key_where = location_of(pair.first.Mark(), source, out.where);
        if (!pair.first.IsScalar()) {
          diagnostics.error(entry.key_where, "", "a key must be a plain name, got a collection");
          continue;
        }
        entry.key = pair.first.Scalar();
        if (!seen.insert(entry.key).second) {
          diagnostics.error(entry.key_where, entry.key,
                            "duplicate key (a key may appear once in a map)");
          continue;
        }
        entry.value = convert(pair.second, source, entry.key_where, diagnostics);
        out.entries.push_back(std::move(entry));
      }
      break;
    }
  }
  return out;
}

std::string quote(const std::string& text) { return "\"" + text + "\""; }

}  // namespace

const SourceNode::Entry* SourceNode::find_entry(std::string_view key) const {
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const Entry& entry) { return entry.key == key; });
  return it == entries.end() ? nullptr : &*it;
}

const SourceNode* SourceNode::find(std::string_view key) const {
  const Entry* entry = find_entry(key);
  return entry ? &entry->value : nullptr;
}

SourceNode* SourceNode::find(std::string_view key) {
  return const_cast<SourceNode*>(std::as_const(*this).find(key));
}

bool SourceNode::erase(std::string_view key) {
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const Entry& entry) { return entry.key == key; });
  if (it == entries.end()) return false;
  entries.erase(it);
  return true;
}

std::string SourceNode::describe() const {
  switch (kind) {
    case Kind::null:
      return "null";
    case Kind::scalar:
      return quoted ? quote(scalar) : scalar;
    case Kind::sequence: {
      std::string text = "[";
      for (std::size_t i = 0; i < items.size(); ++i) {
        text += (i ? ", " : "") + items[i].describe();
      }
      return text + "]";
    }
    case Kind::map: {
      std::string text = "{";
      for (std::size_t i = 0; i < entries.size(); ++i) {
        text += (i ? ", " : "") + entries[i].key + ": " + entries[i].value.describe();
      }
      return text + "}";
    }
  }
  return {};
}

std::optional<SourceNode> parse_yaml(std::string_view text, const std::string& source,
                                     Diagnostics& diagnostics) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    diagnostics.error(location_of(e.mark, source, {source, 0, 0}), "",
                      "YAML syntax error: " + e.msg);
    return std::nullopt;
  }
  return convert(root, source, {source, 1, 1}, diagnostics);
}

std::optional<SourceNode> read_yaml_file(const std::filesystem::path& path,
                                         Diagnostics& diagnostics) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.error({path.string(), 0, 0}, "", "cannot open the file for reading");
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_yaml(text.str(), path.string(), diagnostics);
}

void relocate(SourceNode& node, const SourceLocation& where) {
  node.where = where;
  for (SourceNode& item : node.items) relocate(item, where);
  for (SourceNode::Entry& entry : node.entries) {
    entry.key_where = where;
    relocate(entry.value, where);
  }
}

}  // namespace rodsort::scenarios
