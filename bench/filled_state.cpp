#include "bench/filled_state.hpp"

#include <cmath>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "bench/measures.hpp"
#include "bench/standard_system.hpp"
#include "engine/simulation.hpp"
#include "engine/units.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::bench {

namespace {

constexpr const char* kPackedSystem = "319-full";

/// The cost of the fill per simulated second, for the announcement: the packed system's measured
/// average over its first 30 s (docs/performance.md, section 1) [CPU-s / sim-s].
constexpr double kFillCostPerSecond = 4.0;

engine::Model packed_model(const FillOptions& options) {
  engine::Model model = build_model(find_system(kPackedSystem), options.dt, options.seed);
  model.solver_iterations = options.solver_iterations;
  return model;
}

/// The state in `path`, if it reads whole and holds the paper system's rods.
bool read_filled(const std::filesystem::path& path, std::size_t rods, engine::State& state) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  try {
    state = engine::read_state(in);
  } catch (const std::runtime_error&) {
    return false;
  }
  return state.rods.size() == rods;
}

}  // namespace

std::filesystem::path filled_state_path(const FillOptions& options) {
  return options.directory /
         ("paper-120deg-filled-seed" + std::to_string(options.seed) + "-dt" +
          format("%g", options.dt) + "-iterations" + std::to_string(options.solver_iterations) +
          "-fill" + format("%g", options.fill_time) + "s.state");
}

engine::State filled_paper_state(const FillOptions& options, std::ostream& log) {
  const std::filesystem::path path = filled_state_path(options);
  engine::Model model = packed_model(options);
  engine::State state;
  if (read_filled(path, model.rods.size(), state)) return state;

  log << "rodsort_bench: filling the trap of " << kPackedSystem << ": " << options.fill_time
      << " simulated s from the packed start, about "
      << format("%.0f", kFillCostPerSecond * options.fill_time / 60.0) << " CPU-min, once; kept in "
      << path.string() << '\n'
      << std::flush;
  const double cpu_start = process_cpu_seconds();
  engine::Simulation simulation(std::move(model));
  simulation.advance(std::llround(options.fill_time / options.dt));
  state = simulation.state();

  std::error_code error;
  std::filesystem::create_directories(options.directory, error);
  if (error) {
    throw std::runtime_error("cannot create the directory of filled states " +
                             options.directory.string() + ": " + error.message());
  }
  const std::filesystem::path partial = path.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    engine::write_state(out, state);
    out.flush();
    if (!out) throw std::runtime_error("cannot write the filled state " + partial.string());
  }
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::filesystem::remove(partial);
    throw std::runtime_error("cannot write the filled state " + path.string() + ": " +
                             error.message());
  }
  const trap::VTrap trap = trap::centered_v_trap(
      kPaperBox, kPaperBox, degrees_to_radians(kTrapAngleDegrees), kPaperArm, kTrapWallThickness);
  int inside = 0;
  for (const engine::RodState& rod : state.rods) {
    inside += trap.contains(Eigen::Vector2d(rod.position[0], rod.position[1])) ? 1 : 0;
  }
  log << "rodsort_bench: filled in " << format("%.0f", process_cpu_seconds() - cpu_start)
      << " CPU-s; " << inside << " of " << state.rods.size() << " rods in the trap\n"
      << std::flush;
  return state;
}

engine::Model tile_model(const engine::Model& model, int tiles) {
  if (tiles < 1) throw std::invalid_argument("tiles must be at least 1");
  engine::Model tiled = model;
  tiled.box_x = model.box_x * tiles;
  tiled.box_y = model.box_y * tiles;
  tiled.rods.clear();
  tiled.walls.clear();
  for (int i = 0; i < tiles; ++i) {
    for (int j = 0; j < tiles; ++j) {
      const double dx = model.box_x * i, dy = model.box_y * j;
      for (engine::RodInit rod : model.rods) {
        rod.x += dx;
        rod.y += dy;
        tiled.rods.push_back(rod);
      }
      for (engine::Wall wall : model.walls) {
        wall.center_x += dx;
        wall.center_y += dy;
        tiled.walls.push_back(wall);
      }
    }
  }
  return tiled;
}

engine::State tile_state(const engine::State& one_cell, const engine::Model& one_cell_model,
                         const engine::State& tiled_fresh, int tiles) {
  const std::size_t n = one_cell.rods.size();
  if (tiled_fresh.rods.size() != n * static_cast<std::size_t>(tiles * tiles)) {
    throw std::invalid_argument("the tiled state holds " + std::to_string(tiled_fresh.rods.size()) +
                                " rods, not " + std::to_string(tiles * tiles) + " x " +
                                std::to_string(n));
  }
  engine::State tiled = tiled_fresh;
  tiled.time = one_cell.time;
  tiled.step = one_cell.step;
  tiled.contacts = tiles == 1 ? one_cell.contacts : std::vector<engine::SurfaceContactState>{};
  for (int i = 0; i < tiles; ++i) {
    for (int j = 0; j < tiles; ++j) {
      const std::size_t tile = static_cast<std::size_t>(i * tiles + j);
      for (std::size_t k = 0; k < n; ++k) {
        engine::RodState& rod = tiled.rods[tile * n + k];
        const engine::RodState& source = one_cell.rods[k];
        const auto kick_rng = rod.kick_rng;
        const auto noise_rng = rod.noise_rng;
        rod = source;
        rod.position[0] += one_cell_model.box_x * i;
        rod.position[1] += one_cell_model.box_y * j;
        if (tile != 0) {
          rod.kick_rng = kick_rng;
          rod.noise_rng = noise_rng;
        }
      }
    }
  }
  return tiled;
}

}  // namespace rodsort::bench
