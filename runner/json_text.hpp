#pragma once
// The few JSON pieces run.json needs, written by hand: a quoted string and a number that reads
// back to the same double.

#include <string>
#include <string_view>

namespace rodsort::runner {

/// A JSON string literal, quotes included, with control characters escaped.
std::string json_quote(std::string_view text);
/// The shortest decimal text that reads back to exactly `value`; non-finite values become null.
std::string json_number(double value);

}  // namespace rodsort::runner
