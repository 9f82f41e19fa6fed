#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/exit_code.hpp"
#include "runner/sweep.hpp"

namespace rodsort::app {

Command add_sweep_command(CLI::App& app) {
  auto request = std::make_shared<runner::SweepRequest>();
  auto status_directory = std::make_shared<std::string>();
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Run a sweep's points as parallel processes (or as a Slurm job array) and write sweep.csv; "
      "run it again to continue a stopped sweep");
  sweep->add_option("SWEEP", request->sweep_file, "Sweep file (YAML)")->check(CLI::ExistingFile);
  sweep->add_option("-o,--output", request->output, "Sweep directory (default: runs/<sweep name>)");
  sweep
      ->add_option("-j,--jobs", request->jobs,
                   "Points run at once (default: one per processor this process may use)")
      ->check(CLI::Range(1, 1024));
  sweep
      ->add_option("--set", request->set_options,
                   "Override a key of every point, e.g. --set run.duration=600 (points that "
                   "ran with another run.duration only are continued to the new one); repeatable")
      ->allow_extra_args(false);
  sweep->add_flag("--force", request->force,
                  "Rerun points whose run directory holds a different scenario");
  sweep->add_flag("--any-build", request->any_build,
                  "Resume points whose checkpoint another build of rodsort wrote (same physics, "
                  "not bit for bit the same runs)");
  sweep->add_flag("--dry-run", request->dry_run,
                  "Check every point and list what would run; write nothing");
  sweep
      ->add_option("--status", *status_directory,
                   "Show the state of every point of the sweep in DIR (done, running with an "
                   "ETA, failed with its message, not started) and bring its sweep.csv up to "
                   "date; takes no SWEEP")
      ->check(CLI::ExistingDirectory);
  sweep->add_option("--point", request->point,
                    "Run only this point (its index in the grid or its name) in this process, "
                    "as each task of a Slurm array does");

  runner::SlurmOptions& slurm = request->slurm;
  CLI::Option* slurm_flag =
      sweep->add_flag("--slurm", slurm.enabled,
                      "Submit the points still to run as one Slurm job array (docs/cluster.md) "
                      "instead of running them here");
  const auto slurm_option = [&](const char* name, std::string& value, const char* help) {
    sweep->add_option(name, value, help)->needs(slurm_flag)->group("Slurm");
  };
  slurm_option("--partition", slurm.partition, "sbatch --partition");
  slurm_option("--time", slurm.time_limit, "sbatch --time: each task's time limit, e.g. 12:00:00");
  slurm_option("--mem", slurm.memory, "sbatch --mem, e.g. 2G");
  slurm_option("--account", slurm.account, "sbatch --account");
  sweep->add_option("--throttle", slurm.throttle, "At most this many tasks of the array at once")
      ->check(CLI::Range(1, 100000))
      ->needs(slurm_flag)
      ->group("Slurm");
  sweep
      ->add_option("--signal-before", slurm.signal_seconds,
                   "Seconds before the time limit at which Slurm asks a task to stop; it "
                   "writes its checkpoint")
      ->check(CLI::Range(10, 86400))
      ->capture_default_str()
      ->needs(slurm_flag)
      ->group("Slurm");
  sweep
      ->add_option("--sbatch", slurm.extra_lines,
                   "A further #SBATCH line for the array script, e.g. --sbatch=--qos=long; "
                   "repeatable")
      ->allow_extra_args(false)
      ->needs(slurm_flag)
      ->group("Slurm");
  sweep
      ->add_flag_function(
          "--no-submit", [&slurm](std::int64_t) { slurm.submit = false; },
          "With --slurm: write the array script only, for submitting it yourself")
      ->needs(slurm_flag)
      ->group("Slurm");
  slurm_flag->excludes(sweep->get_option("--point"));

  return {sweep, [request, status_directory] {
            if (!status_directory->empty()) {
              if (!request->sweep_file.empty()) {
                std::cerr << "rodsort: --status reads a sweep directory and takes no SWEEP "
                             "file\n";
                return static_cast<int>(runner::kExitUsage);
              }
              return runner::sweep_status(*status_directory, std::cout, std::cerr);
            }
            if (request->sweep_file.empty()) {
              std::cerr << "rodsort: sweep: give a sweep file (SWEEP), or --status DIR\n";
              return static_cast<int>(runner::kExitUsage);
            }
            return runner::run_sweep(*request, std::cout, std::cerr);
          }};
}

}  // namespace rodsort::app
