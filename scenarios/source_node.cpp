#include "scenarios/source_node.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <set>
#include <system_error>

namespace rodsort::scenarios {
namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& source,
                           const SourceLocation& fallback) {
  if (mark.is_null()) return fallback;
  return {source, mark.line + 1, mark.column + 1};
}

// A scenario is a few hundred nodes and a few kilobytes; these bounds are a thousand times that,
// and they keep a hostile file (an alias that refers to itself, aliases nested ten deep that
// expand to billions of nodes, a file that never ends) from exhausting the stack or the memory.
constexpr std::size_t kMaxNodes = 200'000;              ///< after aliases are expanded
constexpr std::size_t kMaxExpandedText = 16'000'000;    ///< scalar bytes after expansion
constexpr std::size_t kMaxDepth = 64;                   ///< nested maps and sequences
constexpr std::uintmax_t kMaxFileBytes = 16'000'000;

/// Turns yaml-cpp's node graph into a SourceNode tree, refusing what a scenario never needs and
/// what would not end: a collection that contains itself through an alias, expansion beyond the
/// bounds above, tags. After the first refusal of a bound, conversion stops.
class Converter {
 public:
  Converter(const std::string& source, Diagnostics& diagnostics)
      : source_(source), diagnostics_(diagnostics) {}

  bool refused() const { return refused_; }

  SourceNode convert(const YAML::Node& node, const SourceLocation& fallback) {
    SourceNode out;
    out.where = location_of(node.Mark(), source_, fallback);
    if (refused_) return out;
    if (++nodes_ > kMaxNodes) {
      return refuse(out.where, "more than " + std::to_string(kMaxNodes) +
                                   " values once its aliases are expanded; a scenario needs a "
                                   "few hundred (are aliases nested inside each other?)");
    }
    if (!tag_allowed(node)) {
      diagnostics_.error(out.where, "",
                         "a YAML tag (" + node.Tag() +
                             ") is not read: write the value without it (quote a string)");
      return out;
    }
    switch (node.Type()) {
      case YAML::NodeType::Undefined:
      case YAML::NodeType::Null:
        out.kind = SourceNode::Kind::null;
        break;
      case YAML::NodeType::Scalar:
        out.kind = SourceNode::Kind::scalar;
        expanded_text_ += node.Scalar().size();
        if (expanded_text_ > kMaxExpandedText) {
          return refuse(out.where, "more than " + std::to_string(kMaxExpandedText) +
                                       " bytes of values once its aliases are expanded");
        }
        out.scalar = node.Scalar();
        // yaml-cpp tags plain scalars "?" and quoted ones "!".
        out.quoted = node.Tag() == "!";
        break;
      case YAML::NodeType::Sequence:
        out.kind = SourceNode::Kind::sequence;
        if (!open(node, out.where)) return out;
        for (const YAML::Node& item : node) {
          out.items.push_back(convert(item, out.where));
          if (refused_) break;
        }
        ancestors_.pop_back();
        break;
      case YAML::NodeType::Map: {
        out.kind = SourceNode::Kind::map;
        if (!open(node, out.where)) return out;
        std::set<std::string> seen;
        for (const auto& pair : node) {
          SourceNode::Entry entry;
          entry.key_where = location_of(pair.first.Mark(), source_, out.where);
          if (!pair.first.IsScalar()) {
            diagnostics_.error(entry.key_where, "", "a key must be a plain name, got a collection");
            continue;
          }
          entry.key = pair.first.Scalar();
          if (!seen.insert(entry.key).second) {
            diagnostics_.error(entry.key_where, entry.key,
                               "duplicate key (a key may appear once in a map)");
            continue;
          }
          entry.value = convert(pair.second, entry.key_where);
          out.entries.push_back(std::move(entry));
          if (refused_) break;
        }
        ancestors_.pop_back();
        break;
      }
    }
    return out;
  }

 private:
  // Plain scalars and collections carry the non-specific tag "?", quoted scalars "!"; anything
  // else was written by the user (`!!str 60`, `!foo 60`), and reading it as if untagged would
  // make `!!str 60` a number while `"60"` is refused.
  static bool tag_allowed(const YAML::Node& node) {
    const std::string& tag = node.Tag();
    return tag.empty() || tag == "?" || (tag == "!" && node.IsScalar());
  }

  /// Enters a collection; false (and a diagnostic) when it is one of its own ancestors or the
  /// nesting is too deep.
  bool open(const YAML::Node& node, const SourceLocation& where) {
    for (const YAML::Node& ancestor : ancestors_) {
      if (ancestor.is(node)) {
        diagnostics_.error(where, "",
                           "an alias refers to the collection that contains it, a value "
                           "without end");
        return false;
      }
    }
    if (ancestors_.size() >= kMaxDepth) {
      refuse(where, "maps and sequences nested more than " + std::to_string(kMaxDepth) +
                        " deep; a scenario needs four");
      return false;
    }
    ancestors_.push_back(node);
    return true;
  }

  SourceNode refuse(const SourceLocation& where, const std::string& why) {
    refused_ = true;
    diagnostics_.error(where, "", "the YAML holds " + why);
    SourceNode out;
    out.where = where;
    return out;
  }

  const std::string& source_;
  Diagnostics& diagnostics_;
  std::vector<YAML::Node> ancestors_;
  std::size_t nodes_ = 0;
  std::size_t expanded_text_ = 0;
  bool refused_ = false;
};

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
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(std::string(text));
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this is "bad file".
    diagnostics.error(location_of(e.mark, source, {source, 0, 0}), "",
                      "the YAML holds maps and sequences nested more than " +
                          std::to_string(e.depth()) + " deep; a scenario needs four");
    return std::nullopt;
  } catch (const YAML::Exception& e) {
    diagnostics.error(location_of(e.mark, source, {source, 0, 0}), "",
                      "YAML syntax error: " + e.msg);
    return std::nullopt;
  }
  if (documents.empty()) {  // empty, or only comments
    SourceNode nothing;
    nothing.where = {source, 1, 1};
    return nothing;
  }
  if (documents.size() > 1) {
    diagnostics.error(location_of(documents[1].Mark(), source, {source, 0, 0}), "",
                      "a second YAML document; the text must hold one (remove the `---` and "
                      "what follows, or put it in a file of its own)");
    return std::nullopt;
  }
  Converter converter(source, diagnostics);
  SourceNode root = converter.convert(documents.front(), {source, 1, 1});
  if (converter.refused()) return std::nullopt;
  return root;
}

std::optional<SourceNode> read_yaml_file(const std::filesystem::path& path,
                                         Diagnostics& diagnostics) {
  const SourceLocation file{path.string(), 0, 0};
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    diagnostics.error(file, "", "cannot open the file for reading: no such file");
    return std::nullopt;
  }
  if (error) {
    diagnostics.error(file, "", "cannot open the file for reading: " + error.message());
    return std::nullopt;
  }
  // Opening a FIFO would block until a writer comes, and a device may never end: refuse both
  // before opening.
  if (std::filesystem::is_directory(status)) {
    diagnostics.error(file, "", "is a directory; expected a YAML file");
    return std::nullopt;
  }
  if (!std::filesystem::is_regular_file(status)) {
    diagnostics.error(file, "",
                      "is not a regular file (a device, a pipe or a socket); expected a YAML file");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.error(file, "", "cannot open the file for reading");
    return std::nullopt;
  }
  // Read at most one byte past the bound, so that a file that grows while it is read is still
  // refused rather than read without end.
  std::string text(kMaxFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxFileBytes) {
    diagnostics.error(file, "",
                      "larger than " + std::to_string(kMaxFileBytes / 1'000'000) +
                          " MB; a scenario is a few kilobytes");
    return std::nullopt;
  }
  std::optional<SourceNode> root = parse_yaml(text, path.string(), diagnostics);
  if (root && root->is_null()) {
    diagnostics.error({path.string(), 1, 1}, "",
                      "the file holds no YAML value (it is empty, only comments, or null); "
                      "expected a map of keys");
    return std::nullopt;
  }
  return root;
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
