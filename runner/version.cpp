#include "runner/version.hpp"

#include <LinearMath/btScalar.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/fingerprint.hpp"
#include "runner/self_program.hpp"

namespace rodsort::runner {
namespace {

#if defined(__clang__)
constexpr const char* kCompiler = "clang " __clang_version__;
#elif defined(__GNUC__)
constexpr const char* kCompiler = "gcc " __VERSION__;
#else
constexpr const char* kCompiler = "an unknown compiler";
#endif

/// The fingerprint of the rodsort program's file as 16 hex digits (not of a loader that started
/// it); "unknown" where it cannot be read.
std::string executable_fingerprint() {
  std::ifstream in(program_file(), std::ios::binary);
  if (!in) return "unknown";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad() || bytes.empty()) return "unknown";
  char text[17];
  std::snprintf(text, sizeof text, "%016llx",
                static_cast<unsigned long long>(engine::fingerprint(bytes)));
  return text;
}

}  // namespace

const char* version() { return RODSORT_VERSION; }

const std::string& build_identity() {
  static const std::string identity =
      std::string("rodsort ") + RODSORT_VERSION + ", " + kCompiler + ", " + RODSORT_BUILD_TYPE +
      ", Bullet " + std::to_string(btGetVersion()) + ", executable " + executable_fingerprint();
  return identity;
}

}  // namespace rodsort::runner
