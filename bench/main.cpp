// rodsort_bench: the engine's benchmark (see bench/benchmark.hpp and docs/performance.md).

#include <exception>
#include <iostream>

#include "bench/accuracy.hpp"
#include "bench/benchmark.hpp"

int main(int argc, char** argv) {
  rodsort::bench::Options options;
  rodsort::bench::AccuracyOptions accuracy;
  bool accuracy_selected = false;
  CLI::App app{"rodsort_bench: CPU seconds per simulated second of the engine's standard systems"};
  app.name("rodsort_bench");
  rodsort::bench::add_options(app, options);
  rodsort::bench::add_accuracy_options(app, accuracy, accuracy_selected);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    if (accuracy_selected) {
      accuracy.seed = options.seed;
      accuracy.csv = options.csv;
      accuracy.solver_iterations = options.solver_iterations;
      return rodsort::bench::run_accuracy(accuracy, std::cout);
    }
    return rodsort::bench::run(options, std::cout);
  } catch (const std::exception& error) {
    std::cerr << "rodsort_bench: error: " << error.what() << '\n';
    return 1;
  }
}
