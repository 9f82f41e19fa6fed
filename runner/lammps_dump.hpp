#pragma once
// trajectory.dump: the spheres of every rod as a LAMMPS text dump, which OVITO and VMD open as they
// are. Each sphere is an atom (id), each rod a molecule (mol), each species an atom type; the
// radius column lets both viewers draw the spheres at their true size. The cell is periodic in x
// and y and bounded in z by the plates' extreme positions ("pp pp ff").
//
// Two styles. `plain` is the dump every reader takes: numbered types (1, 2, ... in species order)
// and the nine header lines that MDAnalysis's reader counts on. `named` is what LAMMPS writes with
// `dump_modify time yes types labels`: an ITEM: TIME block with the simulated time before each
// ITEM: TIMESTEP, and the species' names in the type column, so that OVITO lists "A" and "RnT";
// readers that take the type as a number (ASE) or expect exactly nine header lines (MDAnalysis)
// cannot read it.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/frame.hpp"
#include "engine/model.hpp"

namespace rodsort::runner {

enum class DumpStyle { plain, named };

class LammpsDumpFormatter {
 public:
  /// `z_low`, `z_high`: the box's bounds in z [mm], constant over the run so viewers keep the view.
  LammpsDumpFormatter(const engine::Model& model, double z_low, double z_high,
                      DumpStyle style = DumpStyle::plain);

  /// One snapshot: ITEM: TIME (the simulated time in s; `named` only), ITEM: TIMESTEP (the step
  /// count), NUMBER OF ATOMS, BOX BOUNDS, ATOMS id mol type x y z radius. Positions in mm, from the
  /// rod's wrapped centre of mass and axis.
  std::string format(const engine::Frame& frame, std::int64_t step) const;

  /// The trap's walls for a viewer, as one snapshot of the same dump format (walls.dump, beside
  /// trajectory.dump): each wall a row of spheres as thick as the wall along its centre line,
  /// half a thickness apart, at mid-gap; mol is the wall's number, type 1 (`wall` when named).
  /// Empty without walls.
  std::string walls(const engine::Model& model) const;

 private:
  /// The header's first lines, to ITEM: TIMESTEP's value: the time (named) and the step.
  std::string header_start(double time_s, std::int64_t step) const;

  DumpStyle style_;
  std::vector<std::vector<engine::Sphere>> species_spheres_;
  std::vector<std::string> type_names_;  ///< the type column's text for each species
  std::size_t rod_count_ = 0;
  double box_x_, box_y_;   ///< [mm]
  double z_low_, z_high_;  ///< [mm]
  std::int64_t atom_count_ = 0;
};

}  // namespace rodsort::runner
