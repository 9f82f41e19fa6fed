#include "scenarios/key_check.hpp"

#include <algorithm>
#include <cctype>

namespace rodsort::scenarios {
namespace {

std::string_view last_segment(std::string_view path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

std::vector<std::string_view> child_names(const Schema& schema, std::string_view pattern) {
  std::vector<std::string_view> names;
  for (const KeyInfo* row : schema.children(pattern)) names.push_back(last_segment(row->path));
  return names;
}

class KeyChecker {
 public:
  KeyChecker(const Schema& schema, Diagnostics& diagnostics)
      : schema_(schema), diagnostics_(diagnostics) {}

  void section(const SourceNode& node, const std::string& pattern, const std::string& concrete) {
    if (node.is_null()) return;
    if (!node.is_map()) {
      diagnostics_.error(node.where, concrete,
                         "expected a map of keys (" + join_words(child_names(schema_, pattern)) +
                             "), got " + node.describe());
      return;
    }
    for (const SourceNode::Entry& entry : node.entries) {
      const std::string child_pattern = join_path(pattern, entry.key);
      const std::string child_concrete = join_path(concrete, entry.key);
      if (const KeyInfo* row = schema_.find(child_pattern)) {
        value(entry.value, *row, child_pattern, child_concrete);
      } else {
        unknown(entry, pattern, child_concrete);
      }
    }
  }

 private:
  void value(const SourceNode& node, const KeyInfo& row, const std::string& pattern,
             const std::string& concrete) {
    switch (row.type) {
      case ValueType::section:
        section(node, pattern, concrete);
        break;
      case ValueType::section_or_none:
        if (node.is_scalar() && node.scalar == "none") break;
        if (node.is_scalar() || node.is_sequence()) {
          diagnostics_.error(node.where, concrete,
                             "expected none or a map of keys (" +
                                 join_words(child_names(schema_, pattern)) + "), got " +
                                 node.describe());
          break;
        }
        section(node, pattern, concrete);
        break;
      case ValueType::section_list:
        if (!node.is_sequence()) {
          diagnostics_.error(node.where, concrete,
                             "expected a list (one `- ` item per entry), got " + node.describe());
          break;
        }
        for (std::size_t i = 0; i < node.items.size(); ++i) {
          const std::string item_concrete = concrete + "[" + std::to_string(i) + "]";
          if (node.items[i].is_map()) {
            section(node.items[i], pattern + "[]", item_concrete);
          } else {
            diagnostics_.error(node.items[i].where, item_concrete,
                               "expected a map of keys (" +
                                   join_words(child_names(schema_, pattern + "[]")) + "), got " +
                                   node.items[i].describe());
          }
        }
        break;
      case ValueType::free_map: {
        if (node.is_null()) break;
        if (!node.is_map()) {
          diagnostics_.error(node.where, concrete, "expected a map, got " + node.describe());
          break;
        }
        const std::string item_pattern = pattern + ".*";
        const KeyInfo& item_row = schema_.at(item_pattern);
        for (const SourceNode::Entry& entry : node.entries) {
          value(entry.value, item_row, item_pattern, join_path(concrete, entry.key));
        }
        break;
      }
      default:
        break;  // values are checked where they are read
    }
  }

  void unknown(const SourceNode::Entry& entry, const std::string& pattern,
               const std::string& concrete) {
    const std::vector<std::string_view> siblings = child_names(schema_, pattern);
    if (closest_word(entry.key, siblings) || siblings.empty()) {
      diagnostics_.error(entry.key_where, concrete,
                         unknown_word_message("key", entry.key, siblings));
      return;
    }
    // A key written at the wrong level ("angle" at the top) is found elsewhere in the schema.
    std::vector<std::string_view> elsewhere;
    for (const KeyInfo& row : schema_.keys()) {
      if (edit_distance(last_segment(row.path), entry.key) == 0) elsewhere.push_back(row.path);
    }
    if (!elsewhere.empty()) {
      diagnostics_.error(entry.key_where, concrete,
                         "unknown key \"" + entry.key + "\" here; did you mean " +
                             join_words(elsewhere) + "? (expected one of: " + join_words(siblings) +
                             ")");
      return;
    }
    diagnostics_.error(entry.key_where, concrete, unknown_word_message("key", entry.key, siblings));
  }

  const Schema& schema_;
  Diagnostics& diagnostics_;
};

}  // namespace

std::string join_words(const std::vector<std::string_view>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    text += (i ? ", " : "") + std::string(words[i]);
  }
  return text;
}

void check_keys(const SourceNode& root, const Schema& schema, Diagnostics& diagnostics) {
  KeyChecker(schema, diagnostics).section(root, "", "");
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance: Levenshtein plus transposition of neighbours ("angel").
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  const auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  };
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::optional<std::string_view> closest_word(std::string_view word,
                                             const std::vector<std::string_view>& candidates) {
  const std::size_t allowed = std::max<std::size_t>(2, word.size() / 3);
  std::optional<std::string_view> best;
  std::size_t best_distance = allowed + 1;
  for (std::string_view candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance && distance < std::max(word.size(), candidate.size())) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string unknown_word_message(std::string_view what, std::string_view word,
                                 const std::vector<std::string_view>& candidates) {
  std::string text = "unknown " + std::string(what) + " \"" + std::string(word) + "\"";
  if (const auto nearest = closest_word(word, candidates)) {
    return text + "; did you mean \"" + std::string(*nearest) + "\"?";
  }
  if (candidates.empty()) return text;
  return text + "; expected one of: " + join_words(candidates);
}

}  // namespace rodsort::scenarios
