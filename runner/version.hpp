#pragma once

#include <string>

namespace rodsort::runner {

/// rodsort's version, from the CMake project (recorded in run.json, printed by --version).
const char* version();

/// What identifies the build of rodsort this process runs: version, compiler, build type, Bullet's
/// version, and the fingerprint of the executable's bytes, so that two builds compare equal only
/// when they are the same program. A checkpoint records it: a run continues bit for bit only with
/// the build that wrote the checkpoint.
const std::string& build_identity();

}  // namespace rodsort::runner
