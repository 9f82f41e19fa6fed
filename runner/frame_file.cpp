#include "runner/frame_file.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "metrics/rods_csv.hpp"
#include "metrics/rods_h5md.hpp"
#include "runner/append_file.hpp"
#include "runner/atomic_file.hpp"
#include "runner/run_directory.hpp"
#include "runner/version.hpp"

namespace rodsort::runner {
namespace {

/// The time of the first line of a rods.csv chunk (its first field).
double leading_time(std::string_view line) {
  double time = 0.0;
  std::from_chars(line.data(), line.data() + line.size(), time);
  return time;
}

/// rods.csv: text, appended a frame at a time with a single write; positions are byte offsets.
class CsvFrameFile : public FrameFile {
 public:
  CsvFrameFile(const RunPlan& plan, const std::filesystem::path& directory)
      : species_names_(plan.metrics.species_names), path_(directory / kRodsCsvFile) {}

  void start() override {
    file_ = std::make_unique<AppendFile>(path_);
    file_->append(std::string(metrics::kRodsCsvHeader) + "\n");
  }

  void resume(const Checkpoint& checkpoint, std::uint64_t replay_from,
              const Visit& visit) override {
    file_ = std::make_unique<AppendFile>(path_);
    const auto recorded = checkpoint.file_bytes.find(kRodsCsvFile);
    if (recorded == checkpoint.file_bytes.end()) {
      throw std::runtime_error("the checkpoint in " + path_.parent_path().string() +
                               " records no size for " + kRodsCsvFile);
    }
    file_->truncate(recorded->second);
    if (visit) replay(replay_from, visit);
  }

  engine::Frame write(const engine::Frame& frame, std::int64_t /*step*/) override {
    text_.str("");
    metrics::RodsCsvWriter writer(text_, species_names_);
    writer.write(frame);
    const std::string text = text_.str();
    file_->append(text);
    return read_back(text);
  }

  std::uint64_t position() const override { return file_->size(); }

  void record(Checkpoint& checkpoint) override {
    file_->sync();
    checkpoint.file_bytes[kRodsCsvFile] = file_->size();
  }

  void sync() override { file_->sync(); }
  const char* name() const override { return kRodsCsvFile; }

 private:
  /// A frame as rods.csv holds it. `first_line`: the line of rods.csv where it starts, for
  /// messages (0: not known).
  engine::Frame read_back(const std::string& frame_text, long first_line = 0) const {
    std::istringstream in(std::string(metrics::kRodsCsvHeader) + "\n" + frame_text);
    metrics::RodsCsvReader reader(in, kRodsCsvFile, species_names_,
                                  first_line > 0 ? first_line - 1 : 1);
    engine::Frame stored;
    if (!reader.next(stored)) {
      throw std::runtime_error("cannot read back a frame of rods.csv: " + reader.error());
    }
    return stored;
  }

  /// Visits the frames of rods.csv from byte `offset` to its end.
  void replay(std::uint64_t offset, const Visit& visit) const {
    const std::string text = read_file(path_);
    if (offset > text.size()) {
      throw std::runtime_error("the checkpoint points past the end of " + path_.string());
    }
    std::size_t frame_start = offset;
    double frame_time = 0.0;
    // Line numbers of the file, for messages about a damaged frame.
    long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + offset, '\n'));
    long frame_line = line;
    const auto visit_frame = [&](std::size_t end) {
      visit(read_back(text.substr(frame_start, end - frame_start), frame_line), frame_start);
    };
    for (std::size_t line_start = offset; line_start < text.size(); ++line) {
      std::size_t line_end = text.find('\n', line_start);
      line_end = line_end == std::string::npos ? text.size() : line_end + 1;
      const double time = leading_time(std::string_view(text).substr(line_start));
      if (line_start == frame_start) {
        frame_time = time;
      } else if (time != frame_time) {
        visit_frame(line_start);
        frame_start = line_start;
        frame_line = line;
        frame_time = time;
      }
      line_start = line_end;
    }
    if (frame_start < text.size()) visit_frame(text.size());
  }

  std::vector<std::string> species_names_;
  std::filesystem::path path_;
  std::unique_ptr<AppendFile> file_;
  std::ostringstream text_;
};

/// rods.h5 (metrics/rods_h5md.hpp); positions are frame indices.
class H5mdFrameFile : public FrameFile {
 public:
  H5mdFrameFile(const RunPlan& plan, const std::filesystem::path& directory)
      : species_names_(plan.metrics.species_names),
        path_(directory / kRodsH5mdFile),
        layout_(h5md_layout(plan)),
        rounding_(plan.h5md_precision, plan.model.box_x, plan.model.box_y) {}

  void start() override { writer_ = std::make_unique<metrics::RodsH5mdWriter>(path_, layout_); }

  void resume(const Checkpoint& checkpoint, std::uint64_t replay_from,
              const Visit& visit) override {
    const auto recorded = checkpoint.file_frames.find(kRodsH5mdFile);
    if (recorded == checkpoint.file_frames.end()) {
      throw std::runtime_error("the checkpoint in " + path_.parent_path().string() +
                               " records no frame count for " + kRodsH5mdFile);
    }
    const std::uint64_t frames = recorded->second;
    // Read before the writer opens the file: HDF5 opens a file once per process.
    if (visit) replay(replay_from, frames, visit);
    writer_ = std::make_unique<metrics::RodsH5mdWriter>(path_, layout_, frames);
  }

  engine::Frame write(const engine::Frame& frame, std::int64_t step) override {
    writer_->write(frame, step);
    return rounding_.stored(frame);
  }

  std::uint64_t position() const override { return writer_->frames(); }

  void record(Checkpoint& checkpoint) override {
    writer_->commit();
    checkpoint.file_frames[kRodsH5mdFile] = writer_->frames();
  }

  void sync() override { writer_->commit(); }
  const char* name() const override { return kRodsH5mdFile; }

 private:
  /// Visits frames [first, end) of rods.h5.
  void replay(std::uint64_t first, std::uint64_t end, const Visit& visit) const {
    metrics::RodsH5mdReader reader(path_, species_names_);
    if (!reader.error().empty()) {
      throw std::runtime_error("cannot read back rods.h5: " + reader.error());
    }
    if (first > end || end > reader.frame_count()) {
      throw std::runtime_error("the checkpoint points past the end of " + path_.string());
    }
    reader.seek(first);
    engine::Frame stored;
    for (std::uint64_t index = first; index < end; ++index) {
      if (!reader.next(stored)) {
        throw std::runtime_error("cannot read back rods.h5: " +
                                 (reader.error().empty() ? reader.warning() : reader.error()));
      }
      visit(stored, index);
    }
  }

  std::vector<std::string> species_names_;
  std::filesystem::path path_;
  metrics::H5mdLayout layout_;
  metrics::H5mdRounding rounding_;
  std::unique_ptr<metrics::RodsH5mdWriter> writer_;
};

}  // namespace

metrics::H5mdLayout h5md_layout(const RunPlan& plan) {
  metrics::H5mdLayout layout;
  layout.species_names = plan.metrics.species_names;
  for (const engine::RodInit& rod : plan.model.rods) layout.rod_species.push_back(rod.species);
  layout.box_x = plan.model.box_x;
  layout.box_y = plan.model.box_y;
  layout.box_z = plan.model.drive.gap;
  layout.walls = plan.model.walls;
  layout.scenario_yaml = plan.resolved_yaml;
  layout.precision = plan.h5md_precision;
  layout.creator_version = version();
  return layout;
}

std::vector<std::unique_ptr<FrameFile>> make_frame_files(const RunPlan& plan,
                                                         const std::filesystem::path& directory) {
  std::vector<std::unique_ptr<FrameFile>> files;
  if (plan.rods_csv) files.push_back(std::make_unique<CsvFrameFile>(plan, directory));
  if (plan.rods_h5md) files.push_back(std::make_unique<H5mdFrameFile>(plan, directory));
  return files;
}

}  // namespace rodsort::runner
