#pragma once
// The benchmark's standard systems, built by hand as engine::Model values (no YAML), so that the
// figures measure the engine alone and stay comparable while the scenario layer evolves.
//
// "paper" systems are the paper's sorting setup: rod A with the collision kick (eps = 0.01 mm^-1),
// a V trap of opening 120° and arm 10 rod lengths in a periodic square cell of side 19.3 rod
// lengths, 319 rods. Larger systems scale the cell's side and the arm by k and the rod count by
// k^2, so that density and geometry stay the paper's. "single" is one free rod, the cost floor of
// a step with nothing to collide with but the plates.
//
// "-full" systems are the same with the trap filled at the start: the state a trapping run spends
// nearly all its time in. Rods are packed into the trap from the apex, in rows across the bisector,
// each pointing its thin end at the apex, as many as fit with the placement clearance (about two
// thirds of the rods); the others go on the lattice outside.
//
// "-filled" systems are the paper's system after its trap has filled by the rods' own motion
// (bench/filled_state.hpp), alone (319-filled) or as 2 x 2 and 4 x 4 copies side by side, each
// with its trap (319-filled-x4, 319-filled-x16).

#include <cstdint>
#include <string>
#include <vector>

#include "engine/model.hpp"

namespace rodsort::bench {

struct SystemSpec {
  std::string name;  ///< as given on the command line: "single", "319", "1276", "5104"
  int rod_count;     ///< rods of type A
  double box;        ///< side of the periodic square cell [mm]
  double trap_arm;   ///< arm length of the V trap, 0 for no trap [mm]
  bool full_trap = false;  ///< rods packed into the trap at the start
  /// Copies per side of the filled paper system (bench/filled_state.hpp); 0 for a system built
  /// from its placement alone.
  int filled_tiles = 0;
};

/// The paper's cell side, 19.3 rod lengths [mm].
inline constexpr double kPaperBox = 19.3 * 4.5;
/// The paper's trap arm, 10 rod lengths [mm].
inline constexpr double kPaperArm = 45.0;
/// The paper's trap opening for the benchmark [degrees].
inline constexpr double kTrapAngleDegrees = 120.0;
/// Thickness of the trap walls [mm] (the scenario schema's default).
inline constexpr double kTrapWallThickness = 1.0;
/// The paper's collision kick [1/mm].
inline constexpr double kPaperKickEps = 0.01;

/// Rod A of brass with the collision kick `kick_eps` [1/mm].
engine::Species rod_a_species(double kick_eps);

/// single, the paper's system with side x1, x2, x4 (319, 1,276, 5,104 rods), the same three with
/// a full trap (319-full, 1276-full, 5104-full), then the filled paper system in 1, 2 x 2 and
/// 4 x 4 copies (319-filled, 319-filled-x4, 319-filled-x16).
std::vector<SystemSpec> standard_systems();

/// The standard system of that name; throws std::invalid_argument naming the known ones.
SystemSpec find_system(const std::string& name);

/// The model of a system: the paper's drive and materials, rod A with the paper's kick, the trap
/// centred in the cell, rods on a jittered lattice outside the walls with random headings (all
/// drawn from `seed`). For a filled system, the packed-trap system 319-full tiled: the model its
/// filled state (bench/filled_state.hpp) is restored into. Throws std::runtime_error if the rods
/// cannot be placed.
engine::Model build_model(const SystemSpec& system, double dt, std::uint64_t seed);

}  // namespace rodsort::bench
