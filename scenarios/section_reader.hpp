#pragma once
// Typed reading of one section of a SourceNode tree through its schema: the row of each key gives
// the type, the unit, the range and the default, so the code that builds a ScenarioSpec only names
// keys. Every rejected value is reported (with file:line:col, key path, value found and what was
// expected) and reading goes on, so that one pass finds every problem of a file.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/diagnostic.hpp"
#include "scenarios/schema.hpp"
#include "scenarios/source_node.hpp"
#include "scenarios/sourced.hpp"

namespace rodsort::scenarios {

/// A number, or one of the words its schema row allows instead ("auto", "random").
struct NumberOrKeyword {
  std::string keyword;  ///< empty when the value is the number
  double number = 0.0;

  bool is(std::string_view word) const { return keyword == word; }
};

class SectionReader {
 public:
  /// `node` may be null or absent (a section left out): every key then takes its default.
  SectionReader(const Schema& schema, const SourceNode* node, std::string pattern, std::string path,
                SourceLocation where, Diagnostics& diagnostics);

  const std::string& path() const { return path_; }
  const SourceLocation& where() const { return where_; }
  /// The key is present with a non-null value.
  bool has(std::string_view key) const;
  /// Present value of a key, or nullptr.
  const SourceNode* node(std::string_view key) const;
  std::string path_of(std::string_view key) const;
  /// Of the key's value when present, else of this section.
  SourceLocation location_of(std::string_view key) const;
  /// Keys of a free map, in file order.
  std::vector<std::string> keys() const;
  /// Where a key of a free map is written.
  SourceLocation key_location(std::string_view key) const;

  /// Absent: the schema's default, which the row must have.
  Sourced<double> real(std::string_view key);
  std::optional<Sourced<double>> optional_real(std::string_view key);
  /// Absent: an error saying the key is required (`context` says when, e.g. "with a trap").
  Sourced<double> required_real(std::string_view key, std::string_view context);
  Sourced<std::int64_t> integer(std::string_view key);
  Sourced<NumberOrKeyword> number_or_keyword(std::string_view key);
  Sourced<std::string> text(std::string_view key);
  /// Absent without a default: an empty string, not given.
  Sourced<std::string> choice(std::string_view key);
  Sourced<std::array<double, 2>> real_pair(std::string_view key);
  std::optional<Sourced<std::array<double, 2>>> optional_real_pair(std::string_view key);
  Sourced<std::vector<double>> real_list(std::string_view key);
  /// Pairs [axial, radius]; radii must be > 0.
  std::optional<Sourced<std::vector<std::array<double, 3>>>> sphere_list(std::string_view key);

  SectionReader section(std::string_view key);
  /// The items of a list of sections; the schema's default list when absent.
  std::vector<SectionReader> list(std::string_view key);

 private:
  struct Found {
    const SourceNode* node;  ///< the value, or the parsed default; nullptr when neither
    bool given;
    const KeyInfo& row;
  };
  Found find(std::string_view key);
  template <class T>
  Sourced<T> start(std::string_view key, const Found& found) const;
  std::optional<double> to_real(const SourceNode& node, const KeyInfo& row, const std::string& path,
                                bool check_range);

  const Schema& schema_;
  const SourceNode* node_;
  std::string pattern_;
  std::string path_;
  SourceLocation where_;
  Diagnostics& diagnostics_;
  /// Parsed defaults, kept alive for the readers of the sections and lists made from them.
  std::shared_ptr<std::vector<std::unique_ptr<SourceNode>>> defaults_;
};

/// Letters, digits, '.', '_' and '-' only: safe as a directory name and as a CSV column.
bool is_plain_name(std::string_view name);

}  // namespace rodsort::scenarios
