#pragma once
// The top view of the cell at one frame, as the camera above the paper's experiment sees it: every
// rod drawn as the union of its spheres' discs (its outline on the plate), filled with its
// species' colour; stationary rods outlined in black with a black dot on their centre of mass; the
// trap's walls, its area shaded, the periodic cell's edge, a scale bar in the cell's lower right
// corner; above the cell the scenario's name, the time and eta (unless left out, for a figure);
// below it the legend.
//
// The cell is periodic: a rod whose centre lies near an edge reaches across it, and its image
// shows on the far side too, both clipped to the cell, as the engine's periodic images collide.
//
// The same drawing goes to a PNG (raster, for movies and web pages) and to an SVG (vector, for
// papers), whose text is kept as <text> elements, editable and searchable. Image sizes are even,
// as video encoders with 4:2:0 chroma need.

#include <cairo.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "engine/frame.hpp"
#include "render/frame_marks.hpp"
#include "render/scene.hpp"

namespace rodsort::render {

struct ViewOptions {
  int width_px = 1000;  ///< image width; the height follows the cell's aspect ratio
  bool header = true;   ///< the scenario's name, the time and eta above the cell
};

/// Where things go in the image [px]. The cell's corner (0, 0) is at the bottom left, y up.
struct ViewLayout {
  int width = 0, height = 0;  ///< of the image, both even [px]
  double scale = 0.0;         ///< [px/mm]
  double cell_left = 0.0, cell_top = 0.0, cell_width = 0.0, cell_height = 0.0;  ///< [px]
  double margin = 0.0;      ///< around everything [px]
  double font_size = 0.0;   ///< [px]
  double legend_top = 0.0;  ///< [px]
  bool header = true;       ///< ViewOptions::header

  /// Image position of a point of the cell given in mm.
  Eigen::Vector2d to_pixels(const Eigen::Vector2d& point_mm) const;
};

/// Smallest allowed image width [px]: narrower, the text no longer fits.
inline constexpr int kMinimumWidth = 200;

/// options.width_px >= kMinimumWidth.
ViewLayout layout_view(const Scene& scene, const ViewOptions& options);

/// The scale bar's length for a cell `box_x` wide [mm]: 1, 2 or 5 times a power of ten, at most a
/// fifth of the cell.
double scale_bar_length(double box_x);

/// Draws the whole image on `cairo`, whose surface is layout.width x layout.height. The frame holds
/// the scene's rods in order; marks.stationary is empty or has one flag per rod. With `svg_text`,
/// the text is not drawn but appended to it as SVG <text> elements.
void draw_top_view(cairo_t* cairo, const ViewLayout& layout, const Scene& scene,
                   const engine::Frame& frame, const FrameMarks& marks,
                   std::string* svg_text = nullptr);

/// Writes the view as a PNG. Throws std::runtime_error naming the file when it cannot.
void write_png(const std::filesystem::path& path, const ViewLayout& layout, const Scene& scene,
               const engine::Frame& frame, const FrameMarks& marks);
/// Writes the view as an SVG. Throws std::runtime_error naming the file when it cannot.
void write_svg(const std::filesystem::path& path, const ViewLayout& layout, const Scene& scene,
               const engine::Frame& frame, const FrameMarks& marks);

}  // namespace rodsort::render
