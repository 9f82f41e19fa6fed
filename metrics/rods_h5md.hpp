#pragma once
// rods.h5: the frames of rods.csv in HDF5, laid out as H5MD 1.1 (https://www.nongnu.org/h5md/),
// which h5py, MDAnalysis (with convert_units=False: it knows no millimetres) and any HDF5 tool
// open. Lengths in mm, velocities in mm/s, angular velocities in rad/s, times in s. Compressed
// (shuffle + deflate) and binary, it takes several times less disk than rods.csv and loads much
// faster.
//
//   /h5md                                 version 1.1, creator rodsort
//   /particles/rods/box                   dimension 3, boundary periodic periodic none
//   /particles/rods/box/edges/value       (F, 3, 3) the cell's edge vectors and the gap [mm]
//   /particles/rods/species               (N) int32, index into /parameters/species_names
//   /particles/rods/position/value        (F, N, 3) x, y wrapped into the cell, z [mm]
//   /particles/rods/image/value           (F, N, 3) int32: unwrapped = position + image * edges
//   /particles/rods/orientation/value     (F, N, 3) unit axis from the thick to the thin end
//   /particles/rods/velocity/value        (F, N, 3) of the centre of mass [mm/s]
//   /particles/rods/angular_velocity_z/value  (F, N) about z [rad/s]
//   each with step (F) int64 and time (F) float64 [s], shared by hard links
//   /parameters/species_names             (S) strings
//   /parameters/walls                     (W, 5) centre x, y, half length, half thickness [mm],
//                                          yaw [rad] of every wall (trap arms, the cell's wall)
//   /parameters/scenario                  scenario.resolved.yaml's text
//
// Floating-point values are stored in single precision (7 significant digits: 1e-5 mm on a 130 mm
// cell, far below any contact length of the model) or, with output.rods_h5md_precision: double,
// in double precision, exactly as the simulation has them.
//
// A run killed at any moment leaves a file that opens: frames are gathered in memory and written a
// chunk at a time, each write followed by a flush, so that between writes the file on disk is
// complete; the datasets' fill values (NaN, step -1) mark frames whose data never reached the disk
// if a write itself is cut short, and the reader drops those and says so.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/frame.hpp"
#include "engine/model.hpp"
#include "metrics/rod_frames.hpp"

namespace rodsort::metrics {

enum class H5mdPrecision { single, full };

/// What stays the same over a run.
struct H5mdLayout {
  std::vector<std::string> species_names;
  std::vector<int> rod_species;     ///< the species index of each rod
  double box_x = 0.0, box_y = 0.0;  ///< the periodic cell [mm]
  double box_z = 0.0;               ///< the gap between the plates at rest [mm]
  std::vector<engine::Wall> walls;
  std::string scenario_yaml;
  H5mdPrecision precision = H5mdPrecision::single;
  std::string creator_version;  ///< of rodsort, in /h5md/creator
};

/// Frames as the file holds them: values rounded to the file's precision, and the unwrapped
/// position rebuilt from the wrapped one and the image, as RodsH5mdReader gives them back.
class H5mdRounding {
 public:
  H5mdRounding(H5mdPrecision precision, double box_x, double box_y)
      : precision_(precision), box_x_(box_x), box_y_(box_y) {}
  engine::Frame stored(const engine::Frame& frame) const;
  double round(double value) const;
  /// The periodic image of an unwrapped coordinate given its wrapped one.
  static std::int32_t image(double unwrapped, double wrapped, double box);

 private:
  H5mdPrecision precision_;
  double box_x_, box_y_;
};

class RodsH5mdWriter {
 public:
  /// Creates the file (replacing one there). Throws std::runtime_error naming the file.
  RodsH5mdWriter(const std::filesystem::path& path, const H5mdLayout& layout);
  /// Opens an existing file to go on after its first `keep_frames` frames, dropping any after.
  RodsH5mdWriter(const std::filesystem::path& path, const H5mdLayout& layout,
                 std::uint64_t keep_frames);
  ~RodsH5mdWriter();
  RodsH5mdWriter(const RodsH5mdWriter&) = delete;
  RodsH5mdWriter& operator=(const RodsH5mdWriter&) = delete;

  /// Adds a frame; it reaches the file at the next commit, which happens by itself when a
  /// chunk's worth of frames has gathered.
  void write(const engine::Frame& frame, std::int64_t step);
  /// Writes the gathered frames and flushes the file to disk.
  void commit();
  /// Frames in the file and gathered, i.e. after commit() the frames on disk.
  std::uint64_t frames() const;
  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Reads rods.h5 frame by frame, a chunk of frames at a time.
class RodsH5mdReader : public RodFrameReader {
 public:
  /// species_names: the run's species in index order (the file's must match them); when empty,
  /// the file's are taken. Errors are reported by next() and error().
  explicit RodsH5mdReader(const std::filesystem::path& path,
                          std::vector<std::string> species_names = {});
  ~RodsH5mdReader() override;

  bool next(engine::Frame& frame) override;
  const std::string& error() const override;
  const std::string& warning() const override;
  const std::vector<std::string>& species() const override;
  /// Frames in the file; fewer can be read when the last ones are incomplete (see warning()).
  std::uint64_t frame_count() const;
  /// The next frame next() returns is frame `index` (0-based).
  void seek(std::uint64_t index);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rodsort::metrics
