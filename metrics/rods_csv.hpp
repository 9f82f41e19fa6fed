#pragma once
// rods.csv: one line per rod per output frame, the run's complete record of the rods' motion,
// from which every metric can be recomputed (`rodsort analyze`).
//
//   t,rod,species,x,y,xu,yu,z,ux,uy,uz,vx,vy,vz,wz
//
// t [s]; rod: index, 0..N-1 in every frame; species: its name; x, y: centre of mass wrapped into
// the cell [mm]; xu, yu: the same, never wrapped [mm]; z [mm]; ux, uy, uz: unit axis from the
// thick to the thin end; vx, vy, vz: velocity of the centre of mass [mm/s]; wz: angular velocity
// about z [rad/s] (the other two components are not kept, and read back as 0). Numbers are written
// with 9 significant digits. A frame is written with a single write of whole lines, so a run that
// stops half-way leaves whole lines behind; the reader drops an incomplete last frame and says so.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "engine/frame.hpp"
#include "metrics/rod_frames.hpp"

namespace rodsort::metrics {

inline constexpr const char* kRodsCsvHeader = "t,rod,species,x,y,xu,yu,z,ux,uy,uz,vx,vy,vz,wz";

class RodsCsvWriter {
 public:
  /// species_names[s] names species index s; names must not contain commas, quotes or newlines.
  RodsCsvWriter(std::ostream& out, std::vector<std::string> species_names);
  void write_header();
  /// Appends every rod of the frame, with one write to the stream.
  void write(const engine::Frame& frame);

 private:
  std::ostream& out_;
  std::vector<std::string> species_names_;
  std::string buffer_;
};

/// Reads rods.csv frame by frame, so that a long run's file need not fit in memory.
class RodsCsvReader : public RodFrameReader {
 public:
  /// file_name is only used in messages. species_names: the run's species in index order, a name
  /// not among them is an error; when empty, each new name gets the next index. header_line: the
  /// line of the file that the stream's first line (the header) stands for, so that a frame read
  /// back from the middle of a file, behind a copy of the header, is reported at its own line.
  RodsCsvReader(std::istream& in, std::string file_name,
                std::vector<std::string> species_names = {}, long header_line = 1);

  /// The next frame; false at the end of the file or at the first error (see error()).
  bool next(engine::Frame& frame) override;
  /// "file:line:col: what was found, what was expected", or empty.
  const std::string& error() const override { return error_; }
  /// Set when an incomplete last frame (a run stopped while writing) was dropped.
  const std::string& warning() const override { return warning_; }
  const std::vector<std::string>& species() const override { return species_names_; }

 private:
  struct Row {
    double time;
    long line;  ///< in the file, for messages
    int rod;
    int species;
    engine::RodFrame rod_frame;
  };
  enum class LineResult { kRow, kEnd, kError };
  LineResult read_row(Row& row);
  bool fail(long line, int column, const std::string& message);

  std::istream& in_;
  std::string file_name_;
  std::vector<std::string> species_names_;
  bool fixed_species_;
  long line_number_ = 0;
  bool header_read_ = false;
  bool has_pending_ = false;
  Row pending_{};
  std::vector<int> rod_species_;  ///< species of each rod in the first frame
  bool have_previous_time_ = false;
  double previous_time_ = 0.0;
  std::string error_;
  std::string warning_;
};

struct RodsCsv {
  std::vector<std::string> species;
  std::vector<engine::Frame> frames;
  std::string error;    ///< empty on success
  std::string warning;  ///< see RodsCsvReader::warning()
};

/// Reads a whole rods.csv; the error names the file when it cannot be opened.
RodsCsv read_rods_csv(const std::filesystem::path& path,
                      std::vector<std::string> species_names = {});

}  // namespace rodsort::metrics
