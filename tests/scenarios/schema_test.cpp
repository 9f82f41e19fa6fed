#include "scenarios/schema.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "metrics/sorting.hpp"
#include "metrics/trapping.hpp"
#include "scenarios/key_check.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/reference_doc.hpp"

namespace fs = std::filesystem;
using namespace rodsort::scenarios;

TEST_CASE("numbers are read whole or not at all", "[schema]") {
  CHECK(parse_real("1.0e-4") == 1.0e-4);
  CHECK(parse_real("+5") == 5.0);
  CHECK(parse_real("-0.5") == -0.5);
  CHECK_FALSE(parse_real("12abc"));
  CHECK_FALSE(parse_real("1.2.3"));
  CHECK_FALSE(parse_real(""));
  CHECK_FALSE(parse_real("nan"));
  CHECK_FALSE(parse_real("inf"));
  CHECK_FALSE(parse_real(" 5"));
  CHECK(parse_integer("319") == 319);
  CHECK_FALSE(parse_integer("3.0"));
  CHECK_FALSE(parse_integer("1e3"));
}

TEST_CASE("written numbers read back to the same double", "[schema]") {
  for (const double value : {0.1, 1.0 / 3.0, 86.85, 0.04348637468, 1e-4, 6.02e23, 200.0}) {
    CHECK(parse_real(format_real(value)) == value);
  }
  CHECK(format_real(200.0) == "200");
  CHECK(format_real(0.07) == "0.07");
  CHECK(format_real(1e-4) == "1e-4");
  CHECK(format_real(6.02e23) == "6.02e23");
  CHECK(format_real(1.5e-10) == "1.5e-10");
}

TEST_CASE("ranges describe themselves as the messages quote them", "[schema]") {
  const Range angle{0.0, 180.0, true, true};
  CHECK(angle.describe() == "in (0, 180)");
  CHECK_FALSE(angle.contains(180.0));
  CHECK(angle.contains(179.9));
  CHECK(Range{0.0, std::numeric_limits<double>::infinity(), true, false}.describe() == "> 0");
  CHECK(Range{0.0, 1.0, false, false}.describe() == "in [0, 1]");
}

TEST_CASE("misspellings find the nearest key", "[schema]") {
  CHECK(edit_distance("angel", "angle") == 1);
  CHECK(edit_distance("Angle", "angle") == 0);
  CHECK(edit_distance("kick_epsilon", "kick_eps") == 4);
  CHECK(closest_word("frequncy", {"frequency", "gamma", "gap"}) == "frequency");
  CHECK_FALSE(closest_word("colour", {"frequency", "gamma", "gap"}));
}

TEST_CASE("every row of the schemas is documented and its default is in range", "[schema]") {
  for (const Schema* schema : {&scenario_schema(), &sweep_schema()}) {
    for (const KeyInfo& row : schema->keys()) {
      CAPTURE(row.path);
      CHECK_FALSE(row.doc.empty());
      if (row.type == ValueType::real && !row.default_value.empty()) {
        const auto value = parse_real(row.default_value);
        if (value) CHECK(row.range.contains(*value));
      }
      const std::size_t dot = row.path.rfind('.');
      if (dot != std::string_view::npos) {
        const std::string_view parent = row.path.substr(0, dot);
        const std::string_view parent_row =
            parent.size() > 2 && parent.substr(parent.size() - 2) == "[]"
                ? parent.substr(0, parent.size() - 2)
                : parent;
        CHECK(schema->find(parent_row) != nullptr);
      }
    }
  }
}

TEST_CASE("docs/scenario-reference.md is generated from the schema", "[reference]") {
  const fs::path path = fs::path(RODSORT_SOURCE_DIR) / "docs/scenario-reference.md";
  const std::string generated = scenario_reference_markdown();
  if (std::getenv("RODSORT_UPDATE_REFERENCE") != nullptr) {
    std::ofstream(path, std::ios::binary) << generated;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream committed;
  committed << in.rdbuf();
  INFO(
      "docs/scenario-reference.md is stale; regenerate it with "
      "`cmake --build build --target scenario-reference`");
  CHECK(committed.str() == generated);
}

TEST_CASE("the metrics defaults are the metrics layer's", "[schema]") {
  CHECK(parse_real(scenario_schema().at("metrics.window").default_value) ==
        rodsort::metrics::kDefaultWindow);
  CHECK(parse_real(scenario_schema().at("metrics.stationary_threshold").default_value) ==
        rodsort::metrics::kDefaultStationarySpeed);
  CHECK(parse_real(scenario_schema().at("metrics.held_distance").default_value) ==
        rodsort::metrics::kDefaultHeldDistance);
  CHECK(parse_real(scenario_schema().at("metrics.held_lag").default_value) ==
        rodsort::metrics::kDefaultHeldLag);
}
