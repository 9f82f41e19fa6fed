#include "metrics/rods_h5md.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace rodsort::metrics {
namespace {

constexpr const char* kRods = "/particles/rods";
/// Frames per chunk at most, and bytes per chunk of the largest dataset at most.
constexpr std::uint64_t kMaxChunkFrames = 64;
constexpr std::uint64_t kMaxChunkBytes = 1 << 20;
constexpr int kDeflateLevel = 4;
constexpr std::int64_t kStepFill = -1;
constexpr std::int32_t kImageFill = std::numeric_limits<std::int32_t>::min();
constexpr double kValueFill = std::numeric_limits<double>::quiet_NaN();

/// HDF5 prints a stack of every failure to stderr unless told not to; rodsort reports failures
/// itself, naming the file.
void silence_hdf5() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

/// An HDF5 identifier closed by its own close function.
class Id {
 public:
  Id() = default;
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Id(Id&& other) noexcept { *this = std::move(other); }
  Id& operator=(Id&& other) noexcept {
    reset();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    close_ = other.close_;
    return *this;
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  ~Id() { reset(); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  void reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

/// Throws naming the file and what failed when an HDF5 call returned a failure.
hid_t checked(hid_t result, const std::string& file, const std::string& what) {
  if (result < 0) throw std::runtime_error(file + ": cannot " + what + " (HDF5)");
  return result;
}

Id group_id(hid_t id) { return Id(id, H5Gclose); }
Id dataset_id(hid_t id) { return Id(id, H5Dclose); }
Id space_id(hid_t id) { return Id(id, H5Sclose); }
Id type_id(hid_t id) { return Id(id, H5Tclose); }
Id plist_id(hid_t id) { return Id(id, H5Pclose); }
Id attribute_id(hid_t id) { return Id(id, H5Aclose); }

Id string_type() {
  Id type = type_id(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

/// A time-dependent element of /particles/rods: its name and the values per rod in a frame.
struct Element {
  const char* name;
  int components;  ///< 3 for a vector, 1 for a scalar
  bool integer;    ///< int32 (the image) rather than floating point
};
constexpr std::array kElements = {
    Element{"position", 3, false},           Element{"image", 3, true},
    Element{"orientation", 3, false},        Element{"velocity", 3, false},
    Element{"angular_velocity_z", 1, false},
};
constexpr std::size_t kImage = 1;

/// The values of one frame's rods for every element, in kElements' order (the image as numbers),
/// rounded as the file keeps them.
void frame_values(const engine::Frame& frame, const H5mdRounding& rounding, double box_x,
                  double box_y, std::array<std::vector<double>, kElements.size()>& out) {
  for (auto& values : out) values.clear();
  for (const engine::RodFrame& rod : frame.rods) {
    out[0].insert(out[0].end(), {rod.position.x(), rod.position.y(), rod.z});
    out[1].insert(
        out[1].end(),
        {static_cast<double>(H5mdRounding::image(rod.unwrapped.x(), rod.position.x(), box_x)),
         static_cast<double>(H5mdRounding::image(rod.unwrapped.y(), rod.position.y(), box_y)),
         0.0});
    out[2].insert(out[2].end(), {rod.axis.x(), rod.axis.y(), rod.axis.z()});
    out[3].insert(out[3].end(), {rod.velocity.x(), rod.velocity.y(), rod.velocity.z()});
    out[4].push_back(rod.angular_velocity.z());
  }
  // Rounded in a loop of its own: GCC 12.2 at -O2 vectorizes a conditional narrowing written
  // inside the braced lists above into code that leaves one value of each pair unrounded.
  for (std::size_t e = 0; e < kElements.size(); ++e) {
    if (kElements[e].integer) continue;
    for (double& value : out[e]) value = rounding.round(value);
  }
}

/// The frame that `values` (one frame of every element, as frame_values writes them) stand for.
void frame_from_values(const std::array<const double*, kElements.size()>& values,
                       const std::vector<int>& rod_species, double box_x, double box_y,
                       engine::Frame& frame) {
  frame.rods.resize(rod_species.size());
  for (std::size_t i = 0; i < rod_species.size(); ++i) {
    engine::RodFrame& rod = frame.rods[i];
    const double* p = values[0] + 3 * i;
    const double* image = values[1] + 3 * i;
    const double* axis = values[2] + 3 * i;
    const double* v = values[3] + 3 * i;
    rod.species = rod_species[i];
    rod.position = {p[0], p[1]};
    rod.unwrapped = {p[0] + image[0] * box_x, p[1] + image[1] * box_y};
    rod.z = p[2];
    rod.axis = {axis[0], axis[1], axis[2]};
    rod.velocity = {v[0], v[1], v[2]};
    rod.angular_velocity = {0.0, 0.0, values[4][i]};
  }
}

void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  const Id type = string_type();
  const Id space = space_id(H5Screate(H5S_SCALAR));
  const Id attribute =
      attribute_id(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  const char* text = value.c_str();
  H5Awrite(attribute.get(), type.get(), &text);
}

void write_strings_attribute(hid_t object, const char* name,
                             const std::vector<std::string>& values) {
  const Id type = string_type();
  const hsize_t size = values.size();
  const Id space = space_id(H5Screate_simple(1, &size, nullptr));
  const Id attribute =
      attribute_id(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  std::vector<const char*> texts;
  for (const std::string& value : values) texts.push_back(value.c_str());
  H5Awrite(attribute.get(), type.get(), texts.data());
}

void write_int_attribute(hid_t object, const char* name, const std::vector<int>& values) {
  const hsize_t size = values.size();
  const Id space =
      space_id(size == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &size, nullptr));
  const Id attribute =
      attribute_id(H5Acreate2(object, name, H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(attribute.get(), H5T_NATIVE_INT, values.data());
}

/// A fixed dataset (not growing, not compressed) of doubles or ints.
void write_fixed(hid_t location, const char* name, hid_t file_type, hid_t memory_type,
                 const std::vector<hsize_t>& dims, const void* data, const std::string& file) {
  const Id space = space_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  const Id dataset = dataset_id(checked(
      H5Dcreate2(location, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      file, std::string("create ") + name));
  if (!dims.empty() && dims[0] == 0) return;
  checked(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), file,
          std::string("write ") + name);
}

void write_strings(hid_t location, const char* name, const std::vector<std::string>& values,
                   const std::string& file) {
  const Id type = string_type();
  std::vector<const char*> texts;
  for (const std::string& value : values) texts.push_back(value.c_str());
  write_fixed(location, name, type.get(), type.get(), {values.size()}, texts.data(), file);
}

std::vector<std::string> read_strings(hid_t dataset, const std::string& file) {
  const Id space = space_id(H5Dget_space(dataset));
  if (H5Sget_simple_extent_ndims(space.get()) != 1) {
    throw std::runtime_error(file + ": /parameters/species_names is not a list of names");
  }
  hsize_t size = 0;
  H5Sget_simple_extent_dims(space.get(), &size, nullptr);
  const Id type = string_type();
  std::vector<char*> texts(size, nullptr);
  if (size > 0) {
    checked(H5Dread(dataset, type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()), file,
            "read /parameters/species_names");
  }
  std::vector<std::string> names;
  for (char* text : texts) names.emplace_back(text != nullptr ? text : "");
  if (size > 0) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, texts.data());
  return names;
}

/// Creation properties of a growing dataset: chunks of `chunk` (frames first), shuffle and
/// deflate, `fill` for values never written, and no modification times (same run, same file).
Id growing_properties(const std::vector<hsize_t>& chunk, hid_t type, const void* fill) {
  Id properties = plist_id(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data());
  H5Pset_shuffle(properties.get());
  H5Pset_deflate(properties.get(), kDeflateLevel);
  H5Pset_fill_value(properties.get(), type, fill);
  H5Pset_obj_track_times(properties.get(), false);
  return properties;
}

}  // namespace

double H5mdRounding::round(double value) const {
  return precision_ == H5mdPrecision::single ? static_cast<double>(static_cast<float>(value))
                                             : value;
}

std::int32_t H5mdRounding::image(double unwrapped, double wrapped, double box) {
  return static_cast<std::int32_t>(std::lround((unwrapped - wrapped) / box));
}

engine::Frame H5mdRounding::stored(const engine::Frame& frame) const {
  std::array<std::vector<double>, kElements.size()> values;
  frame_values(frame, *this, box_x_, box_y_, values);
  std::vector<int> species;
  for (const engine::RodFrame& rod : frame.rods) species.push_back(rod.species);
  engine::Frame result;
  result.time = frame.time;
  frame_from_values(
      {values[0].data(), values[1].data(), values[2].data(), values[3].data(), values[4].data()},
      species, box_x_, box_y_, result);
  return result;
}

// ---------------------------------------------------------------------------------------------
// Writer

struct RodsH5mdWriter::Impl {
  std::filesystem::path path;
  std::string name;  ///< for messages
  H5mdLayout layout;
  H5mdRounding rounding;
  Id file;
  std::array<Id, kElements.size()> values;  ///< the value datasets
  Id steps, times, edges;
  std::uint64_t chunk_frames = 1;
  std::uint64_t committed = 0;
  std::vector<std::int64_t> pending_steps;
  std::vector<double> pending_times;
  std::array<std::vector<double>, kElements.size()> pending;  ///< gathered frames' values
  std::array<std::vector<double>, kElements.size()> scratch;

  explicit Impl(const std::filesystem::path& file_path, const H5mdLayout& file_layout)
      : path(file_path),
        name(file_path.string()),
        layout(file_layout),
        rounding(file_layout.precision, file_layout.box_x, file_layout.box_y) {
    silence_hdf5();
    const std::uint64_t value_bytes = layout.precision == H5mdPrecision::single ? 4 : 8;
    const std::uint64_t frame_bytes =
        std::max<std::uint64_t>(1, 3 * value_bytes * layout.rod_species.size());
    chunk_frames = std::clamp<std::uint64_t>(kMaxChunkBytes / frame_bytes, 1, kMaxChunkFrames);
  }

  hsize_t rods() const { return layout.rod_species.size(); }

  hid_t float_type() const {
    return layout.precision == H5mdPrecision::single ? H5T_IEEE_F32LE : H5T_IEEE_F64LE;
  }

  /// Access without HDF5's lock on the file, so that a run's rods.h5 can be read while the run
  /// goes on: between commits the file on disk is complete.
  static Id unlocked_access() {
    Id access = plist_id(H5Pcreate(H5P_FILE_ACCESS));
    H5Pset_file_locking(access.get(), false, true);
    return access;
  }

  void create() {
    const Id access = unlocked_access();
    file = Id(checked(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), name,
                      "create the file"),
              H5Fclose);
    Id link_properties = plist_id(H5Pcreate(H5P_LINK_CREATE));
    H5Pset_create_intermediate_group(link_properties.get(), 1);
    Id group_properties = plist_id(H5Pcreate(H5P_GROUP_CREATE));
    H5Pset_obj_track_times(group_properties.get(), false);
    const auto make_group = [&](const char* group_name) {
      return group_id(checked(H5Gcreate2(file.get(), group_name, link_properties.get(),
                                         group_properties.get(), H5P_DEFAULT),
                              name, std::string("create ") + group_name));
    };

    {
      const Id h5md = make_group("/h5md");
      write_int_attribute(h5md.get(), "version", {1, 1});
      const Id author = make_group("/h5md/author");
      const char* user = std::getenv("USER");
      write_string_attribute(author.get(), "name", user != nullptr ? user : "unknown");
      const Id creator = make_group("/h5md/creator");
      write_string_attribute(creator.get(), "name", "rodsort");
      write_string_attribute(creator.get(), "version", layout.creator_version.c_str());
    }
    const Id box = make_group("/particles/rods/box");
    write_int_attribute(box.get(), "dimension", {3});
    write_strings_attribute(box.get(), "boundary", {"periodic", "periodic", "none"});

    const Id particles = group_id(H5Gopen2(file.get(), kRods, H5P_DEFAULT));
    write_fixed(particles.get(), "species", H5T_STD_I32LE, H5T_NATIVE_INT, {rods()},
                layout.rod_species.data(), name);
    const std::uint64_t chunk = chunk_frames;
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      const Element& element = kElements[e];
      const std::string group_name = std::string(kRods) + "/" + element.name;
      const Id group = make_group(group_name.c_str());
      std::vector<hsize_t> dims = {0, rods()};
      std::vector<hsize_t> max_dims = {H5S_UNLIMITED, rods()};
      std::vector<hsize_t> chunk_dims = {chunk, std::max<hsize_t>(1, rods())};
      if (element.components > 1) {
        dims.push_back(3);
        max_dims.push_back(3);
        chunk_dims.push_back(3);
      }
      const Id space =
          space_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()));
      const hid_t type = element.integer ? H5T_STD_I32LE : float_type();
      const Id properties = element.integer
                                ? growing_properties(chunk_dims, H5T_NATIVE_INT32, &kImageFill)
                                : growing_properties(chunk_dims, H5T_NATIVE_DOUBLE, &kValueFill);
      values[e] = dataset_id(checked(H5Dcreate2(group.get(), "value", type, space.get(),
                                                H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                                     name, group_name + "/value: create"));
      if (e == 0) {
        const hsize_t zero = 0, unlimited = H5S_UNLIMITED;
        const Id line = space_id(H5Screate_simple(1, &zero, &unlimited));
        const std::vector<hsize_t> line_chunk = {chunk};
        const Id step_properties = growing_properties(line_chunk, H5T_NATIVE_INT64, &kStepFill);
        steps = dataset_id(checked(H5Dcreate2(group.get(), "step", H5T_STD_I64LE, line.get(),
                                              H5P_DEFAULT, step_properties.get(), H5P_DEFAULT),
                                   name, "create step"));
        const Id time_properties = growing_properties(line_chunk, H5T_NATIVE_DOUBLE, &kValueFill);
        times = dataset_id(checked(H5Dcreate2(group.get(), "time", H5T_IEEE_F64LE, line.get(),
                                              H5P_DEFAULT, time_properties.get(), H5P_DEFAULT),
                                   name, "create time"));
      } else {
        const std::string position = std::string(kRods) + "/position/";
        for (const char* shared : {"step", "time"}) {
          checked(H5Lcreate_hard(file.get(), (position + shared).c_str(), group.get(), shared,
                                 H5P_DEFAULT, H5P_DEFAULT),
                  name, std::string("link ") + shared);
        }
      }
    }
    // The box's edges as a time series of matrices, rows the edge vectors: H5MD allows a fixed
    // vector for a box that does not change, but MDAnalysis (2.4) reads only this form.
    {
      const Id group = make_group((std::string(kRods) + "/box/edges").c_str());
      const std::array<hsize_t, 3> dims = {0, 3, 3};
      const std::array<hsize_t, 3> max_dims = {H5S_UNLIMITED, 3, 3};
      const Id space = space_id(H5Screate_simple(3, dims.data(), max_dims.data()));
      const Id properties = growing_properties({chunk, 3, 3}, H5T_NATIVE_DOUBLE, &kValueFill);
      edges = dataset_id(checked(H5Dcreate2(group.get(), "value", H5T_IEEE_F64LE, space.get(),
                                            H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                                 name, "create box/edges"));
      const std::string position = std::string(kRods) + "/position/";
      for (const char* shared : {"step", "time"}) {
        checked(H5Lcreate_hard(file.get(), (position + shared).c_str(), group.get(), shared,
                               H5P_DEFAULT, H5P_DEFAULT),
                name, std::string("link ") + shared);
      }
    }
    // Lengths in mm and speeds in mm/s are not among the units MDAnalysis knows, and it refuses a
    // file with a unit it does not know: only the time's unit is written (docs/cli.md gives all).
    write_string_attribute(times.get(), "unit", "s");

    const Id parameters = make_group("/parameters");
    write_strings(parameters.get(), "species_names", layout.species_names, name);
    std::vector<double> walls;
    for (const engine::Wall& wall : layout.walls) {
      walls.insert(walls.end(),
                   {wall.center_x, wall.center_y, wall.half_length, wall.half_thickness, wall.yaw});
    }
    write_fixed(parameters.get(), "walls", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                {layout.walls.size(), 5}, walls.data(), name);
    {
      const Id walls_set = dataset_id(H5Dopen2(parameters.get(), "walls", H5P_DEFAULT));
      write_strings_attribute(walls_set.get(), "columns",
                              {"center_x", "center_y", "half_length", "half_thickness", "yaw"});
    }
    write_strings(parameters.get(), "scenario", {layout.scenario_yaml}, name);
    flush();
  }

  void open(std::uint64_t keep_frames) {
    const Id access = unlocked_access();
    file = Id(checked(H5Fopen(name.c_str(), H5F_ACC_RDWR, access.get()), name,
                      "open the file to continue it"),
              H5Fclose);
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      const std::string dataset = std::string(kRods) + "/" + kElements[e].name + "/value";
      values[e] = dataset_id(
          checked(H5Dopen2(file.get(), dataset.c_str(), H5P_DEFAULT), name, "open " + dataset));
    }
    const std::string position = std::string(kRods) + "/position/";
    steps = dataset_id(
        checked(H5Dopen2(file.get(), (position + "step").c_str(), H5P_DEFAULT), name, "open step"));
    times = dataset_id(
        checked(H5Dopen2(file.get(), (position + "time").c_str(), H5P_DEFAULT), name, "open time"));
    const std::string box_edges = std::string(kRods) + "/box/edges/value";
    edges = dataset_id(
        checked(H5Dopen2(file.get(), box_edges.c_str(), H5P_DEFAULT), name, "open box/edges"));
    {
      const Id properties = plist_id(H5Dget_create_plist(steps.get()));
      hsize_t chunk = 1;
      H5Pget_chunk(properties.get(), 1, &chunk);
      chunk_frames = chunk;
    }
    for (hid_t dataset : all_datasets()) {
      const Id space = space_id(H5Dget_space(dataset));
      std::array<hsize_t, 3> dims{};
      const int rank = H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
      if (rank < 1 || dims[0] < keep_frames) {
        throw std::runtime_error(name + " holds fewer frames than the checkpoint counts (" +
                                 std::to_string(keep_frames) +
                                 "): it was changed or damaged after the checkpoint was written");
      }
      const bool per_rod =
          dataset != steps.get() && dataset != times.get() && dataset != edges.get();
      if (per_rod && dims[1] != rods()) {
        throw std::runtime_error(name + " holds " + std::to_string(dims[1]) + " rods, the run " +
                                 std::to_string(rods()));
      }
      dims[0] = keep_frames;
      checked(H5Dset_extent(dataset, dims.data()), name, "cut back the frames");
    }
    committed = keep_frames;
    flush();
  }

  std::vector<hid_t> all_datasets() const {
    std::vector<hid_t> all = {steps.get(), times.get(), edges.get()};
    for (const Id& dataset : values) all.push_back(dataset.get());
    return all;
  }

  void add(const engine::Frame& frame, std::int64_t step) {
    frame_values(frame, rounding, layout.box_x, layout.box_y, scratch);
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      pending[e].insert(pending[e].end(), scratch[e].begin(), scratch[e].end());
    }
    pending_steps.push_back(step);
    pending_times.push_back(frame.time);
    if ((committed + pending_steps.size()) % chunk_frames == 0) commit();
  }

  /// Writes `data` as frames [committed, committed + count) of `dataset`.
  void append(hid_t dataset, hid_t memory_type, const void* data, hsize_t count, const char* what) {
    const Id old_space = space_id(H5Dget_space(dataset));
    std::array<hsize_t, 3> dims{};
    const int rank = H5Sget_simple_extent_dims(old_space.get(), dims.data(), nullptr);
    std::array<hsize_t, 3> start{committed, 0, 0};
    std::array<hsize_t, 3> counts = dims;
    counts[0] = count;
    dims[0] = committed + count;
    checked(H5Dset_extent(dataset, dims.data()), name, std::string("extend ") + what);
    const Id space = space_id(H5Dget_space(dataset));
    H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, counts.data(), nullptr);
    const Id memory = space_id(H5Screate_simple(rank, counts.data(), nullptr));
    checked(H5Dwrite(dataset, memory_type, memory.get(), space.get(), H5P_DEFAULT, data), name,
            std::string("write ") + what);
  }

  void commit() {
    const hsize_t count = pending_steps.size();
    if (count == 0) return;
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      if (kElements[e].integer) {
        std::vector<std::int32_t> numbers(pending[e].begin(), pending[e].end());
        append(values[e].get(), H5T_NATIVE_INT32, numbers.data(), count, kElements[e].name);
      } else {
        append(values[e].get(), H5T_NATIVE_DOUBLE, pending[e].data(), count, kElements[e].name);
      }
      pending[e].clear();
    }
    std::vector<double> box(9 * count, 0.0);
    for (hsize_t f = 0; f < count; ++f) {
      box[9 * f] = layout.box_x;
      box[9 * f + 4] = layout.box_y;
      box[9 * f + 8] = layout.box_z;
    }
    append(edges.get(), H5T_NATIVE_DOUBLE, box.data(), count, "box/edges");
    // step and time last: a frame whose step is in the file has all its values there.
    append(times.get(), H5T_NATIVE_DOUBLE, pending_times.data(), count, "time");
    append(steps.get(), H5T_NATIVE_INT64, pending_steps.data(), count, "step");
    committed += count;
    pending_steps.clear();
    pending_times.clear();
    flush();
  }

  /// Hands everything to the kernel and waits until it is on disk.
  void flush() {
    checked(H5Fflush(file.get(), H5F_SCOPE_LOCAL), name, "flush");
    void* handle = nullptr;
    Id access = plist_id(H5Fget_access_plist(file.get()));
    if (H5Fget_vfd_handle(file.get(), access.get(), &handle) >= 0 && handle != nullptr) {
      ::fsync(*static_cast<int*>(handle));
    }
  }
};

RodsH5mdWriter::RodsH5mdWriter(const std::filesystem::path& path, const H5mdLayout& layout)
    : impl_(std::make_unique<Impl>(path, layout)) {
  impl_->create();
}

RodsH5mdWriter::RodsH5mdWriter(const std::filesystem::path& path, const H5mdLayout& layout,
                               std::uint64_t keep_frames)
    : impl_(std::make_unique<Impl>(path, layout)) {
  impl_->open(keep_frames);
}

RodsH5mdWriter::~RodsH5mdWriter() {
  try {
    impl_->commit();
  } catch (...) {
    // A destructor cannot report; what was committed before stays readable.
  }
}

void RodsH5mdWriter::write(const engine::Frame& frame, std::int64_t step) {
  impl_->add(frame, step);
}
void RodsH5mdWriter::commit() { impl_->commit(); }
std::uint64_t RodsH5mdWriter::frames() const {
  return impl_->committed + impl_->pending_steps.size();
}
const std::filesystem::path& RodsH5mdWriter::path() const { return impl_->path; }

// ---------------------------------------------------------------------------------------------
// Reader

struct RodsH5mdReader::Impl {
  std::string name;
  Id file;
  std::array<Id, kElements.size()> values;
  Id steps, times, edges;
  std::vector<std::string> species_names;
  std::vector<int> rod_species;
  double box_x = 0.0, box_y = 0.0;
  std::uint64_t frames = 0;  ///< readable
  std::uint64_t chunk_frames = 1;
  std::uint64_t next = 0;
  std::uint64_t block_start = 0, block_size = 0;  ///< frames in the buffers
  std::array<std::vector<double>, kElements.size()> block;
  std::vector<std::int64_t> block_steps;
  std::vector<double> block_times;
  std::string error, warning;

  void open(std::vector<std::string> expected_species) {
    silence_hdf5();
    if (!std::filesystem::exists(name)) throw std::runtime_error(name + ": no such file");
    file = Id(checked(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), name, "open it as HDF5"),
              H5Fclose);
    const auto open_dataset = [&](const std::string& path) {
      if (!has_path(path)) {
        throw std::runtime_error(name + ": no " + path + " (not a rods.h5 written by rodsort)");
      }
      return dataset_id(
          checked(H5Dopen2(file.get(), path.c_str(), H5P_DEFAULT), name, "open " + path));
    };
    const std::string rods = kRods;
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      values[e] = open_dataset(rods + "/" + kElements[e].name + "/value");
    }
    steps = open_dataset(rods + "/position/step");
    times = open_dataset(rods + "/position/time");
    {
      const Id names = open_dataset("/parameters/species_names");
      species_names = read_strings(names.get(), name);
    }
    {
      const Id species = open_dataset(rods + "/species");
      const Id space = space_id(H5Dget_space(species.get()));
      hsize_t count = 0;
      H5Sget_simple_extent_dims(space.get(), &count, nullptr);
      rod_species.resize(count);
      if (count > 0) {
        checked(H5Dread(species.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                        rod_species.data()),
                name, "read " + rods + "/species");
      }
    }
    edges = open_dataset(rods + "/box/edges/value");
    for (const int species : rod_species) {
      if (species < 0 || species >= static_cast<int>(species_names.size())) {
        throw std::runtime_error(name + ": a rod's species " + std::to_string(species) +
                                 " is not among the " + std::to_string(species_names.size()) +
                                 " in /parameters/species_names");
      }
    }
    if (!expected_species.empty() && expected_species != species_names) {
      std::string found, expected;
      for (const auto& s : species_names) found += (found.empty() ? "" : ", ") + s;
      for (const auto& s : expected_species) expected += (expected.empty() ? "" : ", ") + s;
      throw std::runtime_error(name + ": species " + found + "; the run's scenario has " +
                               expected);
    }
    // The frames every dataset has; shapes as written.
    std::uint64_t count = std::numeric_limits<std::uint64_t>::max();
    for (std::size_t e = 0; e <= kElements.size() + 1; ++e) {
      const hid_t dataset = e < kElements.size()    ? values[e].get()
                            : e == kElements.size() ? steps.get()
                                                    : times.get();
      const Id space = space_id(H5Dget_space(dataset));
      std::array<hsize_t, 3> dims{};
      const int rank = H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
      const int expected_rank = e < kElements.size() ? (kElements[e].components > 1 ? 3 : 2) : 1;
      if (rank != expected_rank || (rank >= 2 && dims[1] != rod_species.size()) ||
          (rank == 3 && dims[2] != 3)) {
        throw std::runtime_error(name + ": a dataset under " + rods +
                                 " does not have the shape rodsort writes");
      }
      count = std::min<std::uint64_t>(count, dims[0]);
    }
    {
      const Id space = space_id(H5Dget_space(edges.get()));
      std::array<hsize_t, 3> dims{};
      if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) != 3 || dims[1] != 3 ||
          dims[2] != 3) {
        throw std::runtime_error(name + ": " + rods +
                                 "/box/edges/value is not a series of 3 x 3 matrices");
      }
      count = std::min<std::uint64_t>(count, dims[0]);
      if (count > 0) {
        std::vector<double> box;
        read(edges.get(), H5T_NATIVE_DOUBLE, 0, 1, box);
        box_x = box[0];
        box_y = box[4];
      }
    }
    frames = count;
    {
      const Id properties = plist_id(H5Dget_create_plist(steps.get()));
      hsize_t chunk = 1;
      if (H5Pget_layout(properties.get()) == H5D_CHUNKED) H5Pget_chunk(properties.get(), 1, &chunk);
      chunk_frames = std::max<hsize_t>(chunk, 1);
    }
  }

  /// Whether every link on the absolute `path` exists.
  bool has_path(const std::string& path) const {
    std::size_t at = 1;
    while (true) {
      const std::size_t slash = path.find('/', at);
      const std::string prefix = path.substr(0, slash);
      if (H5Lexists(file.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      if (slash == std::string::npos) return true;
      at = slash + 1;
    }
  }

  void read_block(std::uint64_t start) {
    const hsize_t count = std::min<std::uint64_t>(chunk_frames, frames - start);
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      read(values[e].get(), H5T_NATIVE_DOUBLE, start, count, block[e]);
    }
    read(steps.get(), H5T_NATIVE_INT64, start, count, block_steps);
    read(times.get(), H5T_NATIVE_DOUBLE, start, count, block_times);
    block_start = start;
    block_size = count;
  }

  template <typename T>
  void read(hid_t dataset, hid_t memory_type, hsize_t start, hsize_t count, std::vector<T>& out) {
    const Id space = space_id(H5Dget_space(dataset));
    std::array<hsize_t, 3> dims{};
    const int rank = H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    std::array<hsize_t, 3> offset{start, 0, 0};
    dims[0] = count;
    std::size_t size = 1;
    for (int d = 0; d < rank; ++d) size *= dims[d];
    out.resize(size);
    H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, offset.data(), nullptr, dims.data(), nullptr);
    const Id memory = space_id(H5Screate_simple(rank, dims.data(), nullptr));
    checked(H5Dread(dataset, memory_type, memory.get(), space.get(), H5P_DEFAULT, out.data()), name,
            "read frames " + std::to_string(start) + " to " + std::to_string(start + count - 1));
  }

  bool next_frame(engine::Frame& frame) {
    if (next >= frames) return false;
    if (next < block_start || next >= block_start + block_size) read_block(next);
    const std::size_t k = next - block_start;
    const std::size_t n = rod_species.size();
    std::array<const double*, kElements.size()> row{};
    bool complete = block_steps[k] >= 0 && std::isfinite(block_times[k]);
    for (std::size_t e = 0; e < kElements.size(); ++e) {
      const std::size_t per_frame = n * static_cast<std::size_t>(kElements[e].components);
      row[e] = block[e].data() + k * per_frame;
      if (kElements[e].integer) continue;
      for (std::size_t i = 0; complete && i < per_frame; ++i) complete = std::isfinite(row[e][i]);
    }
    if (!complete) {
      warning = name + ": dropped " + std::to_string(frames - next) +
                " incomplete frame(s) at the end (the run stopped while writing them)";
      frames = next;
      return false;
    }
    frame.time = block_times[k];
    frame_from_values(row, rod_species, box_x, box_y, frame);
    ++next;
    return true;
  }
};

RodsH5mdReader::RodsH5mdReader(const std::filesystem::path& path,
                               std::vector<std::string> species_names)
    : impl_(std::make_unique<Impl>()) {
  impl_->name = path.string();
  try {
    impl_->open(std::move(species_names));
  } catch (const std::runtime_error& failure) {
    impl_->error = failure.what();
    impl_->frames = 0;
  }
}

RodsH5mdReader::~RodsH5mdReader() = default;

bool RodsH5mdReader::next(engine::Frame& frame) {
  if (!impl_->error.empty()) return false;
  try {
    return impl_->next_frame(frame);
  } catch (const std::runtime_error& failure) {
    impl_->error = failure.what();
    return false;
  }
}

const std::string& RodsH5mdReader::error() const { return impl_->error; }
const std::string& RodsH5mdReader::warning() const { return impl_->warning; }
const std::vector<std::string>& RodsH5mdReader::species() const { return impl_->species_names; }
std::uint64_t RodsH5mdReader::frame_count() const { return impl_->frames; }
void RodsH5mdReader::seek(std::uint64_t index) { impl_->next = index; }

}  // namespace rodsort::metrics
