#pragma once

namespace rodsort::runner {

/// rodsort's version, from the CMake project (recorded in run.json, printed by --version).
const char* version();

}  // namespace rodsort::runner
