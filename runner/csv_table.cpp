#include "runner/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "runner/atomic_file.hpp"

namespace rodsort::runner {
namespace {

std::vector<std::string> split_line(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  return std::nullopt;
}

std::vector<double> CsvTable::numbers(std::size_t column) const {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows) {
    const std::string& text = row.at(column);
    if (text.empty() || text == "nan" || text == "-nan") {
      values.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
      throw std::runtime_error("column " + header.at(column) + ": '" + text + "' is not a number");
    }
    values.push_back(value);
  }
  return values;
}

CsvTable read_csv(const std::filesystem::path& path) {
  const std::string text = read_file(path);
  CsvTable table;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // an incomplete last line
    ++line_number;
    std::vector<std::string> fields = split_line(std::string_view(text).substr(start, end - start));
    start = end + 1;
    if (line_number == 1) {
      table.header = std::move(fields);
      continue;
    }
    if (fields.size() != table.header.size()) {
      throw std::runtime_error(path.string() + ":" + std::to_string(line_number) + ": " +
                               std::to_string(fields.size()) + " fields, the header has " +
                               std::to_string(table.header.size()));
    }
    table.rows.push_back(std::move(fields));
  }
  if (line_number == 0) throw std::runtime_error(path.string() + ": no header line");
  return table;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    const std::string& field = fields[i];
    if (field.find_first_of(",\"\n") == std::string::npos) {
      line += field;
      continue;
    }
    line += '"';
    for (const char c : field) {
      if (c == '"') line += '"';
      line += c;
    }
    line += '"';
  }
  return line;
}

std::string csv_text(const CsvTable& table) {
  std::string text = csv_line(table.header) + "\n";
  for (const auto& row : table.rows) text += csv_line(row) + "\n";
  return text;
}

}  // namespace rodsort::runner
