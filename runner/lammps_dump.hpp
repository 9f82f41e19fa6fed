#pragma once
// trajectory.dump: the spheres of every rod as a LAMMPS text dump, which OVITO and VMD open as they
// are. Each sphere is an atom (id), each rod a molecule (mol), each species an atom type; the
// radius column lets both viewers draw the spheres at their true size. The cell is periodic in x
// and y and bounded in z by the plates' extreme positions ("pp pp ff").

#include <cstdint>
#include <string>
#include <vector>

#include "engine/frame.hpp"
#include "engine/model.hpp"

namespace rodsort::runner {

class LammpsDumpFormatter {
 public:
  /// `z_low`, `z_high`: the box's bounds in z [mm], constant over the run so viewers keep the view.
  LammpsDumpFormatter(const engine::Model& model, double z_low, double z_high);

  /// One snapshot: ITEM: TIMESTEP (the step count), NUMBER OF ATOMS, BOX BOUNDS, ATOMS
  /// id mol type x y z radius. Positions in mm, from the rod's wrapped centre of mass and axis.
  std::string format(const engine::Frame& frame, std::int64_t step) const;

  /// The trap's walls for a viewer, as one snapshot of the same dump format (walls.dump, beside
  /// trajectory.dump): each wall a row of spheres as thick as the wall along its centre line,
  /// half a thickness apart, at mid-gap; mol is the wall's number, type 1. Empty without walls.
  std::string walls(const engine::Model& model) const;

 private:
  std::vector<std::vector<engine::Sphere>> species_spheres_;
  std::size_t rod_count_ = 0;
  double box_x_, box_y_;   ///< [mm]
  double z_low_, z_high_;  ///< [mm]
  std::int64_t atom_count_ = 0;
};

}  // namespace rodsort::runner
