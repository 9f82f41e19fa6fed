#include "runner/checkpoint.hpp"

#include <catch2/catch.hpp>
#include <fstream>

#include "runner/atomic_file.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort;
using runner::Checkpoint;
using rodsort::testing::TempDirectory;

namespace {

Checkpoint sample_checkpoint() {
  Checkpoint checkpoint;
  checkpoint.state.time = 1.25;
  checkpoint.state.step = 12500;
  engine::RodState rod{};
  rod.position = {1.0, 2.0, 0.6};
  rod.basis = {0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0};
  rod.velocity = {3.0, -4.0, 0.5};
  rod.angular_velocity = {0.0, 0.0, 0.7};
  rod.image = {-1, 2};
  rod.touching = {true, false};
  rod.kick_rng = {1, 2, 3, 4};
  rod.noise_rng = {5, 6, 7, 8};
  checkpoint.state.rods = {rod, rod};
  checkpoint.file_bytes = {{"rods.csv", 123456}, {"metrics.csv", 789}};
  checkpoint.file_frames = {{"rods.h5", 1431}};
  checkpoint.wall_s = 10.5;
  checkpoint.cpu_s = 0.1 + 0.2;
  checkpoint.sessions = 3;
  checkpoint.started_at = "2026-11-21T04:41:00Z";
  checkpoint.metrics_replay_offset = 120000;
  return checkpoint;
}

}  // namespace

TEST_CASE("a checkpoint reads back exactly as written", "[runner][checkpoint]") {
  TempDirectory directory;
  const Checkpoint written = sample_checkpoint();
  runner::write_checkpoint(directory / "checkpoint.bin", written);
  const Checkpoint back = runner::read_checkpoint(directory / "checkpoint.bin");
  CHECK(engine::hash_state(back.state) == engine::hash_state(written.state));
  CHECK(back.state.step == 12500);
  CHECK(back.file_bytes == written.file_bytes);
  CHECK(back.file_frames == written.file_frames);
  CHECK(back.wall_s == written.wall_s);
  CHECK(back.cpu_s == written.cpu_s);
  CHECK(back.sessions == 3);
  CHECK(back.started_at == written.started_at);
  CHECK(back.metrics_replay_offset == 120000);
}

TEST_CASE("a damaged checkpoint is refused with its name", "[runner][checkpoint]") {
  TempDirectory directory;
  const auto path = directory / "checkpoint.bin";
  CHECK_THROWS_WITH(runner::read_checkpoint(path), Catch::Contains("checkpoint.bin"));
  runner::write_file_atomically(path, "something else\n");
  CHECK_THROWS_WITH(runner::read_checkpoint(path), Catch::Contains("not a checkpoint"));
  runner::write_checkpoint(path, sample_checkpoint());
  const std::string whole = runner::read_file(path);
  runner::write_file_atomically(path, whole.substr(0, whole.size() - 20));
  CHECK_THROWS_WITH(runner::read_checkpoint(path), Catch::Contains("checkpoint.bin"));
  runner::write_file_atomically(path, whole.substr(0, whole.find("state\n")));
  CHECK_THROWS_WITH(runner::read_checkpoint(path), Catch::Contains("cut short"));
}

TEST_CASE("a checkpoint changed after it was written is refused by its checksum",
          "[runner][checkpoint]") {
  TempDirectory directory;
  const auto path = directory / "checkpoint.bin";
  runner::write_checkpoint(path, sample_checkpoint());
  const std::string whole = runner::read_file(path);
  REQUIRE_NOTHROW(runner::read_checkpoint(path));
  // Any one byte of the state, or of the header, changed: both still parse, neither may resume.
  for (const std::size_t at : {whole.find("state\n") + 10, whole.find("sessions") + 9}) {
    std::string changed = whole;
    changed[at] = static_cast<char>(changed[at] ^ 0x01);
    runner::write_file_atomically(path, changed);
    CHECK_THROWS_WITH(runner::read_checkpoint(path),
                      Catch::Contains("checkpoint.bin") &&
                          Catch::Contains("checksum does not match its content"));
  }
  // The format before checksums is named, not misread.
  runner::write_file_atomically(path, "rodsort-checkpoint 1\nstate\n");
  CHECK_THROWS_WITH(runner::read_checkpoint(path), Catch::Contains("an older rodsort"));
}
