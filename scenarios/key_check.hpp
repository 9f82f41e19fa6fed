#pragma once
// The unknown-key check: every key of a file must be a row of its schema. A misspelt key is the
// commonest mistake in an input file and, left alone, silently leaves a default in place; here it
// is an error that proposes the nearest known key.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/diagnostic.hpp"
#include "scenarios/schema.hpp"
#include "scenarios/source_node.hpp"

namespace rodsort::scenarios {

/// Reports every key the schema does not know, and every section that is not a map or list.
void check_keys(const SourceNode& root, const Schema& schema, Diagnostics& diagnostics);

/// Edits (insert, delete, substitute, swap two neighbours) from a to b, ignoring case.
std::size_t edit_distance(std::string_view a, std::string_view b);
/// The candidate nearest to `word`, if near enough to be a likely misspelling.
std::optional<std::string_view> closest_word(std::string_view word,
                                             const std::vector<std::string_view>& candidates);
/// "a, b, c".
std::string join_words(const std::vector<std::string_view>& words);
/// `unknown <what> "word"; did you mean "x"?` or `...; expected one of: a, b`.
std::string unknown_word_message(std::string_view what, std::string_view word,
                                 const std::vector<std::string_view>& candidates);

}  // namespace rodsort::scenarios
