#pragma once
// ScenarioSpec mirrors a scenario file key for key, every value with the place that set it. It is
// the first of the three stages (YAML -> ScenarioSpec -> compile() -> engine::Model): reading it
// checks keys, types, ranges and the consistency of neighbouring keys; the physics checks that
// need rod shapes and the trap (does the rod fit in the gap, does the trap fit in the cell) run in
// compile(). Defaults are resolved here, so a ScenarioSpec written back out is complete.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/diagnostic.hpp"
#include "scenarios/section_reader.hpp"
#include "scenarios/source_node.hpp"
#include "scenarios/sourced.hpp"

namespace rodsort::scenarios {

struct ShapeSpec {
  enum class Kind { preset, taper, stepped, spheres };
  Kind kind = Kind::preset;
  Sourced<std::string> preset;         ///< "A" or "RnT"
  Sourced<double> thick_radius;        ///< RnT's thick part [mm]
  Sourced<double> thin_radius;         ///< RnT's thin part [mm]
  Sourced<double> step;                ///< RnT's step, from the thick tip [mm]
  Sourced<double> thin_offset;         ///< RnT's thin axis from the thick one's [mm]
  Sourced<double> bend;                ///< RnT's largest offset from the line of its tips [mm]
  Sourced<std::string> bend_form;      ///< "arc" or "s"
  Sourced<double> taper_length;        ///< tip to tip [mm]
  Sourced<double> taper_thick_radius;  ///< [mm]
  Sourced<double> taper_thin_radius;   ///< [mm]
  Sourced<std::int64_t> taper_spheres;
  Sourced<double> stepped_length;                       ///< tip to tip [mm]
  Sourced<std::vector<double>> stepped_radii;           ///< each section's, thick end first [mm]
  Sourced<std::vector<double>> stepped_steps;           ///< where each next section begins [mm]
  Sourced<std::vector<std::array<double, 3>>> spheres;  ///< [axial, radius, lateral] [mm]
  SourceLocation where;
  std::string path;
};

struct SpeciesSpec {
  Sourced<std::string> name;
  ShapeSpec shape;
  Sourced<double> density;  ///< [g/mm^3]
  Sourced<std::string> material;
  Sourced<NumberOrKeyword> count;  ///< a number, or "auto"
  std::optional<Sourced<double>> fraction;
  Sourced<double> kick_eps;                  ///< [1/mm]
  Sourced<double> white_Dr;                  ///< [rad^2/s]
  Sourced<std::string> initial_region;       ///< anywhere, inside_trap, outside_trap
  Sourced<NumberOrKeyword> initial_heading;  ///< [degrees], or random, toward_apex
  SourceLocation where;
  std::string path;

  bool auto_count() const { return count.value.is("auto"); }
};

struct TrapSpec {
  Sourced<double> angle;                               ///< opening angle [degrees]
  Sourced<double> arm_length;                          ///< [mm]
  Sourced<double> wall_thickness;                      ///< [mm]
  std::optional<Sourced<std::array<double, 2>>> apex;  ///< [mm]; centred when absent
  Sourced<double> direction;                           ///< of the bisector, from +x [degrees]
  SourceLocation where;
};

/// One row of the pair table as written: "rod-wall: {friction: 0.03}".
struct MaterialPairSpec {
  std::string first, second;  ///< material names
  std::optional<Sourced<double>> friction;
  std::optional<Sourced<double>> restitution;
  SourceLocation where;
  std::string path;
};

struct ScenarioSpec {
  Sourced<std::string> name;
  Sourced<std::int64_t> seed;
  Sourced<std::array<double, 2>> box_size;  ///< [mm]
  Sourced<std::string> cell_shape;          ///< "periodic", "circle" or "flower"
  Sourced<double> cell_diameter;            ///< [mm]
  Sourced<std::int64_t> cell_petals;
  Sourced<double> cell_petal_depth;     ///< [mm]
  Sourced<double> cell_wall_thickness;  ///< [mm]

  Sourced<double> frequency;  ///< [Hz]
  /// Exactly one of gamma and amplitude is set (gamma = 7 when neither was written).
  std::optional<Sourced<double>> gamma;
  std::optional<Sourced<double>> amplitude;  ///< [mm]
  Sourced<double> gap;                       ///< [mm]
  Sourced<double> base_slope, lid_slope;     ///< RMS slopes of the plates [rad]
  Sourced<double> roughness_wavelength;      ///< [mm]

  Sourced<double> trap_area_ratio;
  std::optional<Sourced<double>> area_fraction;

  std::vector<SpeciesSpec> species;
  SourceLocation species_where;
  std::optional<TrapSpec> trap;  ///< absent for `trap: none`
  std::vector<MaterialPairSpec> materials;

  Sourced<double> duration;  ///< [s]
  Sourced<double> dt;        ///< [s]
  Sourced<std::int64_t> solver_iterations;
  Sourced<std::string> turn_correction;  ///< "tenth" or "full"
  Sourced<std::string> contact_solver;   ///< "sweeps" or "exact"

  Sourced<double> frame_interval;                 ///< [s]
  Sourced<std::string> rods_format;               ///< "csv", "h5md" or "both"
  Sourced<std::string> h5md_precision;            ///< "single" or "double"
  Sourced<double> trajectory_interval;            ///< [s]; 0: none
  Sourced<std::string> trajectory_style;          ///< "plain" or "named"
  Sourced<std::vector<double>> bullet_snapshots;  ///< [s]
  Sourced<double> checkpoint_interval;            ///< [s]

  Sourced<double> metrics_window;        ///< [s]
  Sourced<double> stationary_threshold;  ///< [mm/s]
  Sourced<double> held_distance;         ///< [mm]
  Sourced<double> held_lag;              ///< [s]
};

/// Reads a scenario tree: unknown keys, types, ranges, and the consistency of keys that go
/// together. `default_name` names the scenario when it has no `name` (the file's stem).
ScenarioSpec read_scenario_spec(const SourceNode& root, const std::string& default_name,
                                Diagnostics& diagnostics);

/// Names of the materials a scenario knows: the fixed ones, "rod", then the species' new ones.
std::vector<std::string> material_names(const ScenarioSpec& spec);

}  // namespace rodsort::scenarios
