#pragma once
// `rodsort convert RUN_DIR`: writes rods.h5 from a finished run's rods.csv, so that runs made
// before rods.h5 existed (or with output.rods_format: csv) can be kept in a fraction of the disk
// (docs/performance.md, section 8). rods.csv is left in place: delete it once rods.h5 is checked.

#include <filesystem>
#include <iosfwd>

namespace rodsort::runner {

struct ConvertRequest {
  std::filesystem::path run_directory;
  bool double_precision = false;  ///< rods.h5 in double precision instead of single
};

int convert_run(const ConvertRequest& request, std::ostream& err);

}  // namespace rodsort::runner
