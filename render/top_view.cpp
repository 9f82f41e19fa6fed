#include "render/top_view.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "render/rod_outline.hpp"

namespace rodsort::render {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr const char* kFont = "sans-serif";
constexpr const char* kEta = "\xCE\xB7";                // η
constexpr const char* kSubscriptZero = "\xE2\x82\x80";  // ₀

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void set_colour(cairo_t* cairo, const Colour& colour) {
  cairo_set_source_rgb(cairo, colour.red, colour.green, colour.blue);
}

void set_font(cairo_t* cairo, double size, bool bold = false) {
  cairo_select_font_face(cairo, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo, size);
}

/// Text at (x, y) (its baseline's start) in the current colour: drawn, or, with `svg_text`,
/// appended to it as an SVG <text> element.
void put_text(cairo_t* cairo, std::string* svg_text, double x, double y, double size, bool bold,
              const std::string& text) {
  if (svg_text == nullptr) {
    set_font(cairo, size, bold);
    cairo_move_to(cairo, x, y);
    cairo_show_text(cairo, text.c_str());
    return;
  }
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      default:
        escaped += c;
    }
  }
  double red = 0, green = 0, blue = 0, alpha = 0;
  cairo_pattern_get_rgba(cairo_get_source(cairo), &red, &green, &blue, &alpha);
  char element[256];
  std::snprintf(
      element, sizeof element,
      "<text xml:space=\"preserve\" x=\"%.2f\" y=\"%.2f\" font-family=\"%s\" font-size=\"%.2f\"%s "
      "fill=\"rgb(%d,%d,%d)\">",
      x, y, kFont, size, bold ? " font-weight=\"bold\"" : "",
      static_cast<int>(std::lround(255 * red)), static_cast<int>(std::lround(255 * green)),
      static_cast<int>(std::lround(255 * blue)));
  *svg_text += element + escaped + "</text>\n";
}

double text_width(cairo_t* cairo, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cairo, text.c_str(), &extents);
  return extents.x_advance;
}

/// Width of the outline around a rod [px]: thin for a moving rod, bold for a stationary one.
double edge_width(const ViewLayout& layout, bool stationary) {
  return stationary ? std::max(1.0, 0.12 * layout.scale) : std::max(0.5, 0.05 * layout.scale);
}

/// The outline of `shape` with every disc grown by `grow` [mm].
std::vector<OutlineLoop> grown_outline(engine::RodShape shape, double grow) {
  for (engine::Sphere& sphere : shape.spheres) sphere.radius += grow;
  return rod_outline(shape);
}

/// What drawing a species needs, worked out once per picture. A rod is drawn as two fills: its
/// discs grown by the outline's width in the outline's colour, then its discs over them (filling
/// twice costs a third of stroking the outline, and gives the same picture).
struct SpeciesDrawing {
  std::vector<OutlineLoop> body;
  std::vector<OutlineLoop> moving_edge;
  std::vector<OutlineLoop> stationary_edge;
  double reach = 0.0;  ///< largest distance from the centre of mass to an edge [mm]
};

std::vector<SpeciesDrawing> species_drawings(const Scene& scene, const ViewLayout& layout) {
  std::vector<SpeciesDrawing> drawings;
  const double moving_edge = edge_width(layout, false) / layout.scale;
  const double stationary_edge = edge_width(layout, true) / layout.scale;
  for (const SpeciesLook& species : scene.species) {
    SpeciesDrawing drawing{rod_outline(species.shape), grown_outline(species.shape, moving_edge),
                           grown_outline(species.shape, stationary_edge), 0.0};
    for (const engine::Sphere& sphere : species.shape.spheres) {
      drawing.reach =
          std::max(drawing.reach, std::abs(sphere.axial) + sphere.radius + stationary_edge);
    }
    drawings.push_back(std::move(drawing));
  }
  return drawings;
}

struct RodLook {
  Colour fill;
  bool stationary;
};

/// Fills an outline placed at `centre` [mm] along the in-plane `axis`.
void fill_outline(cairo_t* cairo, const ViewLayout& layout, const std::vector<OutlineLoop>& outline,
                  const Eigen::Vector2d& centre, const Eigen::Vector2d& axis,
                  const Colour& colour) {
  // A rod tilted between the plates looks shorter from above: its discs' centres come closer
  // along the axis (by cos(tilt) >= 0.99 between the paper's plates), their radii stay.
  const double heading = std::atan2(axis.y(), axis.x());
  cairo_new_path(cairo);
  for (const OutlineLoop& loop : outline) {
    cairo_new_sub_path(cairo);
    for (const OutlineArc& arc : loop) {
      const Eigen::Vector2d at = layout.to_pixels(centre + arc.axial * axis);
      // The image's y axis points down: angles change sign, and a clockwise loop in the cell runs
      // with growing angles in the image.
      cairo_arc(cairo, at.x(), at.y(), arc.radius * layout.scale, -(heading + arc.from),
                -(heading + arc.to));
    }
    cairo_close_path(cairo);
  }
  set_colour(cairo, colour);
  cairo_fill(cairo);
}

/// One rod, centre and in-plane axis in mm.
void draw_rod(cairo_t* cairo, const ViewLayout& layout, const SpeciesDrawing& drawing,
              const Eigen::Vector2d& centre, const Eigen::Vector2d& axis, const RodLook& look) {
  if (look.stationary) {
    fill_outline(cairo, layout, drawing.stationary_edge, centre, axis, kStationaryColour);
  } else {
    fill_outline(cairo, layout, drawing.moving_edge, centre, axis, edge_colour(look.fill));
  }
  fill_outline(cairo, layout, drawing.body, centre, axis, look.fill);
  if (look.stationary) {
    const Eigen::Vector2d at = layout.to_pixels(centre);
    cairo_arc(cairo, at.x(), at.y(), std::max(1.2, 0.18 * layout.scale), 0.0, kTwoPi);
    set_colour(cairo, kStationaryColour);
    cairo_fill(cairo);
  }
}

/// A rod and each of its periodic images that reaches into the cell (the caller clips to it).
void draw_rod_with_images(cairo_t* cairo, const ViewLayout& layout, const Scene& scene,
                          const SpeciesDrawing& drawing, const engine::RodFrame& rod,
                          const RodLook& look) {
  const Eigen::Vector2d axis(rod.axis.x(), rod.axis.y());
  for (const int shift_x : {-1, 0, 1}) {
    for (const int shift_y : {-1, 0, 1}) {
      const Eigen::Vector2d centre =
          rod.position + Eigen::Vector2d(shift_x * scene.box_x, shift_y * scene.box_y);
      const bool reaches_cell =
          centre.x() + drawing.reach > 0.0 && centre.x() - drawing.reach < scene.box_x &&
          centre.y() + drawing.reach > 0.0 && centre.y() - drawing.reach < scene.box_y;
      if (reaches_cell) draw_rod(cairo, layout, drawing, centre, axis, look);
    }
  }
}

void draw_wall(cairo_t* cairo, const ViewLayout& layout, const engine::Wall& wall) {
  const Eigen::Vector2d centre(wall.center_x, wall.center_y);
  const Eigen::Vector2d along =
      wall.half_length * Eigen::Vector2d(std::cos(wall.yaw), std::sin(wall.yaw));
  const Eigen::Vector2d across =
      wall.half_thickness * Eigen::Vector2d(-std::sin(wall.yaw), std::cos(wall.yaw));
  cairo_new_path(cairo);
  const std::array<Eigen::Vector2d, 4> corners = {centre + along + across, centre - along + across,
                                                  centre - along - across, centre + along - across};
  for (const Eigen::Vector2d& corner : corners) {
    const Eigen::Vector2d at = layout.to_pixels(corner);
    cairo_line_to(cairo, at.x(), at.y());
  }
  cairo_close_path(cairo);
  set_colour(cairo, kWallColour);
  cairo_fill(cairo);
}

void draw_polygon(cairo_t* cairo, const ViewLayout& layout,
                  const std::vector<Eigen::Vector2d>& corners, const Colour& colour) {
  cairo_new_path(cairo);
  for (const Eigen::Vector2d& corner : corners) {
    const Eigen::Vector2d at = layout.to_pixels(corner);
    cairo_line_to(cairo, at.x(), at.y());
  }
  cairo_close_path(cairo);
  set_colour(cairo, colour);
  cairo_fill(cairo);
}

/// One entry of the legend: a rod drawn as in the cell, and its label.
struct LegendEntry {
  int species;  ///< whose shape the swatch shows
  RodLook look;
  std::string label;
  double x = 0.0, y = 0.0;  ///< top left of the entry [px]
};

/// The legend's entries placed in rows from `top`, wrapped at the layout's width. The cairo
/// context only measures text.
std::vector<LegendEntry> place_legend(cairo_t* cairo, const Scene& scene, const ViewLayout& layout,
                                      double top) {
  std::vector<LegendEntry> entries;
  for (std::size_t s = 0; s < scene.species.size(); ++s) {
    const SpeciesLook& species = scene.species[s];
    entries.push_back({static_cast<int>(s),
                       {species.colour, false},
                       species.name + " (" + std::to_string(species.count) + " rods)"});
  }
  if (!scene.species.empty()) {
    std::string label = "stationary";
    if (!scene.stationary_rule.empty()) label += ": " + scene.stationary_rule;
    entries.push_back({0, {kBackgroundColour, true}, label});
  }
  set_font(cairo, layout.font_size);
  const double row_height = 1.6 * layout.font_size;
  const double right = layout.width - layout.margin;
  double x = layout.margin;
  double y = top;
  for (LegendEntry& entry : entries) {
    const double swatch =
        scene.species[static_cast<std::size_t>(entry.species)].shape.length * layout.scale;
    const double width = swatch + 0.5 * layout.font_size + text_width(cairo, entry.label);
    if (x > layout.margin && x + width > right) {
      x = layout.margin;
      y += row_height;
    }
    entry.x = x;
    entry.y = y;
    x += width + 1.5 * layout.font_size;
  }
  return entries;
}

std::string format_number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string status_line(const engine::Frame& frame, const FrameMarks& marks) {
  std::string line = "t = " + format_number("%.2f", frame.time) + " s";
  if (!marks.stationary.empty()) {
    const auto stationary = std::count(marks.stationary.begin(), marks.stationary.end(), true);
    line += "    N" + std::string(kSubscriptZero) + " = " + std::to_string(stationary);
  }
  line += "    " + std::string(kEta) + " = ";
  line += marks.eta ? format_number("%.3f", *marks.eta) : std::string("\xE2\x80\x93");  // –
  if (marks.eta_trap) {
    line += "    " + std::string(kEta) + " in trap = " + format_number("%.3f", *marks.eta_trap);
  }
  return line;
}

int round_up_to_even(double value) {
  const int whole = static_cast<int>(std::ceil(value));
  return whole + (whole % 2);
}

SurfacePtr surface_ptr(cairo_surface_t* surface) { return {surface, &cairo_surface_destroy}; }
ContextPtr context_ptr(cairo_t* cairo) { return {cairo, &cairo_destroy}; }

void check_status(cairo_status_t status, const std::filesystem::path& path) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write " + path.string() + ": " +
                             cairo_status_to_string(status));
  }
}

}  // namespace

Eigen::Vector2d ViewLayout::to_pixels(const Eigen::Vector2d& point_mm) const {
  return {cell_left + point_mm.x() * scale, cell_top + cell_height - point_mm.y() * scale};
}

ViewLayout layout_view(const Scene& scene, const ViewOptions& options) {
  assert(options.width_px >= kMinimumWidth);
  assert(scene.box_x > 0.0 && scene.box_y > 0.0);
  ViewLayout layout;
  layout.width = round_up_to_even(options.width_px);
  layout.margin = std::max(8.0, 0.02 * layout.width);
  layout.font_size = std::clamp(layout.width / 55.0, 10.0, 28.0);
  layout.cell_left = layout.margin;
  layout.cell_width = layout.width - 2.0 * layout.margin;
  layout.scale = layout.cell_width / scene.box_x;
  layout.cell_height = scene.box_y * layout.scale;
  layout.cell_top = layout.margin + (options.header ? 2.9 * layout.font_size : 0.0);
  layout.header = options.header;
  layout.legend_top = layout.cell_top + layout.cell_height + 0.8 * layout.font_size;

  const SurfacePtr scratch = surface_ptr(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1));
  const ContextPtr cairo = context_ptr(cairo_create(scratch.get()));
  const std::vector<LegendEntry> legend =
      place_legend(cairo.get(), scene, layout, layout.legend_top);
  const double legend_bottom =
      legend.empty() ? layout.legend_top : legend.back().y + 1.6 * layout.font_size;
  layout.height = round_up_to_even(legend_bottom + layout.margin);
  return layout;
}

double scale_bar_length(double box_x) {
  const double limit = box_x / 5.0;
  double length = std::pow(10.0, std::floor(std::log10(limit)));
  for (const double factor : {5.0, 2.0}) {
    if (length * factor <= limit) {
      length *= factor;
      break;
    }
  }
  return length;
}

namespace {

/// A bar of scale_bar_length() in the cell's lower right corner, on a light box, its length above.
void draw_scale_bar(cairo_t* cairo, const ViewLayout& layout, const Scene& scene,
                    std::string* svg_text) {
  const double length_mm = scale_bar_length(scene.box_x);
  const double length_px = length_mm * layout.scale;
  const double pad = 0.5 * layout.font_size;
  const double right = layout.cell_left + layout.cell_width - 1.5 * pad;
  const double bottom = layout.cell_top + layout.cell_height - 1.5 * pad;
  const double left = right - length_px;
  char label[32];
  std::snprintf(label, sizeof label, "%g mm", length_mm);
  set_font(cairo, 0.85 * layout.font_size);
  const double label_width = text_width(cairo, label);
  const double box_width = std::max(length_px, label_width) + 2.0 * pad;
  const double box_left = right + pad - box_width;
  const double box_top = bottom - 0.85 * layout.font_size - 2.2 * pad;
  cairo_rectangle(cairo, box_left, box_top, box_width, bottom + pad - box_top);
  cairo_set_source_rgba(cairo, 1.0, 1.0, 1.0, 0.8);
  cairo_fill(cairo);
  set_colour(cairo, kTextColour);
  cairo_set_line_width(cairo, std::max(1.5, layout.width / 400.0));
  cairo_move_to(cairo, left, bottom);
  cairo_line_to(cairo, right, bottom);
  for (const double x : {left, right}) {
    cairo_move_to(cairo, x, bottom - 0.4 * pad);
    cairo_line_to(cairo, x, bottom + 0.4 * pad);
  }
  cairo_stroke(cairo);
  put_text(cairo, svg_text, 0.5 * (left + right) - 0.5 * label_width, bottom - 0.8 * pad,
           0.85 * layout.font_size, false, label);
}

}  // namespace

void draw_top_view(cairo_t* cairo, const ViewLayout& layout, const Scene& scene,
                   const engine::Frame& frame, const FrameMarks& marks, std::string* svg_text) {
  assert(marks.stationary.empty() || marks.stationary.size() == frame.rods.size());
  set_colour(cairo, kBackgroundColour);
  cairo_paint(cairo);

  cairo_save(cairo);
  cairo_rectangle(cairo, layout.cell_left, layout.cell_top, layout.cell_width, layout.cell_height);
  set_colour(cairo, kCellColour);
  cairo_fill_preserve(cairo);
  cairo_clip(cairo);
  if (!scene.trap_area.empty()) draw_polygon(cairo, layout, scene.trap_area, kTrapAreaColour);
  const std::vector<SpeciesDrawing> drawings = species_drawings(scene, layout);
  for (std::size_t r = 0; r < frame.rods.size(); ++r) {
    const engine::RodFrame& rod = frame.rods[r];
    assert(rod.species >= 0 && static_cast<std::size_t>(rod.species) < scene.species.size());
    const RodLook look{scene.species[static_cast<std::size_t>(rod.species)].colour,
                       !marks.stationary.empty() && marks.stationary[r]};
    draw_rod_with_images(cairo, layout, scene, drawings[static_cast<std::size_t>(rod.species)], rod,
                         look);
  }
  for (const engine::Wall& wall : scene.walls) draw_wall(cairo, layout, wall);
  cairo_restore(cairo);

  cairo_rectangle(cairo, layout.cell_left, layout.cell_top, layout.cell_width, layout.cell_height);
  cairo_set_line_width(cairo, std::max(1.0, layout.width / 800.0));
  set_colour(cairo, kCellEdgeColour);
  cairo_stroke(cairo);

  draw_scale_bar(cairo, layout, scene, svg_text);

  set_colour(cairo, kTextColour);
  if (layout.header) {
    put_text(cairo, svg_text, layout.margin, layout.margin + 1.1 * layout.font_size,
             1.1 * layout.font_size, true, scene.title);
    put_text(cairo, svg_text, layout.margin, layout.margin + 2.4 * layout.font_size,
             layout.font_size, false, status_line(frame, marks));
  }

  for (const LegendEntry& entry : place_legend(cairo, scene, layout, layout.legend_top)) {
    const engine::RodShape& shape = scene.species[static_cast<std::size_t>(entry.species)].shape;
    const double swatch = shape.length * layout.scale;
    const double middle_y = entry.y + 0.8 * layout.font_size;
    // The swatch's centre of mass sits where the whole rod, tip to tip, fits from entry.x.
    const double centre_x = entry.x - shape.thick_tip * layout.scale;
    const Eigen::Vector2d centre_mm(
        (centre_x - layout.cell_left) / layout.scale,
        (layout.cell_top + layout.cell_height - middle_y) / layout.scale);
    draw_rod(cairo, layout, drawings[static_cast<std::size_t>(entry.species)], centre_mm,
             Eigen::Vector2d::UnitX(), entry.look);
    set_colour(cairo, kTextColour);
    put_text(cairo, svg_text, entry.x + swatch + 0.5 * layout.font_size,
             middle_y + 0.35 * layout.font_size, layout.font_size, false, entry.label);
  }
}

void write_png(const std::filesystem::path& path, const ViewLayout& layout, const Scene& scene,
               const engine::Frame& frame, const FrameMarks& marks) {
  const SurfacePtr surface =
      surface_ptr(cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height));
  const ContextPtr cairo = context_ptr(cairo_create(surface.get()));
  draw_top_view(cairo.get(), layout, scene, frame, marks);
  check_status(cairo_status(cairo.get()), path);
  check_status(cairo_surface_write_to_png(surface.get(), path.c_str()), path);
}

void write_svg(const std::filesystem::path& path, const ViewLayout& layout, const Scene& scene,
               const engine::Frame& frame, const FrameMarks& marks) {
  const SurfacePtr surface =
      surface_ptr(cairo_svg_surface_create(path.c_str(), layout.width, layout.height));
  check_status(cairo_surface_status(surface.get()), path);
  std::string text;
  {
    const ContextPtr cairo = context_ptr(cairo_create(surface.get()));
    draw_top_view(cairo.get(), layout, scene, frame, marks, &text);
    check_status(cairo_status(cairo.get()), path);
  }
  cairo_surface_finish(surface.get());
  check_status(cairo_surface_status(surface.get()), path);
  // Cairo writes text as glyph outlines; the text goes in as <text> elements instead, last so
  // that it lies over the drawing.
  std::ifstream in(path, std::ios::binary);
  std::stringstream svg;
  svg << in.rdbuf();
  std::string document = svg.str();
  const std::size_t end = document.rfind("</svg>");
  if (!in || end == std::string::npos)
    throw std::runtime_error("cannot read back " + path.string());
  document.insert(end, text);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << document;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace rodsort::render
