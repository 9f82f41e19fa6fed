// Every file in tests/scenarios/bad/ is a scenario that must be refused. Its comment lines
// `# expect: LINE:COL: TEXT` list the errors it must produce: each must be reported at that
// position with TEXT in its message, and no other error may be reported.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scenarios/number_text.hpp"
#include "scenarios/scenario.hpp"

namespace fs = std::filesystem;
using namespace rodsort::scenarios;

namespace {

struct Expectation {
  int line;
  int column;
  std::string text;
};

std::vector<Expectation> expectations_of(const fs::path& path) {
  std::vector<Expectation> out;
  std::ifstream in(path);
  const std::string marker = "# expect: ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(marker, 0) != 0) continue;
    const std::string rest = line.substr(marker.size());
    const std::size_t colon1 = rest.find(':');
    const std::size_t colon2 = rest.find(':', colon1 + 1);
    out.push_back({static_cast<int>(*parse_integer(rest.substr(0, colon1))),
                   static_cast<int>(*parse_integer(rest.substr(colon1 + 1, colon2 - colon1 - 1))),
                   rest.substr(colon2 + 2)});
  }
  return out;
}

}  // namespace

TEST_CASE("every bad scenario is refused with the messages it lists", "[bad]") {
  const fs::path folder = fs::path(RODSORT_SOURCE_DIR) / "tests/scenarios/bad";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 20);
  for (const fs::path& file : files) {
    CAPTURE(file.filename().string());
    const std::vector<Expectation> expected = expectations_of(file);
    REQUIRE_FALSE(expected.empty());
    const LoadResult result = load_scenario(file);
    CAPTURE(format_diagnostics(result.diagnostics));
    CHECK_FALSE(result.ok());
    std::size_t errors = 0;
    for (const Diagnostic& diagnostic : result.diagnostics) {
      if (diagnostic.severity == Severity::error) ++errors;
    }
    CHECK(errors == expected.size());
    for (const Expectation& expectation : expected) {
      CAPTURE(expectation.line, expectation.column, expectation.text);
      const std::string prefix = file.string() + ":" + std::to_string(expectation.line) + ":" +
                                 std::to_string(expectation.column) + ": ";
      const bool found = std::any_of(
          result.diagnostics.begin(), result.diagnostics.end(), [&](const Diagnostic& d) {
            const std::string text = d.to_string();
            return d.severity == Severity::error && text.rfind(prefix, 0) == 0 &&
                   text.find(expectation.text) != std::string::npos;
          });
      CHECK(found);
    }
  }
}
