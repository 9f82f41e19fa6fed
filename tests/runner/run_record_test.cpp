#include "runner/run_record.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

TEST_CASE("a run record survives its JSON text", "[runner][run_record]") {
  RunRecord record;
  record.version = "0.1.0";
  record.name = "fig2b \"theta\" 120";
  record.seed = 18446744073709551615ULL;
  record.status = RunStatus::kInterrupted;
  record.rods = 319;
  record.dt_s = 1e-4;
  record.duration_s = 300;
  record.steps = 1234567;
  record.total_steps = 3000000;
  record.simulated_s = 123.4567;
  record.wall_s = 0.1 + 0.2;
  record.cpu_s = 987.125;
  record.sessions = 2;
  record.started_at = "2026-11-21T04:41:00Z";
  record.updated_at = "2026-11-21T05:41:00Z";
  record.message = "interrupted by SIGINT\nresume it";
  const std::string json = to_json(record);
  CHECK_THAT(json, Catch::Contains("\"status\": \"interrupted\""));
  CHECK(nlohmann::json::parse(json).at("cpu_s_per_simulated_s").get<double>() ==
        987.125 / 123.4567);
  const RunRecord back = parse_run_record(json);
  CHECK(back.name == record.name);
  CHECK(back.seed == record.seed);
  CHECK(back.status == RunStatus::kInterrupted);
  CHECK(back.rods == 319);
  CHECK(back.dt_s == record.dt_s);
  CHECK(back.steps == record.steps);
  CHECK(back.total_steps == record.total_steps);
  CHECK(back.simulated_s == record.simulated_s);
  CHECK(back.wall_s == record.wall_s);  // exact: shortest round-trip text
  CHECK(back.cpu_s == record.cpu_s);
  CHECK(back.sessions == 2);
  CHECK(back.started_at == record.started_at);
  CHECK(back.message == record.message);
}

TEST_CASE("run.json is read back from a run directory", "[runner][run_record]") {
  TempDirectory directory;
  CHECK_FALSE(read_run_record(directory.path()).has_value());
  RunRecord record;
  record.name = "tiny";
  record.status = RunStatus::kComplete;
  write_run_record(directory.path(), record);
  const auto back = read_run_record(directory.path());
  REQUIRE(back.has_value());
  CHECK(back->status == RunStatus::kComplete);
}

TEST_CASE("a file that is not a run record is refused with its name", "[runner][run_record]") {
  CHECK_THROWS_WITH(parse_run_record("[1, 2]"), Catch::Contains("not a run record"));
  CHECK_THROWS_WITH(parse_run_record("{\"status\": \"running\"}"),
                    Catch::Contains("not a run record"));
  CHECK_THROWS_WITH(run_status_from_string("paused"), Catch::Contains("paused"));
}

TEST_CASE("run.json escapes what a message may hold and keeps its numbers exact",
          "[runner][run_record]") {
  RunRecord record;
  record.message = std::string("a\"b\\c\n") + '\x01' + " 5 µm";
  record.simulated_s = 1e-4;
  record.dt_s = 0.07;
  const std::string json = to_json(record);
  CHECK_THAT(json, Catch::Contains(R"("message": "a\"b\\c\n\u0001 5 µm")"));
  CHECK_THAT(json, Catch::Contains(R"("dt_s": 0.07,)"));
  const RunRecord back = parse_run_record(json);
  CHECK(back.message == record.message);
  CHECK(back.simulated_s == 1e-4);
  CHECK(back.dt_s == 0.07);
}

TEST_CASE("the current time is written in ISO 8601, UTC", "[runner][run_record]") {
  const std::string now = utc_now_iso8601();
  REQUIRE(now.size() == 20);
  CHECK(now[4] == '-');
  CHECK(now[10] == 'T');
  CHECK(now.back() == 'Z');
}
