#pragma once
// Friction and restitution belong to a pair of materials, not to one body: rod-rod, rod-base,
// rod-lid and rod-trap each have their own values in the paper.

#include <string>
#include <vector>

namespace rodsort::engine {

struct ContactCoefficients {
  double friction;     ///< Coulomb coefficient, paper rod-rod: 0.05
  double restitution;  ///< normal coefficient of restitution, paper rod-rod: 0.3
};

/// Symmetric table of contact coefficients between named materials.
/// Indices 0..2 are fixed: base plate, lid, trap walls; rod materials follow.
class MaterialTable {
 public:
  static constexpr int kBase = 0;
  static constexpr int kLid = 1;
  static constexpr int kWall = 2;
  static constexpr int kFirstRod = 3;

  /// The paper's values with one rod material named "rod".
  static MaterialTable paper();

  /// Adds a rod material with the paper's "rod" coefficients against everything; returns its index.
  int add_rod_material(const std::string& name);
  void set(int a, int b, ContactCoefficients coefficients);
  const ContactCoefficients& get(int a, int b) const;
  int index_of(const std::string& name) const;  ///< -1 when unknown
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
  std::vector<ContactCoefficients> pairs_;  ///< names_.size()^2, symmetric
};

}  // namespace rodsort::engine
