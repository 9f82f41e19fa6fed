#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/convert.hpp"

namespace rodsort::app {

Command add_convert_command(CLI::App& app) {
  auto request = std::make_shared<runner::ConvertRequest>();
  CLI::App* convert = app.add_subcommand(
      "convert",
      "Write a stopped run's frames from rods.csv into rods.h5 (HDF5/H5MD, several times smaller); "
      "rods.csv stays");
  convert->add_option("RUN_DIR", request->run_directory, "Run directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  convert->add_flag("--double", request->double_precision,
                    "Store double precision (default: single, 7 significant digits)");
  return {convert, [request] { return runner::convert_run(*request, std::cerr); }};
}

}  // namespace rodsort::app
