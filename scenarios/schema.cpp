#include "scenarios/schema.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "scenarios/number_text.hpp"

namespace rodsort::scenarios {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr Range any_number() { return {}; }
constexpr Range positive() { return {0.0, kInf, true, false}; }
constexpr Range non_negative() { return {0.0, kInf, false, false}; }
constexpr Range closed(double min, double max) { return {min, max, false, false}; }
constexpr Range open(double min, double max) { return {min, max, true, true}; }
constexpr Range half_open(double min, double max) { return {min, max, true, false}; }

using V = ValueType;

// One row per key, kept as a table by hand.
// clang-format off
// The scenario format. Defaults are the paper's (Kumar et al., "Sorting motile rods by activity").
std::vector<KeyInfo> scenario_keys() {
  return {
      {"name", V::text, "", "", {}, {}, "Name of the run: letters, digits, '.', '_' and '-'.",
       "the file name without .yaml"},
      {"seed", V::integer, "", "1", closed(0, 9.0e18), {},
       "Seed of every random stream: initial placement, collision kicks, white noise."},

      {"box", V::section, "", "", {}, {},
       "The periodic cell, or the box around a bounded one (cell.shape)."},
      {"box.size", V::real_pair, "mm", "[86.85, 86.85]", half_open(0, 1.0e6), {},
       "Sides of the cell in x and y, periodic in both; one number for a square. Paper: 19.3 rod "
       "lengths. At most 1e6 mm, where doubles still resolve a position to 1e-10 mm, a "
       "ten-millionth of a rod's travel in one step.",
       "[86.85, 86.85]; around a bounded cell, the smallest square that holds it"},

      {"cell", V::section, "", "", {}, {},
       "What bounds the rods: the periodic box (the paper's simulations), or a wall closing a "
       "disc (its experiments' cell, 13 cm across with a flower-shaped wall)."},
      {"cell.shape", V::choice, "", "periodic", {}, {"periodic", "circle", "flower"},
       "`periodic`: the box, periodic in x and y. `circle`: a circular wall of cell.diameter. "
       "`flower`: a wall of cell.petals circular scallops bulging outward, which turns rods "
       "sliding along it back into the bulk at the cusps. The box then defaults to the "
       "smallest square that holds the wall clear of its periodic edges by a rod's reach, and "
       "the trap is centred in the cell."},
      {"cell.diameter", V::real, "mm", "130", half_open(0, 1.0e5), {},
       "Inner diameter of a circular wall, or of the circle through a flower's petal tips. "
       "Paper's experiments: 13 cm."},
      {"cell.petals", V::integer, "", "16", closed(3, 10000), {},
       "Number of scallops of a flower wall; the paper does not give it."},
      {"cell.petal_depth", V::real, "mm", "5", positive(), {},
       "Radial depth of a flower's scallops, from the cusps out to the petal tips; at most the "
       "depth at which the cusps turn the wall by a right angle (5.1 mm for 16 petals on "
       "130 mm, 9.9 for 8). The paper does not give it."},
      {"cell.wall_thickness", V::real, "mm", "1", positive(), {},
       "Thickness of the cell's wall, which lies outside the disc."},

      {"drive", V::section, "", "", {}, {}, "Vertical vibration of base and lid."},
      {"drive.frequency", V::real, "Hz", "200", half_open(0, 5.0e5), {},
       "f: base height z_b(t) = A cos(2 pi f t), lid at z_b(t) + gap. At most 5e5 Hz: 20 steps "
       "per period at the shortest run.dt."},
      {"drive.gamma", V::real, "", "7", positive(), {},
       "Dimensionless peak acceleration Gamma = A (2 pi f)^2 / g. Give gamma or amplitude, not "
       "both.",
       "7, unless amplitude is given"},
      {"drive.amplitude", V::real, "mm", "", positive(), {},
       "A, the amplitude of the base's motion, instead of gamma.",
       "from gamma (0.0435 at the paper's 7 and 200 Hz)"},
      {"drive.gap", V::real, "mm", "1.2", positive(), {},
       "w: height of the lid above the base. Rods stop propelling when their thick end no longer "
       "reaches the lid."},

      {"roughness", V::section, "", "", {}, {},
       "Rough plates: a fixed random height field on the base and the lid (docs/model.md, "
       "\"Rough plates\"). The paper's plates are flat."},
      {"roughness.base_slope", V::real, "rad", "0", closed(0, 0.3), {},
       "RMS slope of the base's surface; 0 is flat."},
      {"roughness.lid_slope", V::real, "rad", "0", closed(0, 0.3), {},
       "RMS slope of the lid's surface; 0 is flat."},
      {"roughness.wavelength", V::real, "mm", "0.25", positive(), {},
       "Mean wavelength of the height field (wavenumbers spread over 0.5-1.5 times 2 pi / "
       "wavelength); RMS height = slope x wavelength / (2 pi), about."},

      {"population", V::section, "", "", {}, {}, "How many rods `count: auto` makes."},
      {"population.trap_area_ratio", V::real, "", "1.2", positive(), {},
       "r = phi_r / F: total projected area of the species counted `auto`, divided by the trap "
       "area A_t, so N = round(r A_t / a) for one species. Paper: 1.2, which keeps the trap from "
       "exhausting the rods."},
      {"population.area_fraction", V::real, "", "", open(0, 1), {},
       "phi_r: total projected area of the species counted `auto`, divided by the cell's area. "
       "Replaces trap_area_ratio; needed for `count: auto` when `trap: none`.",
       "none"},

      {"species", V::section_list, "", "[{name: A, shape: {preset: A}}]", {}, {},
       "The kinds of rods, each with its shape, count and noise.",
       "one species: rod A, count auto"},
      {"species[].name", V::text, "", "", {}, {},
       "Name of the species, used in output columns; unique.",
       "the preset's name, else species<i>"},
      {"species[].shape", V::section, "", "", {}, {},
       "Profile of the rod: a `preset`, a `taper`, a `stepped` rod, or explicit `spheres` (one of "
       "the four)."},
      {"species[].shape.preset", V::choice, "", "", {}, {"A", "RnT"},
       "A: the paper's rod, 9 spheres with radii 0.55 -> 0.20 mm, 4.5 mm tip to tip. RnT: 3.5 mm, "
       "r = thick_radius from the thick tip to the step, r = thin_radius beyond it.",
       "A, when no taper, stepped or spheres is given"},
      {"species[].shape.thick_radius", V::real, "mm", "0.55", half_open(0, 1.75), {},
       "Radius of the thick part of the RnT preset (RnT only): the paper's 1.1 mm thick. With the "
       "lid it sets RnT's clearance (docs/model.md, \"The clearance to the lid\")."},
      {"species[].shape.thin_radius", V::real, "mm", "0.3", positive(), {},
       "Radius of the thin part of the RnT preset (RnT only), at most thick_radius; the preset's "
       "spheres, at most 0.872 radii apart, may number 200 at most."},
      {"species[].shape.step", V::real, "mm", "1.75", positive(), {},
       "Where the RnT preset's single step lies, from its thick tip (RnT only; the paper gives no "
       "figure, mid-length by default). From thick_radius + sqrt(thick_radius^2 - thin_radius^2) "
       "to 3.5 - thin_radius: one whole sphere on each side. Moved back from mid-length (to 3 mm), or "
       "with other radii, RnT's gait may change with run.dt and the solver's sweeps, and validate "
       "warns above run.dt = 6.25e-6 s or below 30 sweeps (docs/model.md, \"Where the RnT's step "
       "lies\")."},
      {"species[].shape.thin_offset", V::real, "mm", "0", non_negative(), {},
       "How far the RnT preset's thin part lies off the thick part's axis, parallel to it (RnT "
       "only): 0, the paper's straight rod, by default. At most thick_radius - thin_radius, so "
       "that the rod stays thick_radius wide. An offset breaks the rod's mirror symmetry about "
       "its axis (docs/model.md, \"An RnT whose thin part is off its axis\")."},
      {"species[].shape.bend", V::real, "mm", "0", closed(0, 0.5), {},
       "How far the RnT preset is bent in the plane of its roll, its largest offset from the "
       "straight line through its tips (RnT only): 0, the paper's straight rod, by default. The "
       "rod must fit in the gap at every roll (docs/model.md, \"A bent RnT\")."},
      {"species[].shape.bend_form", V::choice, "", "arc", {}, {"arc", "s"},
       "The form of the bend (RnT only): `arc`, bulging by `bend` at mid-length, the tips on the "
       "straight line; `s`, one sine wave, the thick half to one side and the thin half to the "
       "other by `bend`, the tips and mid-length on the line."},
      {"species[].shape.taper", V::section, "", "", {}, {},
       "A linear taper: spheres with radii linear from the thick to the thin end."},
      {"species[].shape.taper.length", V::real, "mm", "", positive(), {},
       "Tip to tip (required with taper)."},
      {"species[].shape.taper.thick_radius", V::real, "mm", "", positive(), {},
       "Radius of the sphere at the thick end (required with taper)."},
      {"species[].shape.taper.thin_radius", V::real, "mm", "", positive(), {},
       "Radius of the sphere at the thin end (required with taper)."},
      {"species[].shape.taper.spheres", V::integer, "", "9", closed(2, 200), {},
       "Number of spheres, evenly spaced."},
      {"species[].shape.stepped", V::section, "", "", {}, {},
       "A rod of cylinders in steps, thick end first, each section built as the RnT preset's two: "
       "spheres evenly spaced at most 0.872 radii apart, the last placed so that its outline comes "
       "down to the next radius exactly at the step, the next section's first centred on the "
       "step; at most 200 spheres. `{length: 3.5, radii: [0.55, 0.3], steps: [1.75]}` is the RnT "
       "preset."},
      {"species[].shape.stepped.length", V::real, "mm", "", positive(), {},
       "Tip to tip (required with stepped)."},
      {"species[].shape.stepped.radii", V::real_list, "mm", "", positive(), {},
       "Each section's radius, from the thick end; none larger than the one before (required "
       "with stepped)."},
      {"species[].shape.stepped.steps", V::real_list, "mm", "[]", positive(), {},
       "Where each next section begins, from the thick tip, growing: one fewer than the radii, "
       "each leaving room for one whole sphere on either side."},
      {"species[].shape.spheres", V::sphere_list, "mm", "", any_number(), {},
       "Explicit spheres [axial position, radius], the axial position growing from the thick to "
       "the thin end (any origin), each with an optional third number, its centre's offset from "
       "the axis in the rod's plane (0 when left out), for a bent rod: [axial, radius, lateral]. "
       "The offsets may span at most the thickest sphere's diameter, and the rod must fit in the "
       "gap at every roll about its axis, which placement draws at random for a rod with offsets "
       "(docs/model.md, \"A bent RnT\").",
       "none"},
      {"species[].density", V::real, "g/mm^3", "8.5e-3", closed(1.0e-6, 0.03), {},
       "Density of the rod's material (brass). From air's (1.2e-6) to beyond osmium's (0.0226), "
       "the densest element."},
      {"species[].material", V::text, "", "rod", {}, {},
       "Contact material of the rods in the `materials` pair table; a new name starts with the "
       "values of `rod`."},
      {"species[].count", V::integer, "", "auto", closed(0, 1.0e6), {"auto"},
       "Number of rods, or `auto`: the species counted auto share the area set by `population` "
       "(split by `fraction`)."},
      {"species[].fraction", V::real, "", "", half_open(0, 1), {},
       "Number fraction of this species among those counted `auto`; required when several are, "
       "and then they must add up to 1.",
       "1 when it is the only species counted auto"},
      {"species[].noise", V::section, "", "", {}, {}, "Angular noise of the rods."},
      {"species[].noise.kick_eps", V::real, "1/mm", "0.01", non_negative(), {},
       "Collision kick: at every impact on base or lid, omega_z += s eps v_rel, s = +-1. Paper: "
       "0.01."},
      {"species[].noise.white_Dr", V::real, "rad^2/s", "0", non_negative(), {},
       "White angular noise: rotational diffusion coefficient D_r (the paper's sorting runs)."},
      {"species[].initial", V::section, "", "", {}, {}, "Where the rods start."},
      {"species[].initial.region", V::choice, "", "anywhere", {},
       {"anywhere", "inside_trap", "outside_trap"},
       "Where the centres of the rods are drawn, uniformly; never overlapping a wall or a rod."},
      {"species[].initial.heading", V::real, "degrees", "random", closed(-360, 360),
       {"random", "toward_apex"},
       "Direction from the thick to the thin end, from +x: isotropic (`random`), pointing at the "
       "trap's apex (`toward_apex`), or this angle."},

      {"trap", V::section_or_none, "", "none", {}, {"none"},
       "The V-shaped trap: two thin walls spanning the gap, or `none`."},
      {"trap.angle", V::real, "degrees", "", open(0, 180), {},
       "Opening angle theta between the arms (required with a trap). Paper: 20 to 160."},
      {"trap.arm_length", V::real, "mm", "45", positive(), {},
       "L, along the inner face from the apex. Paper: 10 rod lengths. A_t = L^2 sin(theta) / 2."},
      {"trap.wall_thickness", V::real, "mm", "1", positive(), {},
       "Thickness of the walls, which lie outside the triangle A_t."},
      {"trap.apex", V::real_pair, "mm", "", any_number(), {},
       "Position of the apex in the cell.",
       "centred: apex and middle of the opening equally far from the cell's centre"},
      {"trap.direction", V::real, "degrees", "45", closed(-360, 360), {},
       "Direction of the bisector from the apex into the opening, from +x. Along the cell's "
       "diagonal (45) the paper's widest traps (160 degrees, 45 mm arms) fit in its 86.85 mm "
       "cell; along an edge (0) only those up to 125 degrees do."},

      {"materials", V::free_map, "", "{}", {}, {},
       "Pair table of contact coefficients, keyed `a-b` by material names: base, lid, wall (the "
       "trap), rod, and the species' materials. Unlisted pairs keep their defaults.",
       "the paper's: rod-rod 0.05/0.3, rod-base 0.03/0.1, rod-lid 0.01/0.1, rod-wall 0.03/0.65"},
      {"materials.*", V::section, "", "", {}, {}, "Coefficients of one pair, e.g. `rod-wall`."},
      {"materials.*.friction", V::real, "", "", non_negative(), {}, "Coulomb friction coefficient.",
       "the pair's default"},
      {"materials.*.restitution", V::real, "", "", closed(0, 1), {},
       "Normal coefficient of restitution. With a rod's restitution above 0.65 against both the "
       "base and the lid, rods rattle between the plates and their gait changes with run.dt; "
       "validate warns above run.dt = 1.25e-5 s (docs/model.md, \"Restitution of base and lid "
       "together\").",
       "the pair's default"},

      {"run", V::section, "", "", {}, {}, "Length and time step of the simulation."},
      {"run.duration", V::real, "s", "300", positive(), {}, "Simulated time."},
      {"run.dt", V::real, "s", "1.0e-4", closed(1.0e-7, 1.0), {},
       "Time step; at least 20 steps per drive period. Nothing that moves a rod may move a "
       "sphere by more than half the thinnest radius in one step (plates, kick, white noise)."},
      {"run.solver_iterations", V::integer, "", "10", closed(1, 1000), {},
       "Iterations of Bullet's contact solver per step; the rods' speed and D_r depend on it "
       "by 10-20% (docs/performance.md, section 4)."},
      {"run.turn_correction", V::choice, "", "tenth", {}, {"tenth", "full"},
       "How much of the turns of Bullet's position correction (split impulse) is applied: "
       "`tenth`, Bullet's default, the white noise turning rods after each step; `full`, all, "
       "the white noise turned through the correction so that contacts resist it. `full` halves "
       "the white noise's overlaps and makes rod A's v0 depend less on dt, but changes the RnT "
       "rod's gait at the default dt (docs/model.md, \"Checks while a run goes\")."},
      {"run.contact_solver", V::choice, "", "sweeps", {}, {"sweeps", "exact"},
       "How each step's contacts are solved: `sweeps`, Bullet's sequential impulses "
       "(run.solver_iterations sweeps); `exact`, as one linear complementarity problem by "
       "Dantzig's algorithm (Bullet's MLCP solver) with a compliance of 1e-8 s/g that keeps "
       "every problem solvable. Its cost grows as the cube of the contacts solved together: "
       "for lone rods (rodsort single), to check a result against an exact solve "
       "(docs/model.md, \"An exact contact solve\")."},

      {"output", V::section, "", "", {}, {}, "What the run writes, and how often."},
      {"output.frame_interval", V::real, "s", "0.07", positive(), {},
       "Interval between frames in rods.csv (the paper's camera: 0.07 s); a multiple of dt."},
      {"output.rods_format", V::choice, "", "csv", {}, {"csv", "h5md", "both"},
       "The file of frames: `csv`, rods.csv, text with 9 significant digits; `h5md`, rods.h5, "
       "HDF5 laid out as H5MD, compressed, several times smaller and faster to load (h5py, "
       "MDAnalysis); `both`. The run's metrics are computed from the frames as the first of these "
       "files holds them, so that `rodsort analyze` gives them back exactly."},
      {"output.h5md_precision", V::choice, "", "single", {}, {"single", "double"},
       "Floating-point precision of rods.h5: `single` (7 significant digits; 1e-5 mm on a 130 mm "
       "cell) or `double` (the simulation's own numbers, about twice the disk)."},
      {"output.trajectory_interval", V::real, "s", "0.7", non_negative(), {},
       "Interval between frames of the sphere trajectory for OVITO/VMD; 0 for none."},
      {"output.trajectory_style", V::choice, "", "plain", {}, {"plain", "named"},
       "trajectory.dump's flavour of the LAMMPS dump: `plain`, types numbered 1, 2, ... in "
       "species order, which every reader takes (OVITO, VMD, ASE, MDAnalysis); `named`, as "
       "LAMMPS writes with `dump_modify time yes types labels`: the species' names as types (OVITO "
       "lists A and RnT) and the simulated time in an ITEM: TIME block, which ASE and "
       "MDAnalysis cannot read."},
      {"output.bullet_snapshots", V::real_list, "s", "[]", non_negative(), {},
       "Simulated times at which to write .bullet snapshots of the world."},
      {"output.checkpoint_interval", V::real, "s", "10", positive(), {},
       "Simulated time between checkpoints (one is also written when the run is stopped)."},

      {"metrics", V::section, "", "", {}, {}, "Trapping measurements."},
      {"metrics.window", V::real, "s", "0.07", positive(), {},
       "tau: a rod's speed is its displacement over this window; a multiple of frame_interval (another value is rounded up to one, with a warning)."},
      {"metrics.stationary_threshold", V::real, "mm/s", "5", non_negative(), {},
       "A rod is stationary (the paper's zero velocity) when its speed is below this."},
      {"metrics.held_distance", V::real, "mm", "1", positive(), {},
       "A rod inside the trap is held when it moved less than this over held_lag: a pile's rods are, a rod passing through is not, however slow (the held columns of metrics.csv)."},
      {"metrics.held_lag", V::real, "s", "5", positive(), {},
       "The time over which a held rod moved less than held_distance; the held columns are nan until the run is this old."},

      {"derived", V::any, "", "", {}, {},
       "Values computed from the others (amplitude, rod counts, areas, masses), written into "
       "resolved scenarios for the record; ignored when read.",
       "none"},
  };
}

std::vector<KeyInfo> sweep_keys() {
  return {
      {"name", V::text, "", "", {}, {}, "Name of the sweep: letters, digits, '.', '_' and '-'.",
       "the file name without .yaml"},
      {"base", V::any, "", "", {}, {},
       "The scenario every point starts from: a file path, relative to the sweep file, or the "
       "scenario's keys inline (required)."},
      {"set", V::any, "", "{}", {}, {},
       "Values every point takes, on top of the base: a map from key paths to values "
       "(`run.duration: 1000`)."},
      {"grid", V::any, "", "", {}, {},
       "A list of axes; the points are every combination of one value per axis. An axis is a map "
       "from scenario key paths (`trap.angle`, `species[0].noise.kick_eps`) to lists of values; "
       "keys in one axis change together, so their lists have one length. A list may be written "
       "`{from: 20, to: 160, step: 10}` (both ends included) (required)."},
  };
}
// clang-format on

}  // namespace

bool Range::contains(double value) const {
  const bool above = min_open ? value > min : value >= min;
  const bool below = max_open ? value < max : value <= max;
  return above && below;
}

bool Range::unbounded() const { return std::isinf(min) && std::isinf(max); }

std::string Range::describe() const {
  if (unbounded()) return "";
  if (std::isinf(max)) return (min_open ? "> " : ">= ") + format_real(min);
  if (std::isinf(min)) return (max_open ? "< " : "<= ") + format_real(max);
  return std::string("in ") + (min_open ? "(" : "[") + format_real(min) + ", " + format_real(max) +
         (max_open ? ")" : "]");
}

Schema::Schema(std::string_view title, std::vector<KeyInfo> keys)
    : title_(title), keys_(std::move(keys)) {}

const KeyInfo* Schema::find(std::string_view path) const {
  const auto it = std::find_if(keys_.begin(), keys_.end(),
                               [&](const KeyInfo& key) { return key.path == path; });
  return it == keys_.end() ? nullptr : &*it;
}

const KeyInfo& Schema::at(std::string_view path) const {
  const KeyInfo* key = find(path);
  assert(key != nullptr && "every key the program reads is in the schema");
  return *key;
}

std::vector<const KeyInfo*> Schema::children(std::string_view parent) const {
  std::vector<const KeyInfo*> rows;
  for (const KeyInfo& key : keys_) {
    const std::size_t dot = key.path.rfind('.');
    const std::string_view key_parent =
        dot == std::string_view::npos ? std::string_view{} : key.path.substr(0, dot);
    if (key_parent == parent) rows.push_back(&key);
  }
  return rows;
}

const Schema& scenario_schema() {
  static const Schema schema("Scenario file", scenario_keys());
  return schema;
}

const Schema& sweep_schema() {
  static const Schema schema("Sweep file", sweep_keys());
  return schema;
}

std::string join_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return std::string(parent) + "." + std::string(key);
}

}  // namespace rodsort::scenarios
