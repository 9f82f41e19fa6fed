#pragma once
// A 64-bit fingerprint of bytes (FNV-1a): pins a State in the determinism tests and seals the
// files a run resumes from, so that a changed or damaged checkpoint or resolved scenario is
// refused rather than resumed. It detects accidents and edits, not a forger.

#include <cstdint>
#include <string_view>

namespace rodsort::engine {

inline std::uint64_t fingerprint(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace rodsort::engine
