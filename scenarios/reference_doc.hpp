#pragma once
// docs/scenario-reference.md is generated from the schemas, never written by hand: a test compares
// the committed file with this function's output and fails when they differ.

#include <string>

namespace rodsort::scenarios {

/// The whole of docs/scenario-reference.md.
std::string scenario_reference_markdown();

}  // namespace rodsort::scenarios
