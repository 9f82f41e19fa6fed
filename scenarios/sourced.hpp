#pragma once
// A value read from a scenario, with where it came from. Checks that run long after parsing (a trap
// too large for the cell, rods too thick for the gap) use it to point at the line that set it.

#include <string>

#include "scenarios/diagnostic.hpp"

namespace rodsort::scenarios {

template <class T>
struct Sourced {
  T value{};
  SourceLocation where;  ///< of the value; of its section when the value is a default
  std::string path;      ///< concrete key path, e.g. "species[1].count"
  bool given = false;    ///< written by the user (file, --set or sweep), not a default
};

}  // namespace rodsort::scenarios
