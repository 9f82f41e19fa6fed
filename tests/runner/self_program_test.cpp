#include "runner/self_program.hpp"

#include <link.h>
#include <sys/auxv.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <string>
#include <vector>

#include "rodsort_program.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::runner::testing::kRodsortProgram;
using rodsort::runner::testing::ProgramResult;
using rodsort::runner::testing::run_program;
using rodsort::runner::testing::run_rodsort;
using rodsort::testing::TempDirectory;

namespace {

/// The dynamic loader that started this test program (the object loaded at AT_BASE); empty when
/// none did.
std::string own_loader() {
  struct Search {
    ElfW(Addr) base;
    std::string name;
  } search{getauxval(AT_BASE), {}};
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        auto& s = *static_cast<Search*>(data);
        if (info->dlpi_addr == s.base && info->dlpi_name != nullptr) s.name = info->dlpi_name;
        return 0;
      },
      &search);
  return search.base == 0 ? std::string() : search.name;
}

void touch(const std::filesystem::path& file) { std::ofstream(file) << "x"; }

}  // namespace

TEST_CASE("the command that starts rodsort again: the program, or the loader that mapped it",
          "[runner]") {
  TempDirectory directory;
  const auto loader = directory / "ld-linux-x86-64.so.2";
  const auto program = directory / "rodsort";
  touch(loader);
  touch(program);
  using Words = std::vector<std::string>;

  // Started by the kernel (an interpreter ran first): /proc/self/exe is the program.
  CHECK(program_command_from(program, program.string(), false, {"rodsort", "sweep", "s.yaml"}) ==
        Words{program.string()});
  // Started through the loader, with its options: the loader, its options and the program.
  CHECK(program_command_from(loader, program.string(), true,
                             {"./ld.so", "--library-path", "lib", program.string(), "sweep"}) ==
        Words{loader.string(), "--library-path", "lib", program.string()});
  // A static program: no interpreter, and AT_EXECFN is the executable itself.
  CHECK(program_command_from(program, program.string(), true, {program.string(), "run"}) ==
        Words{program.string()});
  // A loader's command line without the program (cannot happen): the executable, as before.
  CHECK(program_command_from(loader, program.string(), true, {"ld.so", "--list"}) ==
        Words{loader.string()});

  // This test program was started normally: it is its own command, and its own file.
  CHECK(program_command() == Words{std::filesystem::read_symlink("/proc/self/exe").string()});
  CHECK(program_file() == std::filesystem::read_symlink("/proc/self/exe"));
}

TEST_CASE(
    "rodsort started through its dynamic loader sweeps with itself, and a plain rodsort "
    "resumes its runs",
    "[runner][sweep]") {
  // How a build carried to a machine without its libraries runs there.
  const std::string loader = own_loader();
  REQUIRE_FALSE(loader.empty());
  TempDirectory directory;
  const auto sweep = directory / "sweep";
  const ProgramResult swept = run_program(
      {loader, kRodsortProgram, "sweep", RODSORT_SOURCE_DIR "/tests/runner/data/tiny-sweep.yaml",
       "-o", sweep.string(), "-j", "2"},
      directory.path());
  INFO(swept.out << swept.err);
  REQUIRE(swept.status == kExitOk);
  const CsvTable table = read_csv(sweep / "sweep.csv");
  REQUIRE(table.rows.size() == 2);
  for (const auto& row : table.rows) CHECK(row[2] == "complete");

  // The checkpoint names this build (the program's bytes, not the loader's): the program run
  // directly continues it.
  const ProgramResult resumed =
      run_rodsort({"run", "--resume", (sweep / table.rows[0][0]).string(), "--duration", "0.42"},
                  directory.path());
  INFO(resumed.out << resumed.err);
  CHECK(resumed.status == kExitOk);
  CHECK_THAT(resumed.err, !Catch::Contains("another build"));
}
