#include "metrics/rod_frames.hpp"

#include <fstream>
#include <stdexcept>

#include "metrics/rods_csv.hpp"
#include "metrics/rods_h5md.hpp"

namespace rodsort::metrics {
namespace {

/// A RodsCsvReader with the stream it reads.
class OwnedCsvReader : public RodFrameReader {
 public:
  OwnedCsvReader(const std::filesystem::path& path, std::vector<std::string> species_names)
      : in_(path), reader_(in_, path.string(), std::move(species_names)) {
    if (!in_) throw std::runtime_error(path.string() + ": cannot open for reading");
  }
  bool next(engine::Frame& frame) override { return reader_.next(frame); }
  const std::string& error() const override { return reader_.error(); }
  const std::string& warning() const override { return reader_.warning(); }
  const std::vector<std::string>& species() const override { return reader_.species(); }

 private:
  std::ifstream in_;
  RodsCsvReader reader_;
};

}  // namespace

std::filesystem::path rod_frames_file(const std::filesystem::path& run_directory) {
  for (const char* name : {kRodsCsvName, kRodsH5mdName}) {
    if (std::filesystem::exists(run_directory / name)) return run_directory / name;
  }
  return {};
}

std::unique_ptr<RodFrameReader> open_rod_frames(const std::filesystem::path& file,
                                                std::vector<std::string> species_names) {
  if (file.extension() == ".h5") {
    return std::make_unique<RodsH5mdReader>(file, std::move(species_names));
  }
  return std::make_unique<OwnedCsvReader>(file, std::move(species_names));
}

}  // namespace rodsort::metrics
