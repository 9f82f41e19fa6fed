#include "scenarios/diagnostic.hpp"

#include <algorithm>

namespace rodsort::scenarios {

std::string SourceLocation::to_string() const {
  if (line <= 0) return source;
  return source + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string Diagnostic::to_string() const {
  std::string text = where.to_string() + ": ";
  if (severity == Severity::warning) text += "warning: ";
  if (!key_path.empty()) text += key_path + ": ";
  return text + message;
}

void Diagnostics::error(const SourceLocation& where, std::string key_path, std::string message) {
  all_.push_back({Severity::error, where, std::move(key_path), std::move(message)});
}

void Diagnostics::warning(const SourceLocation& where, std::string key_path, std::string message) {
  all_.push_back({Severity::warning, where, std::move(key_path), std::move(message)});
}

void Diagnostics::add(Diagnostic diagnostic) { all_.push_back(std::move(diagnostic)); }

bool Diagnostics::has_errors() const { return error_count() > 0; }

std::size_t Diagnostics::error_count() const {
  return static_cast<std::size_t>(std::count_if(
      all_.begin(), all_.end(), [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics, bool with_warnings) {
  std::string text;
  std::size_t errors = 0;
  for (const Diagnostic& diagnostic : diagnostics) {
    if (!with_warnings && diagnostic.severity == Severity::warning) continue;
    text += diagnostic.to_string() + "\n";
    if (diagnostic.severity == Severity::error) ++errors;
  }
  if (errors > 0) {
    text += std::to_string(errors) + (errors == 1 ? " error\n" : " errors\n");
  }
  return text;
}

}  // namespace rodsort::scenarios
