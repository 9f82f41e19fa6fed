#include "metrics/rods_csv.hpp"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <string_view>

namespace rodsort::metrics {
namespace {

constexpr int kFieldCount = 15;
constexpr const char* kFieldNames[kFieldCount] = {
    "t", "rod", "species", "x", "y", "xu", "yu", "z", "ux", "uy", "uz", "vx", "vy", "vz", "wz"};

std::string format_time(double time) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", time);
  return text;
}

void append_number(std::string& buffer, double value) {
  char text[32];
  const int length = std::snprintf(text, sizeof text, ",%.9g", value);
  buffer.append(text, length);
}

}  // namespace

RodsCsvWriter::RodsCsvWriter(std::ostream& out, std::vector<std::string> species_names)
    : out_(out), species_names_(std::move(species_names)) {
  for ([[maybe_unused]] const std::string& name : species_names_) {
    assert(!name.empty() && name.find_first_of(",\"\r\n") == std::string::npos);
  }
}

void RodsCsvWriter::write_header() { out_ << kRodsCsvHeader << '\n'; }

void RodsCsvWriter::write(const engine::Frame& frame) {
  buffer_.clear();
  char text[32];
  for (std::size_t i = 0; i < frame.rods.size(); ++i) {
    const engine::RodFrame& rod = frame.rods[i];
    buffer_.append(text, std::snprintf(text, sizeof text, "%.9g,%zu,", frame.time, i));
    buffer_ += species_names_.at(rod.species);
    for (const double value :
         {rod.position.x(), rod.position.y(), rod.unwrapped.x(), rod.unwrapped.y(), rod.z,
          rod.axis.x(), rod.axis.y(), rod.axis.z(), rod.velocity.x(), rod.velocity.y(),
          rod.velocity.z(), rod.angular_velocity.z()}) {
      append_number(buffer_, value);
    }
    buffer_ += '\n';
  }
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
}

RodsCsvReader::RodsCsvReader(std::istream& in, std::string file_name,
                             std::vector<std::string> species_names, long header_line)
    : in_(in),
      file_name_(std::move(file_name)),
      species_names_(std::move(species_names)),
      fixed_species_(!species_names_.empty()),
      line_number_(header_line - 1) {}

bool RodsCsvReader::fail(long line, int column, const std::string& message) {
  error_ = file_name_;
  error_ += ':';
  error_ += std::to_string(line);
  if (column > 0) {
    error_ += ':';
    error_ += std::to_string(column);
  }
  error_ += ": ";
  error_ += message;
  return false;
}

RodsCsvReader::LineResult RodsCsvReader::read_row(Row& row) {
  std::string line;
  while (true) {
    if (!std::getline(in_, line)) return LineResult::kEnd;
    ++line_number_;
    const bool ended_by_newline = !in_.eof();
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!ended_by_newline && !line.empty()) {
      warning_ = file_name_ + ":" + std::to_string(line_number_) +
                 ": the last line is cut short (the run stopped while writing); dropped it";
      return LineResult::kEnd;
    }
    if (!line.empty()) break;
  }
  // Split into fields, remembering where each starts for messages.
  std::string_view fields[kFieldCount];
  int columns[kFieldCount];
  int count = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string::npos ? line.size() : comma;
    if (count < kFieldCount) {
      fields[count] = std::string_view(line).substr(start, end - start);
      columns[count] = static_cast<int>(start) + 1;
    }
    ++count;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (count != kFieldCount) {
    fail(line_number_, 0,
         "expected " + std::to_string(kFieldCount) + " comma-separated fields (" + kRodsCsvHeader +
             "), got " + std::to_string(count));
    return LineResult::kError;
  }
  double numbers[kFieldCount] = {};
  for (int f = 0; f < kFieldCount; ++f) {
    if (f == 2) continue;  // species, a name
    const std::string_view text = fields[f];
    if (f == 1) {
      int rod = -1;
      const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), rod);
      if (status != std::errc() || end != text.data() + text.size() || text.empty() || rod < 0) {
        fail(line_number_, columns[f],
             "field 'rod': expected a rod index (0, 1, 2, ...), got '" + std::string(text) + "'");
        return LineResult::kError;
      }
      row.rod = rod;
      continue;
    }
    double value = 0.0;
    const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (status != std::errc() || end != text.data() + text.size() || text.empty()) {
      fail(line_number_, columns[f],
           std::string("field '") + kFieldNames[f] + "': expected a number, got '" +
               std::string(text) + "'");
      return LineResult::kError;
    }
    if (!std::isfinite(value)) {
      fail(line_number_, columns[f],
           std::string("field '") + kFieldNames[f] + "': expected a finite number, got '" +
               std::string(text) + "'");
      return LineResult::kError;
    }
    numbers[f] = value;
  }
  const std::string name(fields[2]);
  const auto known = std::find(species_names_.begin(), species_names_.end(), name);
  if (known != species_names_.end()) {
    row.species = static_cast<int>(known - species_names_.begin());
  } else if (fixed_species_ || name.empty()) {
    std::string expected;
    for (const std::string& species : species_names_) {
      if (!expected.empty()) expected += ", ";
      expected += '\'';
      expected += species;
      expected += '\'';
    }
    fail(line_number_, columns[2],
         "field 'species': expected one of the run's species (" + expected + "), got '" + name +
             "'");
    return LineResult::kError;
  } else {
    row.species = static_cast<int>(species_names_.size());
    species_names_.push_back(name);
  }
  row.time = numbers[0];
  row.line = line_number_;
  engine::RodFrame& rod = row.rod_frame;
  rod.species = row.species;
  rod.position = {numbers[3], numbers[4]};
  rod.unwrapped = {numbers[5], numbers[6]};
  rod.z = numbers[7];
  rod.axis = {numbers[8], numbers[9], numbers[10]};
  rod.velocity = {numbers[11], numbers[12], numbers[13]};
  rod.angular_velocity = {0.0, 0.0, numbers[14]};
  return LineResult::kRow;
}

bool RodsCsvReader::next(engine::Frame& frame) {
  if (!error_.empty()) return false;
  if (!header_read_) {
    header_read_ = true;
    std::string header;
    if (!std::getline(in_, header)) {
      return fail(line_number_, 0,
                  std::string("empty file, expected the header '") + kRodsCsvHeader + "'");
    }
    ++line_number_;
    if (!header.empty() && header.back() == '\r') header.pop_back();
    if (header != kRodsCsvHeader) {
      return fail(
          line_number_, 0,
          std::string("expected the header '") + kRodsCsvHeader + "', got '" + header + "'");
    }
  }
  Row row{};
  if (has_pending_) {
    row = pending_;
    has_pending_ = false;
  } else if (read_row(row) != LineResult::kRow) {
    return false;
  }
  if (have_previous_time_ && !(row.time > previous_time_)) {
    return fail(row.line, 1,
                "field 't': expected a time after " + format_time(previous_time_) + ", got " +
                    format_time(row.time));
  }
  const bool first_frame = rod_species_.empty();
  frame.time = row.time;
  frame.rods.clear();
  long last_line = row.line;
  bool at_end = false;
  while (true) {
    if (row.rod != static_cast<int>(frame.rods.size())) {
      return fail(row.line, 0,
                  "field 'rod': expected rod " + std::to_string(frame.rods.size()) +
                      " (rods are listed 0, 1, 2, ... in every frame), got " +
                      std::to_string(row.rod));
    }
    if (!first_frame) {
      if (row.rod >= static_cast<int>(rod_species_.size())) {
        return fail(row.line, 0,
                    "frame at t = " + format_time(frame.time) + " has more rods than the first (" +
                        std::to_string(rod_species_.size()) + ")");
      }
      if (row.species != rod_species_[row.rod]) {
        return fail(row.line, 0,
                    "field 'species': rod " + std::to_string(row.rod) + " was '" +
                        species_names_[rod_species_[row.rod]] + "' in the first frame, got '" +
                        species_names_[row.species] + "'");
      }
    }
    frame.rods.push_back(row.rod_frame);
    last_line = row.line;
    const LineResult result = read_row(row);
    if (result == LineResult::kError) return false;
    if (result == LineResult::kEnd) {
      at_end = true;
      break;
    }
    if (row.time != frame.time) {
      pending_ = row;
      has_pending_ = true;
      break;
    }
  }
  const std::size_t expected = first_frame ? frame.rods.size() : rod_species_.size();
  if (!warning_.empty() && at_end && (first_frame || frame.rods.size() < expected)) {
    warning_ += "; dropped the incomplete frame at t = " + format_time(frame.time);
    return false;
  }
  if (frame.rods.size() < expected) {
    if (at_end) {
      warning_ = file_name_ + ": the last frame (t = " + format_time(frame.time) + ") has " +
                 std::to_string(frame.rods.size()) + " of " + std::to_string(expected) +
                 " rods (the run stopped while writing); dropped it";
      return false;
    }
    return fail(last_line, 0,
                "frame at t = " + format_time(frame.time) + " has " +
                    std::to_string(frame.rods.size()) + " rods, the first frame had " +
                    std::to_string(expected));
  }
  if (first_frame) {
    for (const engine::RodFrame& rod : frame.rods) rod_species_.push_back(rod.species);
  }
  have_previous_time_ = true;
  previous_time_ = frame.time;
  return true;
}

RodsCsv read_rods_csv(const std::filesystem::path& path, std::vector<std::string> species_names) {
  RodsCsv result;
  std::ifstream in(path);
  if (!in) {
    result.error = path.string() + ": cannot open for reading";
    return result;
  }
  RodsCsvReader reader(in, path.string(), std::move(species_names));
  engine::Frame frame;
  while (reader.next(frame)) result.frames.push_back(frame);
  result.species = reader.species();
  result.error = reader.error();
  result.warning = reader.warning();
  return result;
}

}  // namespace rodsort::metrics
