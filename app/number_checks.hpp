#pragma once
// Checks of numeric options with short messages. CLI11's PositiveNumber and NonNegativeNumber
// state their range up to the largest double, a 309-digit number, when they refuse a value.

#include <CLI/CLI.hpp>
#include <string>

namespace rodsort::app {

/// A number above `floor` (or at least `floor` when `floor_allowed`); `what` names the bound.
inline CLI::Validator number_above(double floor, bool floor_allowed, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) return "expected a number, got " + text;
        if (value > floor || (floor_allowed && value == floor)) return {};
        return "expected " + what + ", got " + text;
      },
      floor_allowed ? "NONNEGATIVE" : "POSITIVE");
}

inline CLI::Validator positive_number() { return number_above(0.0, false, "a number > 0"); }
inline CLI::Validator non_negative_number() { return number_above(0.0, true, "a number >= 0"); }

}  // namespace rodsort::app
