#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "runner/append_file.hpp"
#include "runner/atomic_file.hpp"
#include "runner/run_directory.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

TEST_CASE("an atomic write replaces the whole file and leaves no temporary", "[runner][files]") {
  TempDirectory directory;
  const auto path = directory / "run.json";
  write_file_atomically(path, "first version, rather long\n");
  write_file_atomically(path, "second\n");
  CHECK(read_file(path) == "second\n");
  CHECK_FALSE(std::filesystem::exists(directory / "run.json.tmp"));
}

TEST_CASE("an atomic write into a missing directory names the file", "[runner][files]") {
  TempDirectory directory;
  const auto path = directory / "missing" / "run.json";
  CHECK_THROWS_WITH(write_file_atomically(path, "x"), Catch::Contains("missing/run.json.tmp"));
}

TEST_CASE("an append file counts its bytes and cuts back to a recorded size", "[runner][files]") {
  TempDirectory directory;
  const auto path = directory / "rods.csv";
  std::uint64_t after_header = 0;
  {
    AppendFile file(path);
    CHECK(file.size() == 0);
    file.append("t,rod\n");
    after_header = file.size();
    file.append("0,0\n0,1\n");
    CHECK(file.size() == 14);
  }
  AppendFile reopened(path);
  CHECK(reopened.size() == 14);
  reopened.truncate(after_header);
  reopened.append("0.5,0\n");
  CHECK(read_file(path) == "t,rod\n0.5,0\n");
  CHECK_THROWS_WITH(reopened.truncate(1000), Catch::Contains("fewer than the 1000"));
}

TEST_CASE("a directory holds a run when any file a run writes is there", "[runner][files]") {
  TempDirectory directory;
  CHECK_FALSE(holds_run(directory.path()));
  CHECK_FALSE(holds_run(directory / "absent"));
  std::ofstream(directory / "notes.txt") << "mine\n";
  CHECK_FALSE(holds_run(directory.path()));
  std::ofstream(directory / snapshot_file_name(2.5)) << "x";
  CHECK(holds_run(directory.path()));
  std::ofstream(directory / kRodsCsvFile) << "t\n";
  clear_run(directory.path());
  CHECK_FALSE(holds_run(directory.path()));
  CHECK(std::filesystem::exists(directory / "notes.txt"));
}

TEST_CASE("snapshot files are named by their simulated time", "[runner][files]") {
  CHECK(snapshot_file_name(2.5) == "snapshot-t2.5.bullet");
  CHECK(snapshot_file_name(100.0) == "snapshot-t100.bullet");
  CHECK(snapshot_file_name(0.07) == "snapshot-t0.07.bullet");
}
