#include "runner/usable_cpus.hpp"

#include <sched.h>

#include <catch2/catch.hpp>

using rodsort::runner::usable_cpus;

TEST_CASE("a sweep runs as many points as the affinity mask and Slurm allow", "[runner][sweep]") {
  CHECK(usable_cpus(8, std::nullopt, std::nullopt) == 8);
  CHECK(usable_cpus(8, "2", std::nullopt) == 2);
  CHECK(usable_cpus(8, std::nullopt, "4") == 4);
  CHECK(usable_cpus(8, "2", "4") == 2);            // the task's share, not the node's
  CHECK(usable_cpus(2, "16", std::nullopt) == 2);  // never beyond the mask
  CHECK(usable_cpus(8, "", "x") == 8);             // unreadable values are ignored
  CHECK(usable_cpus(8, "0", "-3") == 8);
  CHECK(usable_cpus(8, "3 ", std::nullopt) == 8);
  CHECK(usable_cpus(0, std::nullopt, std::nullopt) == 1);
}

TEST_CASE("the affinity mask of this process is read", "[runner][sweep]") {
  cpu_set_t saved;
  CPU_ZERO(&saved);
  REQUIRE(sched_getaffinity(0, sizeof saved, &saved) == 0);
  int first = 0;
  while (!CPU_ISSET(first, &saved)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  REQUIRE(sched_setaffinity(0, sizeof one, &one) == 0);
  const int measured = usable_cpus();
  REQUIRE(sched_setaffinity(0, sizeof saved, &saved) == 0);
  CHECK(measured == 1);
  CHECK(usable_cpus() == CPU_COUNT(&saved));
}
