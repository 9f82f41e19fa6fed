#pragma once
// The small CSV files a sweep reads and writes (metrics.csv, sweep.csv): a header line and rows of
// fields. Fields holding a comma or a quote are quoted as RFC 4180 says.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rodsort::runner {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< each as long as the header

  /// Index of a column, or nullopt.
  std::optional<std::size_t> column(std::string_view name) const;
  /// A column as numbers; "nan" and empty fields read as NaN. Throws std::runtime_error naming the
  /// column when a field is not a number.
  std::vector<double> numbers(std::size_t column) const;
};

/// Reads a CSV file. A last line without its newline (a run stopped while writing) is dropped.
/// Throws std::runtime_error naming the file and line when a row has the wrong number of fields.
CsvTable read_csv(const std::filesystem::path& path);

/// One CSV line, without its newline, quoting the fields that need it.
std::string csv_line(const std::vector<std::string>& fields);

/// The whole table as CSV text.
std::string csv_text(const CsvTable& table);

}  // namespace rodsort::runner
