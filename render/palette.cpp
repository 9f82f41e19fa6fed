#include "render/palette.hpp"

#include <array>
#include <cmath>

namespace rodsort::render {
namespace {

constexpr Colour from_rgb8(int red, int green, int blue) {
  return {red / 255.0, green / 255.0, blue / 255.0};
}

// Okabe-Ito, without its black (kept for marks and text) and ordered for contrast between
// neighbours.
constexpr std::array kSpeciesColours = {
    from_rgb8(0, 114, 178),    // blue
    from_rgb8(230, 159, 0),    // orange
    from_rgb8(0, 158, 115),    // bluish green
    from_rgb8(213, 94, 0),     // vermillion
    from_rgb8(204, 121, 167),  // reddish purple
    from_rgb8(86, 180, 233),   // sky blue
    from_rgb8(240, 228, 66),   // yellow
};

}  // namespace

Colour species_colour(int index) {
  const int count = species_colour_count();
  return kSpeciesColours[static_cast<std::size_t>(((index % count) + count) % count)];
}

int species_colour_count() { return static_cast<int>(kSpeciesColours.size()); }

Colour edge_colour(const Colour& fill) {
  constexpr double kDarkening = 0.55;
  return {fill.red * kDarkening, fill.green * kDarkening, fill.blue * kDarkening};
}

Rgb8 to_rgb8(const Colour& colour) {
  const auto byte = [](double component) {
    return static_cast<std::uint8_t>(std::lround(255.0 * component));
  };
  return {byte(colour.red), byte(colour.green), byte(colour.blue)};
}

}  // namespace rodsort::render
