#pragma once
// One table of keys per file format (scenario, sweep). Each row gives a key's path, type, unit,
// default, allowed range and a one-line doc. The same rows drive the unknown-key check and its
// "did you mean", the typed reading and range checks of every value, the defaults, and the
// generated docs/scenario-reference.md. A key that is not in the table cannot be read.
//
// Paths: "drive.gap"; the items of a list are "species[]" ("species[].noise.kick_eps"); the keys of
// a map whose keys the user chooses are "*" ("materials.*.friction").

#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rodsort::scenarios {

enum class ValueType {
  section,          ///< a map of the keys listed below it
  section_list,     ///< a list of sections
  section_or_none,  ///< a section, or the word `none`
  free_map,         ///< a map whose keys the user chooses; its values are the "*" rows
  real,             ///< a number, possibly replaced by one of the row's keywords
  integer,          ///< a whole number, possibly replaced by one of the row's keywords
  text,             ///< a name: letters, digits, '.', '_', '-'
  choice,           ///< one of the row's keywords
  real_pair,        ///< [x, y]; one number stands for both
  real_list,        ///< [a, b, ...]
  sphere_list,      ///< [[axial, radius], ...], each with an optional lateral offset third
  any,              ///< any YAML; read by hand, not by the generic reader
};

/// Allowed interval of a number (for lists and pairs, of each element).
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< min itself excluded
  bool max_open = false;

  bool contains(double value) const;
  bool unbounded() const;
  /// "> 0", ">= 0", "in (0, 180)", "in [0, 1]"; empty when unbounded.
  std::string describe() const;
};

struct KeyInfo {
  KeyInfo(std::string_view path, ValueType type, std::string_view unit,
          std::string_view default_value, Range range, std::vector<std::string_view> keywords,
          std::string_view doc, std::string_view default_note = {})
      : path(path),
        type(type),
        unit(unit),
        default_value(default_value),
        range(range),
        keywords(std::move(keywords)),
        doc(doc),
        default_note(default_note) {}

  std::string_view path;
  ValueType type;
  std::string_view unit;           ///< "mm", "degrees", "1/mm"; empty when dimensionless
  std::string_view default_value;  ///< YAML text used when the key is absent; empty: none
  Range range;
  std::vector<std::string_view> keywords;  ///< choices, or words that may replace a number
  std::string_view doc;
  std::string_view default_note;  ///< shown in the docs instead of default_value when set
};

class Schema {
 public:
  Schema(std::string_view title, std::vector<KeyInfo> keys);

  std::string_view title() const { return title_; }
  const std::vector<KeyInfo>& keys() const { return keys_; }
  /// The row of a path ("species[].count"), or nullptr.
  const KeyInfo* find(std::string_view path) const;
  /// The row of a path the program knows is in the table.
  const KeyInfo& at(std::string_view path) const;
  /// The rows directly below `parent` ("" for the top level, "species[]" for a list's items).
  std::vector<const KeyInfo*> children(std::string_view parent) const;

 private:
  std::string_view title_;
  std::vector<KeyInfo> keys_;
};

/// The keys of a scenario file.
const Schema& scenario_schema();
/// The keys of a sweep file.
const Schema& sweep_schema();

/// Joins a parent path and a key: ("", "seed") -> "seed", ("trap", "angle") -> "trap.angle".
std::string join_path(std::string_view parent, std::string_view key);

}  // namespace rodsort::scenarios
