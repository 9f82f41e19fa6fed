// Writes a Scenario back as YAML with every default explicit. Numbers are written with the
// shortest text that reads back to the same double, and derived placements (the trap's apex) are
// written out, so that loading the written file compiles to the same Model, bit for bit.

#include <yaml-cpp/yaml.h>

#include "engine/units.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/scenario.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::scenarios {
namespace {

class Writer {
 public:
  Writer& key(const std::string& key) {
    out_ << YAML::Key << key << YAML::Value;
    return *this;
  }
  Writer& number(double value) {
    out_ << format_real(value);
    return *this;
  }
  Writer& whole(std::int64_t value) {
    out_ << std::to_string(value);
    return *this;
  }
  Writer& word(const std::string& value) {
    out_ << value;
    return *this;
  }
  Writer& pair(const std::array<double, 2>& value) {
    out_ << YAML::Flow << YAML::BeginSeq << format_real(value[0]) << format_real(value[1])
         << YAML::EndSeq;
    return *this;
  }
  /// A sphere as written: [axial, radius], with its lateral offset third where it has one.
  Writer& sphere(const std::array<double, 3>& value) {
    if (value[2] == 0.0) return pair({value[0], value[1]});
    out_ << YAML::Flow << YAML::BeginSeq << format_real(value[0]) << format_real(value[1])
         << format_real(value[2]) << YAML::EndSeq;
    return *this;
  }
  Writer& numbers(const std::vector<double>& values) {
    out_ << YAML::Flow << YAML::BeginSeq;
    for (const double value : values) out_ << format_real(value);
    out_ << YAML::EndSeq;
    return *this;
  }
  Writer& begin_map() {
    out_ << YAML::BeginMap;
    return *this;
  }
  Writer& end_map() {
    out_ << YAML::EndMap;
    return *this;
  }
  Writer& begin_list() {
    out_ << YAML::BeginSeq;
    return *this;
  }
  Writer& end_list() {
    out_ << YAML::EndSeq;
    return *this;
  }
  std::string text() const { return out_.c_str(); }

 private:
  YAML::Emitter out_;
};

void write_shape(Writer& w, const ShapeSpec& shape) {
  w.key("shape").begin_map();
  switch (shape.kind) {
    case ShapeSpec::Kind::preset:
      w.key("preset").word(shape.preset.value);
      if (shape.preset.value == "RnT") {
        w.key("thick_radius").number(shape.thick_radius.value);
        w.key("thin_radius").number(shape.thin_radius.value);
        w.key("step").number(shape.step.value);
        if (shape.thin_offset.value != 0.0) w.key("thin_offset").number(shape.thin_offset.value);
        if (shape.bend.value != 0.0) {
          w.key("bend").number(shape.bend.value);
          w.key("bend_form").word(shape.bend_form.value);
        }
      }
      break;
    case ShapeSpec::Kind::taper:
      w.key("taper").begin_map();
      w.key("length").number(shape.taper_length.value);
      w.key("thick_radius").number(shape.taper_thick_radius.value);
      w.key("thin_radius").number(shape.taper_thin_radius.value);
      w.key("spheres").whole(shape.taper_spheres.value);
      w.end_map();
      break;
    case ShapeSpec::Kind::stepped:
      w.key("stepped").begin_map();
      w.key("length").number(shape.stepped_length.value);
      w.key("radii").numbers(shape.stepped_radii.value);
      w.key("steps").numbers(shape.stepped_steps.value);
      w.end_map();
      break;
    case ShapeSpec::Kind::spheres:
      w.key("spheres").begin_list();
      for (const auto& sphere : shape.spheres.value) w.sphere(sphere);
      w.end_list();
      break;
  }
  w.end_map();
}

void write_species(Writer& w, const SpeciesSpec& species) {
  w.begin_map();
  w.key("name").word(species.name.value);
  write_shape(w, species.shape);
  w.key("density").number(species.density.value);
  w.key("material").word(species.material.value);
  w.key("count");
  if (species.auto_count()) {
    w.word("auto");
  } else {
    w.whole(static_cast<std::int64_t>(species.count.value.number));
  }
  if (species.fraction) w.key("fraction").number(species.fraction->value);
  w.key("noise").begin_map();
  w.key("kick_eps").number(species.kick_eps.value);
  w.key("white_Dr").number(species.white_Dr.value);
  w.end_map();
  w.key("initial").begin_map();
  w.key("region").word(species.initial_region.value);
  w.key("heading");
  const NumberOrKeyword& heading = species.initial_heading.value;
  if (heading.keyword.empty()) {
    w.number(heading.number);
  } else {
    w.word(heading.keyword);
  }
  w.end_map();
  w.end_map();
}

void write_materials(Writer& w, const engine::MaterialTable& table) {
  w.key("materials").begin_map();
  const auto count = static_cast<int>(table.names().size());
  for (int rod = engine::MaterialTable::kFirstRod; rod < count; ++rod) {
    for (int other = 0; other <= rod; ++other) {
      const engine::ContactCoefficients& c = table.get(rod, other);
      w.key(table.names()[static_cast<std::size_t>(rod)] + "-" +
            table.names()[static_cast<std::size_t>(other)]);
      w.begin_map().key("friction").number(c.friction).key("restitution").number(c.restitution);
      w.end_map();
    }
  }
  w.end_map();
}

void write_derived(Writer& w, const Scenario& scenario) {
  const engine::Model& model = scenario.model;
  const ScenarioSpec& spec = scenario.spec;
  w.key("derived").begin_map();
  if (spec.amplitude) {
    w.key("gamma").number(model.drive.gamma());
  } else {
    w.key("amplitude").number(model.drive.amplitude);
  }
  w.key("steps_per_drive_period").number(1.0 / (model.drive.frequency * model.dt));
  w.key("steps").whole(scenario.run.steps);
  if (scenario.trap) w.key("trap_area").number(scenario.trap_area);
  if (scenario.cell) w.key("cell_area").number(scenario.cell_area);
  double rod_area = 0.0;
  w.key("species").begin_list();
  for (std::size_t i = 0; i < scenario.species.size(); ++i) {
    const SpeciesDerived& derived = scenario.species[i];
    rod_area += derived.count * derived.projected_area;
    w.begin_map();
    w.key("name").word(model.species[i].name);
    w.key("count").whole(derived.count);
    w.key("projected_area").number(derived.projected_area);
    w.key("mass").number(derived.mass);
    w.key("length").number(derived.length);
    w.key("thickness").number(2.0 * model.species[i].shape.max_radius);
    // A rod that is not straight: the angle between its principal axis, which the rod's heading
    // and outputs follow, and the thick part's axis [rad].
    if (model.species[i].shape.axis_lean != 0.0) {
      w.key("axis_lean").number(model.species[i].shape.axis_lean);
    }
    w.end_map();
  }
  w.end_list();
  w.key("rods").whole(static_cast<std::int64_t>(model.rods.size()));
  w.key("area_fraction").number(rod_area / scenario.cell_area);
  w.end_map();
}

}  // namespace

std::string resolved_yaml(const Scenario& scenario) {
  const ScenarioSpec& spec = scenario.spec;
  Writer w;
  w.begin_map();
  w.key("name").word(spec.name.value);
  w.key("seed").whole(spec.seed.value);
  const engine::Model& model = scenario.model;
  w.key("box").begin_map().key("size").pair({model.box_x, model.box_y}).end_map();
  w.key("cell").begin_map();
  w.key("shape").word(spec.cell_shape.value);
  if (scenario.cell) {
    w.key("diameter").number(spec.cell_diameter.value);
    if (spec.cell_shape.value == "flower") {
      w.key("petals").whole(spec.cell_petals.value);
      w.key("petal_depth").number(spec.cell_petal_depth.value);
    }
    w.key("wall_thickness").number(spec.cell_wall_thickness.value);
  }
  w.end_map();

  w.key("drive").begin_map();
  w.key("frequency").number(spec.frequency.value);
  if (spec.amplitude) {
    w.key("amplitude").number(spec.amplitude->value);
  } else {
    w.key("gamma").number(spec.gamma->value);
  }
  w.key("gap").number(spec.gap.value);
  w.end_map();

  w.key("roughness").begin_map();
  w.key("base_slope").number(spec.base_slope.value);
  w.key("lid_slope").number(spec.lid_slope.value);
  w.key("wavelength").number(spec.roughness_wavelength.value);
  w.end_map();

  w.key("population").begin_map();
  if (spec.area_fraction) {
    w.key("area_fraction").number(spec.area_fraction->value);
  } else {
    w.key("trap_area_ratio").number(spec.trap_area_ratio.value);
  }
  w.end_map();

  w.key("species").begin_list();
  for (const SpeciesSpec& species : spec.species) write_species(w, species);
  w.end_list();

  w.key("trap");
  if (const auto* v_trap = dynamic_cast<const trap::VTrap*>(scenario.trap.get())) {
    const TrapSpec& t = *spec.trap;
    w.begin_map();
    w.key("angle").number(t.angle.value);
    w.key("arm_length").number(t.arm_length.value);
    w.key("wall_thickness").number(t.wall_thickness.value);
    w.key("apex").pair({v_trap->apex().x(), v_trap->apex().y()});
    w.key("direction").number(t.direction.value);
    w.end_map();
  } else {
    w.word("none");
  }

  write_materials(w, scenario.model.materials);

  w.key("run").begin_map();
  w.key("duration").number(spec.duration.value);
  w.key("dt").number(spec.dt.value);
  w.key("solver_iterations").whole(spec.solver_iterations.value);
  w.key("turn_correction").word(spec.turn_correction.value);
  w.key("contact_solver").word(spec.contact_solver.value);
  w.end_map();

  w.key("output").begin_map();
  w.key("frame_interval").number(spec.frame_interval.value);
  w.key("rods_format").word(spec.rods_format.value);
  w.key("h5md_precision").word(spec.h5md_precision.value);
  w.key("trajectory_interval").number(spec.trajectory_interval.value);
  w.key("trajectory_style").word(spec.trajectory_style.value);
  w.key("bullet_snapshots").numbers(spec.bullet_snapshots.value);
  w.key("checkpoint_interval").number(spec.checkpoint_interval.value);
  w.end_map();

  w.key("metrics").begin_map();
  w.key("window").number(spec.metrics_window.value);
  w.key("stationary_threshold").number(spec.stationary_threshold.value);
  w.key("held_distance").number(spec.held_distance.value);
  w.key("held_lag").number(spec.held_lag.value);
  w.end_map();

  write_derived(w, scenario);
  w.end_map();
  return "# Resolved by rodsort: every default explicit. `derived` is for the record and is\n"
         "# ignored when this file is read; reading it gives the same model.\n" +
         w.text() + "\n";
}

}  // namespace rodsort::scenarios
