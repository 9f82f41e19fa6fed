#include "scenarios/scenario_spec.hpp"

#include <algorithm>
#include <cmath>

#include "engine/materials.hpp"
#include "scenarios/key_check.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/schema.hpp"

namespace rodsort::scenarios {
namespace {

/// Says which earlier key a conflicting one clashes with.
std::string also_at(const SourceLocation& where) { return " (set at " + where.to_string() + ")"; }

ShapeSpec read_shape(SectionReader shape, Diagnostics& diagnostics) {
  ShapeSpec out;
  out.where = shape.where();
  out.path = shape.path();
  const bool has_preset = shape.has("preset");
  const bool has_taper = shape.has("taper");
  const bool has_stepped = shape.has("stepped");
  const bool has_spheres = shape.has("spheres");
  if (int(has_preset) + int(has_taper) + int(has_stepped) + int(has_spheres) > 1) {
    diagnostics.error(shape.where(), shape.path(),
                      "give one of preset, taper, stepped or spheres, not several");
  }
  out.thick_radius = shape.real("thick_radius");
  out.thin_radius = shape.real("thin_radius");
  out.step = shape.real("step");
  out.thin_offset = shape.real("thin_offset");
  out.bend = shape.real("bend");
  out.bend_form = shape.choice("bend_form");
  if (has_taper) {
    out.kind = ShapeSpec::Kind::taper;
    SectionReader taper = shape.section("taper");
    out.taper_length = taper.required_real("length", "with taper");
    out.taper_thick_radius = taper.required_real("thick_radius", "with taper");
    out.taper_thin_radius = taper.required_real("thin_radius", "with taper");
    out.taper_spheres = taper.integer("spheres");
  } else if (has_stepped) {
    out.kind = ShapeSpec::Kind::stepped;
    SectionReader stepped = shape.section("stepped");
    out.stepped_length = stepped.required_real("length", "with stepped");
    if (stepped.has("radii")) {
      out.stepped_radii = stepped.real_list("radii");
    } else {
      diagnostics.error(stepped.where(), stepped.path_of("radii"),
                        "missing; with stepped it is required (a list of the sections' radii in "
                        "mm, thick end first)");
    }
    out.stepped_steps = stepped.real_list("steps");
  } else if (has_spheres && !has_preset) {
    out.kind = ShapeSpec::Kind::spheres;
    out.spheres = *shape.sphere_list("spheres");
  } else {
    out.kind = ShapeSpec::Kind::preset;
    out.preset = shape.choice("preset");
    if (!out.preset.given) out.preset.value = "A";
  }
  const bool rnt = out.kind == ShapeSpec::Kind::preset && out.preset.value == "RnT";
  if (shape.has("thick_radius") && !rnt) {
    diagnostics.error(shape.location_of("thick_radius"), shape.path_of("thick_radius"),
                      "applies to `preset: RnT` only (use taper.thick_radius for a taper)");
  }
  if (shape.has("thin_radius") && !rnt) {
    diagnostics.error(shape.location_of("thin_radius"), shape.path_of("thin_radius"),
                      "applies to `preset: RnT` only (use taper.thin_radius for a taper)");
  }
  if (shape.has("step") && !rnt) {
    diagnostics.error(shape.location_of("step"), shape.path_of("step"),
                      "applies to `preset: RnT` only");
  }
  for (const char* key : {"thin_offset", "bend", "bend_form"}) {
    if (shape.has(key) && !rnt) {
      diagnostics.error(shape.location_of(key), shape.path_of(key),
                        "applies to `preset: RnT` only");
    }
  }
  return out;
}

SpeciesSpec read_species(SectionReader species, std::size_t index, Diagnostics& diagnostics) {
  SpeciesSpec out;
  out.where = species.where();
  out.path = species.path();
  out.shape = read_shape(species.section("shape"), diagnostics);
  out.name = species.text("name");
  if (!out.name.given) {
    out.name.value = out.shape.kind == ShapeSpec::Kind::preset ? out.shape.preset.value
                                                               : "species" + std::to_string(index);
  }
  out.density = species.real("density");
  out.material = species.text("material");
  out.count = species.number_or_keyword("count");
  out.fraction = species.optional_real("fraction");
  if (out.fraction && !out.auto_count()) {
    diagnostics.error(
        out.fraction->where, out.fraction->path,
        "applies to `count: auto` only, but count is " + format_real(out.count.value.number));
  }
  SectionReader noise = species.section("noise");
  out.kick_eps = noise.real("kick_eps");
  out.white_Dr = noise.real("white_Dr");
  SectionReader initial = species.section("initial");
  out.initial_region = initial.choice("region");
  out.initial_heading = initial.number_or_keyword("heading");
  return out;
}

void check_species(const std::vector<SpeciesSpec>& species, const SourceLocation& where,
                   Diagnostics& diagnostics) {
  if (species.empty()) {
    diagnostics.error(where, "species", "needs at least one species");
    return;
  }
  // Each species is a colour, columns of metrics.csv and a line of every plot.
  constexpr std::size_t kMaxSpecies = 64;
  if (species.size() > kMaxSpecies) {
    diagnostics.error(where, "species",
                      "expected at most " + std::to_string(kMaxSpecies) + " species, got " +
                          std::to_string(species.size()));
    return;
  }
  for (std::size_t i = 0; i < species.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (species[i].name.value == species[j].name.value) {
        diagnostics.error(species[i].name.given ? species[i].name.where : species[i].where,
                          species[i].path + ".name",
                          "duplicate species name \"" + species[i].name.value + "\" (also " +
                              species[j].path + "); give each species its own name");
      }
    }
  }
  std::vector<const SpeciesSpec*> auto_counted;
  for (const SpeciesSpec& s : species) {
    if (s.auto_count()) auto_counted.push_back(&s);
  }
  if (auto_counted.size() < 2) return;
  double total = 0.0;
  for (const SpeciesSpec* s : auto_counted) {
    if (!s->fraction) {
      diagnostics.error(s->where, s->path + ".fraction",
                        "missing; several species have `count: auto`, so each needs its number "
                        "fraction among them");
      return;
    }
    total += s->fraction->value;
  }
  if (std::abs(total - 1.0) > 1e-9) {
    diagnostics.error(
        where, "species",
        "the fractions of the species counted auto must add up to 1, got " + format_real(total));
  }
}

std::optional<TrapSpec> read_trap(const SectionReader& root, SectionReader trap) {
  // `none`, and a value that is not a section (already reported), make no trap.
  const SourceNode* node = root.node("trap");
  if (node == nullptr || !node->is_map()) return std::nullopt;
  TrapSpec out;
  out.where = trap.where();
  out.angle = trap.required_real("angle", "with a trap");
  out.arm_length = trap.real("arm_length");
  out.wall_thickness = trap.real("wall_thickness");
  out.apex = trap.optional_real_pair("apex");
  out.direction = trap.real("direction");
  return out;
}

std::vector<MaterialPairSpec> read_materials(SectionReader materials,
                                             const std::vector<std::string>& names,
                                             Diagnostics& diagnostics) {
  std::vector<std::string_view> name_views(names.begin(), names.end());
  std::vector<MaterialPairSpec> out;
  for (const std::string& key : materials.keys()) {
    const SourceLocation key_where = materials.key_location(key);
    const std::string path = materials.path_of(key);
    const std::size_t dash = key.find('-');
    if (dash == std::string::npos || key.find('-', dash + 1) != std::string::npos) {
      diagnostics.error(
          key_where, path,
          "expected a pair of materials `a-b` (materials: " + join_words(name_views) + ")");
      continue;
    }
    MaterialPairSpec pair;
    pair.first = key.substr(0, dash);
    pair.second = key.substr(dash + 1);
    pair.where = key_where;
    pair.path = path;
    bool known = true;
    for (const std::string& name : {pair.first, pair.second}) {
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        diagnostics.error(key_where, path, unknown_word_message("material", name, name_views));
        known = false;
      }
    }
    SectionReader coefficients = materials.section(key);
    pair.friction = coefficients.optional_real("friction");
    pair.restitution = coefficients.optional_real("restitution");
    if (!known) continue;
    const auto fixed = [&](const std::string& name) {
      return engine::MaterialTable::paper().index_of(name) < engine::MaterialTable::kFirstRod &&
             engine::MaterialTable::paper().index_of(name) >= 0;
    };
    if (fixed(pair.first) && fixed(pair.second)) {
      diagnostics.error(key_where, path,
                        "base, lid and wall never touch each other; a pair needs a rod material");
      continue;
    }
    for (const MaterialPairSpec& earlier : out) {
      if ((earlier.first == pair.first && earlier.second == pair.second) ||
          (earlier.first == pair.second && earlier.second == pair.first)) {
        diagnostics.error(key_where, path,
                          "the same pair as " + earlier.path + also_at(earlier.where));
      }
    }
    out.push_back(std::move(pair));
  }
  return out;
}

}  // namespace

std::vector<std::string> material_names(const ScenarioSpec& spec) {
  std::vector<std::string> names = engine::MaterialTable::paper().names();
  for (const SpeciesSpec& species : spec.species) {
    if (std::find(names.begin(), names.end(), species.material.value) == names.end()) {
      names.push_back(species.material.value);
    }
  }
  return names;
}

ScenarioSpec read_scenario_spec(const SourceNode& root, const std::string& default_name,
                                Diagnostics& diagnostics) {
  const Schema& schema = scenario_schema();
  check_keys(root, schema, diagnostics);
  if (!root.is_map() && !root.is_null()) {
    diagnostics.error(root.where, "", "expected a map of scenario keys, got " + root.describe());
  }
  SectionReader top(schema, &root, "", "", root.where, diagnostics);
  ScenarioSpec spec;

  spec.name = top.text("name");
  if (!spec.name.given) spec.name.value = default_name;
  spec.seed = top.integer("seed");
  spec.box_size = top.section("box").real_pair("size");
  SectionReader cell = top.section("cell");
  spec.cell_shape = cell.choice("shape");
  spec.cell_diameter = cell.real("diameter");
  spec.cell_petals = cell.integer("petals");
  spec.cell_petal_depth = cell.real("petal_depth");
  spec.cell_wall_thickness = cell.real("wall_thickness");

  SectionReader drive = top.section("drive");
  spec.frequency = drive.real("frequency");
  spec.gamma = drive.optional_real("gamma");
  spec.amplitude = drive.optional_real("amplitude");
  if (spec.gamma && spec.amplitude) {
    diagnostics.error(
        spec.amplitude->where, spec.amplitude->path,
        "give gamma or amplitude, not both (gamma" + also_at(spec.gamma->where) + ")");
  } else if (!spec.gamma && !spec.amplitude) {
    spec.gamma = drive.real("gamma");
  }
  spec.gap = drive.real("gap");

  SectionReader roughness = top.section("roughness");
  spec.base_slope = roughness.real("base_slope");
  spec.lid_slope = roughness.real("lid_slope");
  spec.roughness_wavelength = roughness.real("wavelength");

  SectionReader population = top.section("population");
  spec.trap_area_ratio = population.real("trap_area_ratio");
  spec.area_fraction = population.optional_real("area_fraction");
  if (spec.area_fraction && spec.trap_area_ratio.given) {
    diagnostics.error(spec.area_fraction->where, spec.area_fraction->path,
                      "give trap_area_ratio or area_fraction, not both (trap_area_ratio" +
                          also_at(spec.trap_area_ratio.where) + ")");
  }

  spec.species_where = top.location_of("species");
  std::vector<SectionReader> species = top.list("species");
  for (std::size_t i = 0; i < species.size(); ++i) {
    spec.species.push_back(read_species(species[i], i, diagnostics));
  }
  const SourceNode* species_node = top.node("species");
  if (species_node == nullptr || species_node->is_sequence()) {
    check_species(spec.species, spec.species_where, diagnostics);
  }

  spec.trap = read_trap(top, top.section("trap"));
  spec.materials = read_materials(top.section("materials"), material_names(spec), diagnostics);

  SectionReader run = top.section("run");
  spec.duration = run.real("duration");
  spec.dt = run.real("dt");
  spec.solver_iterations = run.integer("solver_iterations");
  spec.turn_correction = run.choice("turn_correction");
  spec.contact_solver = run.choice("contact_solver");

  SectionReader output = top.section("output");
  spec.frame_interval = output.real("frame_interval");
  spec.rods_format = output.choice("rods_format");
  spec.h5md_precision = output.choice("h5md_precision");
  spec.trajectory_interval = output.real("trajectory_interval");
  spec.trajectory_style = output.choice("trajectory_style");
  spec.bullet_snapshots = output.real_list("bullet_snapshots");
  spec.checkpoint_interval = output.real("checkpoint_interval");

  SectionReader metrics = top.section("metrics");
  spec.metrics_window = metrics.real("window");
  spec.stationary_threshold = metrics.real("stationary_threshold");
  spec.held_distance = metrics.real("held_distance");
  spec.held_lag = metrics.real("held_lag");
  return spec;
}

}  // namespace rodsort::scenarios
