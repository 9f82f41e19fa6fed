#include "runner/version.hpp"

namespace rodsort::runner {

const char* version() { return RODSORT_VERSION; }

}  // namespace rodsort::runner
