#pragma once
// Every Bullet collision object of a simulation carries a BodyTag in its user pointer: what it is,
// its material, and for a rod or a periodic image the rod it stands for. Contact materials, the
// periodic solver and the collision kick all read it.

#include "engine/materials.hpp"
#include "engine/plate_roughness.hpp"

namespace rodsort::engine {

enum class BodyKind { kRod, kImage, kBase, kLid, kWall };

/// Collision groups: images meet only rods; plates and walls meet only rods.
enum CollisionGroup : int { kGroupRod = 1, kGroupPlate = 2, kGroupWall = 4, kGroupImage = 8 };

struct BodyTag {
  BodyKind kind;
  int material;                  ///< index into *materials
  const MaterialTable* materials;
  int rod = -1;                  ///< rod index for kRod and kImage
  int shift = -1;                ///< periodic shift index for kImage
  int wall = -1;                 ///< wall index for kWall
  const PlateRoughness* roughness = nullptr;  ///< kBase and kLid: the surface, null when flat
};

/// Makes Bullet combine friction and restitution by looking the pair up in the bodies' material
/// table instead of multiplying per-body values. Idempotent.
void install_material_table_callbacks();

}  // namespace rodsort::engine
