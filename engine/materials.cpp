#include "engine/materials.hpp"

#include <cassert>
#include <stdexcept>

namespace rodsort::engine {

MaterialTable MaterialTable::paper() {
  MaterialTable table;
  table.names_ = {"base", "lid", "wall", "rod"};
  table.pairs_.assign(table.names_.size() * table.names_.size(), ContactCoefficients{0.0, 0.0});
  table.set(kFirstRod, kFirstRod, {0.05, 0.3});
  table.set(kFirstRod, kBase, {0.03, 0.1});
  table.set(kFirstRod, kLid, {0.01, 0.1});
  table.set(kFirstRod, kWall, {0.03, 0.65});
  return table;
}

int MaterialTable::add_rod_material(const std::string& name) {
  if (index_of(name) >= 0) throw std::invalid_argument("material '" + name + "' exists already");
  const std::size_t old_count = names_.size();
  const std::size_t count = old_count + 1;
  std::vector<ContactCoefficients> pairs(count * count, ContactCoefficients{0.0, 0.0});
  for (std::size_t a = 0; a < old_count; ++a) {
    for (std::size_t b = 0; b < old_count; ++b) pairs[a * count + b] = pairs_[a * old_count + b];
  }
  names_.push_back(name);
  pairs_ = std::move(pairs);
  const int index = static_cast<int>(old_count);
  for (int other = 0; other < index; ++other) set(index, other, get(kFirstRod, other));
  set(index, index, get(kFirstRod, kFirstRod));
  return index;
}

void MaterialTable::set(int a, int b, ContactCoefficients coefficients) {
  const auto count = static_cast<int>(names_.size());
  assert(a >= 0 && a < count && b >= 0 && b < count);
  pairs_[static_cast<std::size_t>(a * count + b)] = coefficients;
  pairs_[static_cast<std::size_t>(b * count + a)] = coefficients;
}

const ContactCoefficients& MaterialTable::get(int a, int b) const {
  const auto count = static_cast<int>(names_.size());
  assert(a >= 0 && a < count && b >= 0 && b < count);
  return pairs_[static_cast<std::size_t>(a * count + b)];
}

int MaterialTable::index_of(const std::string& name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace rodsort::engine
