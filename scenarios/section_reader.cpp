#include "scenarios/section_reader.hpp"

#include <algorithm>
#include <cassert>
#include <cctype>

#include "scenarios/key_check.hpp"
#include "scenarios/number_text.hpp"

namespace rodsort::scenarios {
namespace {

std::string with_unit(const std::string& text, std::string_view unit) {
  return unit.empty() ? text : text + " " + std::string(unit);
}

std::string keywords_text(const std::vector<std::string_view>& keywords) {
  std::string text;
  for (std::size_t i = 0; i < keywords.size(); ++i) {
    if (i > 0) text += i + 1 == keywords.size() ? " or " : ", ";
    text += keywords[i];
  }
  return text;
}

/// "a number in mm", "auto or a whole number".
std::string expected_number(const KeyInfo& row, bool whole) {
  std::string text = whole ? "a whole number" : "a number";
  if (!row.unit.empty()) text += " in " + std::string(row.unit);
  if (!row.keywords.empty()) text = keywords_text(row.keywords) + " or " + text;
  return text;
}

}  // namespace

bool is_plain_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
  });
}

SectionReader::SectionReader(const Schema& schema, const SourceNode* node, std::string pattern,
                             std::string path, SourceLocation where, Diagnostics& diagnostics)
    : schema_(schema),
      node_(node != nullptr && node->is_map() ? node : nullptr),
      pattern_(std::move(pattern)),
      path_(std::move(path)),
      where_(std::move(where)),
      diagnostics_(diagnostics),
      defaults_(std::make_shared<std::vector<std::unique_ptr<SourceNode>>>()) {}

const SourceNode* SectionReader::node(std::string_view key) const {
  if (node_ == nullptr) return nullptr;
  const SourceNode* value = node_->find(key);
  return value != nullptr && !value->is_null() ? value : nullptr;
}

bool SectionReader::has(std::string_view key) const { return node(key) != nullptr; }

std::string SectionReader::path_of(std::string_view key) const { return join_path(path_, key); }

SourceLocation SectionReader::location_of(std::string_view key) const {
  const SourceNode* value = node(key);
  return value ? value->where : where_;
}

std::vector<std::string> SectionReader::keys() const {
  std::vector<std::string> keys;
  if (node_ != nullptr) {
    for (const SourceNode::Entry& entry : node_->entries) keys.push_back(entry.key);
  }
  return keys;
}

SourceLocation SectionReader::key_location(std::string_view key) const {
  const SourceNode::Entry* entry = node_ ? node_->find_entry(key) : nullptr;
  return entry ? entry->key_where : where_;
}

SectionReader::Found SectionReader::find(std::string_view key) {
  // A key of a free map (materials) reads through the map's "*" row.
  const KeyInfo* row_pointer = schema_.find(join_path(pattern_, key));
  if (row_pointer == nullptr) row_pointer = &schema_.at(join_path(pattern_, "*"));
  const KeyInfo& row = *row_pointer;
  if (const SourceNode* value = node(key)) return {value, true, row};
  if (row.default_value.empty()) return {nullptr, false, row};
  Diagnostics ignored;
  auto parsed = parse_yaml(row.default_value, "default", ignored);
  assert(parsed && !ignored.has_errors() && "schema defaults are valid YAML");
  relocate(*parsed, where_);
  defaults_->push_back(std::make_unique<SourceNode>(std::move(*parsed)));
  return {defaults_->back().get(), false, row};
}

template <class T>
Sourced<T> SectionReader::start(std::string_view key, const Found& found) const {
  Sourced<T> out;
  out.where = found.node ? found.node->where : where_;
  out.path = path_of(key);
  out.given = found.given;
  return out;
}

std::optional<double> SectionReader::to_real(const SourceNode& node, const KeyInfo& row,
                                             const std::string& path, bool check_range) {
  std::optional<double> value;
  if (node.is_scalar() && !node.quoted) value = parse_real(node.scalar);
  if (!value) {
    diagnostics_.error(node.where, path,
                       "expected " + expected_number(row, false) + ", got " + node.describe());
    return std::nullopt;
  }
  if (check_range && !row.range.contains(*value)) {
    diagnostics_.error(
        node.where, path,
        "must be " + with_unit(row.range.describe(), row.unit) + ", got " + node.describe());
    return std::nullopt;
  }
  return value;
}

Sourced<double> SectionReader::real(std::string_view key) {
  const Found found = find(key);
  assert(found.node && "real() needs a value or a schema default");
  auto out = start<double>(key, found);
  if (const auto value = to_real(*found.node, found.row, out.path, true)) out.value = *value;
  return out;
}

std::optional<Sourced<double>> SectionReader::optional_real(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return real(key);
}

Sourced<double> SectionReader::required_real(std::string_view key, std::string_view context) {
  if (has(key)) return real(key);
  const Found found = find(key);
  auto out = start<double>(key, found);
  diagnostics_.error(where_, out.path,
                     "missing; " + std::string(context) + " it is required (" +
                         expected_number(found.row, false) + ")");
  return out;
}

Sourced<std::int64_t> SectionReader::integer(std::string_view key) {
  const Found found = find(key);
  assert(found.node && "integer() needs a value or a schema default");
  auto out = start<std::int64_t>(key, found);
  const SourceNode& node = *found.node;
  std::optional<std::int64_t> value;
  if (node.is_scalar() && !node.quoted) value = parse_integer(node.scalar);
  if (!value) {
    diagnostics_.error(node.where, out.path,
                       "expected " + expected_number(found.row, true) + ", got " + node.describe());
  } else if (!found.row.range.contains(static_cast<double>(*value))) {
    diagnostics_.error(node.where, out.path,
                       "must be " + with_unit(found.row.range.describe(), found.row.unit) +
                           ", got " + node.describe());
  } else {
    out.value = *value;
  }
  return out;
}

Sourced<NumberOrKeyword> SectionReader::number_or_keyword(std::string_view key) {
  const Found found = find(key);
  assert(found.node && "number_or_keyword() needs a value or a schema default");
  auto out = start<NumberOrKeyword>(key, found);
  const SourceNode& node = *found.node;
  if (node.is_scalar() && !node.quoted &&
      std::find(found.row.keywords.begin(), found.row.keywords.end(), node.scalar) !=
          found.row.keywords.end()) {
    out.value.keyword = node.scalar;
    return out;
  }
  if (found.row.type == ValueType::integer) {
    out.value.number = static_cast<double>(integer(key).value);
    return out;
  }
  if (const auto value = to_real(node, found.row, out.path, true)) out.value.number = *value;
  return out;
}

Sourced<std::string> SectionReader::text(std::string_view key) {
  const Found found = find(key);
  auto out = start<std::string>(key, found);
  if (!found.node) return out;
  const SourceNode& node = *found.node;
  if (!node.is_scalar() || !is_plain_name(node.scalar)) {
    diagnostics_.error(
        node.where, out.path,
        "expected a name of letters, digits, '.', '_' or '-', got " + node.describe());
    return out;
  }
  // A name becomes a directory name (255 bytes at most), with a sweep point's labels after it.
  constexpr std::size_t kMaxNameLength = 100;
  if (node.scalar.size() > kMaxNameLength) {
    diagnostics_.error(node.where, out.path,
                       "expected a name of at most " + std::to_string(kMaxNameLength) +
                           " characters (it names the run's directory), got one of " +
                           std::to_string(node.scalar.size()));
    return out;
  }
  out.value = node.scalar;
  return out;
}

Sourced<std::string> SectionReader::choice(std::string_view key) {
  const Found found = find(key);
  auto out = start<std::string>(key, found);
  if (!found.node) return out;
  const SourceNode& node = *found.node;
  const auto& choices = found.row.keywords;
  if (!node.is_scalar() ||
      std::find(choices.begin(), choices.end(), node.scalar) == choices.end()) {
    std::string message = "expected " + keywords_text(choices) + ", got " + node.describe();
    if (node.is_scalar()) {
      if (const auto nearest = closest_word(node.scalar, choices)) {
        message += "; did you mean \"" + std::string(*nearest) + "\"?";
      }
    }
    diagnostics_.error(node.where, out.path, message);
    return out;
  }
  out.value = node.scalar;
  return out;
}

Sourced<std::array<double, 2>> SectionReader::real_pair(std::string_view key) {
  const Found found = find(key);
  assert(found.node && "real_pair() needs a value or a schema default");
  auto out = start<std::array<double, 2>>(key, found);
  const SourceNode& node = *found.node;
  if (node.is_scalar()) {
    const auto value = to_real(node, found.row, out.path, true);
    out.value = {value.value_or(0.0), value.value_or(0.0)};
    return out;
  }
  if (!node.is_sequence() || node.items.size() != 2) {
    diagnostics_.error(node.where, out.path,
                       "expected [x, y] or one number" +
                           (found.row.unit.empty() ? "" : " in " + std::string(found.row.unit)) +
                           ", got " + node.describe());
    return out;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const auto value = to_real(node.items[i], found.row, out.path, true);
    out.value[i] = value.value_or(0.0);
  }
  return out;
}

std::optional<Sourced<std::array<double, 2>>> SectionReader::optional_real_pair(
    std::string_view key) {
  if (!has(key)) return std::nullopt;
  return real_pair(key);
}

Sourced<std::vector<double>> SectionReader::real_list(std::string_view key) {
  const Found found = find(key);
  assert(found.node && "real_list() needs a value or a schema default");
  auto out = start<std::vector<double>>(key, found);
  const SourceNode& node = *found.node;
  if (node.is_scalar()) {
    const auto value = to_real(node, found.row, out.path, true);
    if (value) out.value.push_back(*value);
    return out;
  }
  if (!node.is_sequence()) {
    diagnostics_.error(node.where, out.path, "expected a list of numbers, got " + node.describe());
    return out;
  }
  constexpr std::size_t kMaxListLength = 1000;  // snapshot times: each is a file of the world
  if (node.items.size() > kMaxListLength) {
    diagnostics_.error(node.where, out.path,
                       "expected at most " + std::to_string(kMaxListLength) + " values, got " +
                           std::to_string(node.items.size()));
    return out;
  }
  for (const SourceNode& item : node.items) {
    const auto value = to_real(item, found.row, out.path, true);
    if (value) out.value.push_back(*value);
  }
  return out;
}

std::optional<Sourced<std::vector<std::array<double, 3>>>> SectionReader::sphere_list(
    std::string_view key) {
  if (!has(key)) return std::nullopt;
  const Found found = find(key);
  auto out = start<std::vector<std::array<double, 3>>>(key, found);
  const SourceNode& node = *found.node;
  const std::string expected =
      "expected a list of spheres [axial position, radius] or [axial position, radius, lateral "
      "offset] in mm";
  if (!node.is_sequence() || node.items.empty()) {
    diagnostics_.error(node.where, out.path, expected + ", got " + node.describe());
    return out;
  }
  constexpr std::size_t kMaxSpheres = 200;  // as taper.spheres
  if (node.items.size() > kMaxSpheres) {
    diagnostics_.error(node.where, out.path,
                       "expected at most " + std::to_string(kMaxSpheres) + " spheres, got " +
                           std::to_string(node.items.size()));
    return out;
  }
  for (std::size_t i = 0; i < node.items.size(); ++i) {
    const SourceNode& item = node.items[i];
    const std::string item_path = out.path + "[" + std::to_string(i) + "]";
    if (!item.is_sequence() || item.items.size() < 2 || item.items.size() > 3) {
      diagnostics_.error(item.where, item_path, expected + ", got " + item.describe());
      continue;
    }
    const auto axial = to_real(item.items[0], found.row, item_path, false);
    const auto radius = to_real(item.items[1], found.row, item_path, false);
    const auto lateral =
        item.items.size() == 3 ? to_real(item.items[2], found.row, item_path, false) : 0.0;
    if (radius && *radius <= 0.0) {
      diagnostics_.error(item.items[1].where, item_path,
                         "a sphere's radius must be > 0 mm, got " + item.items[1].describe());
      continue;
    }
    if (axial && radius && lateral) out.value.push_back({*axial, *radius, *lateral});
  }
  return out;
}

SectionReader SectionReader::section(std::string_view key) {
  const Found found = find(key);
  SectionReader reader(schema_, found.node, std::string(found.row.path), path_of(key),
                       found.node ? found.node->where : where_, diagnostics_);
  reader.defaults_ = defaults_;
  return reader;
}

std::vector<SectionReader> SectionReader::list(std::string_view key) {
  const Found found = find(key);
  std::vector<SectionReader> items;
  if (!found.node || !found.node->is_sequence()) return items;
  for (std::size_t i = 0; i < found.node->items.size(); ++i) {
    const SourceNode& item = found.node->items[i];
    SectionReader reader(schema_, &item, std::string(found.row.path) + "[]",
                         path_of(key) + "[" + std::to_string(i) + "]", item.where, diagnostics_);
    reader.defaults_ = defaults_;
    items.push_back(std::move(reader));
  }
  return items;
}

}  // namespace rodsort::scenarios
