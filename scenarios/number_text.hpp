#pragma once
// Numbers as a user types them and as rodsort writes them back. Parsing is strict (LAMMPS rejects
// `12abc`, so do we): the whole text must be the number. Writing uses the shortest text that reads
// back to the same double, so a resolved scenario reproduces its Model bit for bit.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rodsort::scenarios {

/// A finite decimal number, the whole of `text` ("12abc", "", "nan", "inf" are rejected).
std::optional<double> parse_real(std::string_view text);
/// A whole number in decimal, the whole of `text` ("3.0" and "1e3" are rejected).
std::optional<std::int64_t> parse_integer(std::string_view text);
/// Shortest text that parse_real reads back to exactly `value`.
std::string format_real(double value);

}  // namespace rodsort::scenarios
