#pragma once
// What rodsort says about a scenario a user wrote: where (file:line:col, or the --set option that
// set the value), which key, what was found and what was expected. Diagnostics are values; the
// whole file is checked and every problem is reported at once.

#include <string>
#include <vector>

namespace rodsort::scenarios {

/// Where a value came from: a file position, or a command-line option (line 0).
struct SourceLocation {
  std::string source;  ///< file path as the user gave it, or e.g. "--set trap.angle=190"
  int line = 0;        ///< 1-based; 0 when the source has no lines
  int column = 0;      ///< 1-based

  /// "file:line:col", or just the source when it has no lines.
  std::string to_string() const;
};

enum class Severity { error, warning };

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLocation where;
  std::string key_path;  ///< e.g. "species[1].noise.kick_eps"; empty for file-level problems
  std::string message;   ///< says what was found and what was expected

  /// "fig2.yaml:14:7: trap.angle: must be in (0, 180) degrees, got 190"; warnings say "warning: ".
  std::string to_string() const;
};

/// Collects diagnostics while a scenario is read, checked and compiled.
class Diagnostics {
 public:
  void error(const SourceLocation& where, std::string key_path, std::string message);
  void warning(const SourceLocation& where, std::string key_path, std::string message);
  void add(Diagnostic diagnostic);

  bool has_errors() const;
  std::size_t error_count() const;
  const std::vector<Diagnostic>& all() const { return all_; }

 private:
  std::vector<Diagnostic> all_;
};

/// One diagnostic per line, in the order found, and a last line counting the errors when any.
/// Without `with_warnings`, the errors only: for a scenario read again after the run that
/// already said its warnings (render, analyze, a run continued to a longer duration).
std::string format_diagnostics(const std::vector<Diagnostic>& diagnostics,
                               bool with_warnings = true);

}  // namespace rodsort::scenarios
