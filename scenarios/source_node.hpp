#pragma once
// A YAML document as a tree that remembers where every key and value came from. yaml-cpp's nodes
// know their position in the text they were parsed from, but a value set by `--set` or by a sweep
// point comes from somewhere else; this tree keeps one SourceLocation per node whatever its origin,
// so that validation, which runs after overrides are applied, can still name the right place.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scenarios/diagnostic.hpp"

namespace rodsort::scenarios {

struct SourceNode {
  enum class Kind { null, scalar, sequence, map };
  struct Entry;

  Kind kind = Kind::null;
  std::string scalar;             ///< text of a scalar, as written
  bool quoted = false;            ///< a quoted scalar is a string, never a number
  std::vector<SourceNode> items;  ///< of a sequence
  std::vector<Entry> entries;     ///< of a map, in file order
  SourceLocation where;

  bool is_null() const { return kind == Kind::null; }
  bool is_scalar() const { return kind == Kind::scalar; }
  bool is_sequence() const { return kind == Kind::sequence; }
  bool is_map() const { return kind == Kind::map; }

  /// The value of `key` in a map; nullptr when absent or when this is not a map.
  const SourceNode* find(std::string_view key) const;
  SourceNode* find(std::string_view key);
  const Entry* find_entry(std::string_view key) const;
  /// Removes `key` from a map; true when it was there.
  bool erase(std::string_view key);

  /// How the value reads in a message: a scalar as written, a collection in flow style.
  std::string describe() const;
};

struct SourceNode::Entry {
  std::string key;
  SourceLocation key_where;
  SourceNode value;
};

/// Parses YAML text; a syntax error is reported in `diagnostics` (with `source` as the file name)
/// and gives std::nullopt. A duplicate key is reported and its first value kept, so that the rest
/// of the file is still checked.
std::optional<SourceNode> parse_yaml(std::string_view text, const std::string& source,
                                     Diagnostics& diagnostics);
/// Reads and parses a file; a missing or unreadable file is a diagnostic too.
std::optional<SourceNode> read_yaml_file(const std::filesystem::path& path,
                                         Diagnostics& diagnostics);

/// Sets every location in the tree (keys and values) to `where`.
void relocate(SourceNode& node, const SourceLocation& where);

}  // namespace rodsort::scenarios
