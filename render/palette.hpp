#pragma once
// The colours of rodsort's pictures. Species take the Okabe-Ito palette (Okabe & Ito, "Color
// Universal Design", 2008), whose colours stay apart under the common colour-vision deficiencies
// and in greyscale print: blue and orange first, the usual pair for a two-species mixture.
// tools/rodsort_plot.py uses the same colours in the same order, so that a species has one colour
// in snapshots and in plots.

#include <cstdint>

namespace rodsort::render {

/// An opaque colour, components in [0, 1].
struct Colour {
  double red, green, blue;
};

/// 8-bit sRGB components, as a PNG stores them.
struct Rgb8 {
  std::uint8_t red, green, blue;
};

/// The colour of species `index` (>= 0); the palette repeats after seven species.
Colour species_colour(int index);
/// Number of distinct species colours before they repeat.
int species_colour_count();

/// The outline of a moving rod: its fill colour, darkened.
Colour edge_colour(const Colour& fill);

inline constexpr Colour kWallColour{0.20, 0.20, 0.20};        ///< trap walls and other obstacles
inline constexpr Colour kCellColour{1.0, 1.0, 1.0};           ///< inside the periodic cell
inline constexpr Colour kTrapAreaColour{0.93, 0.93, 0.90};    ///< the trap's area A_t
inline constexpr Colour kCellEdgeColour{0.55, 0.55, 0.55};    ///< the periodic cell's edge
inline constexpr Colour kBackgroundColour{0.96, 0.96, 0.96};  ///< around the cell
inline constexpr Colour kTextColour{0.0, 0.0, 0.0};
inline constexpr Colour kStationaryColour{0.0, 0.0, 0.0};  ///< mark of a stationary rod

/// The colour rounded to 8 bits per component.
Rgb8 to_rgb8(const Colour& colour);

}  // namespace rodsort::render
