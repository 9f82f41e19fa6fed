#pragma once
// A PNG read back with cairo, and counts of its pixels by colour: what a test can say about a
// picture without comparing it to a stored one.

#include <cairo.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "render/palette.hpp"

namespace rodsort::render::testing {

class PngPixels {
 public:
  explicit PngPixels(const std::filesystem::path& path)
      : surface_(cairo_image_surface_create_from_png(path.c_str())) {
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error("cannot read " + path.string());
    }
  }
  ~PngPixels() { cairo_surface_destroy(surface_); }
  PngPixels(const PngPixels&) = delete;
  PngPixels& operator=(const PngPixels&) = delete;

  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }

  Rgb8 at(int x, int y) const {
    const unsigned char* row =
        cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
    std::uint32_t pixel;
    std::memcpy(&pixel, row + 4 * x, sizeof pixel);
    return {static_cast<std::uint8_t>(pixel >> 16), static_cast<std::uint8_t>(pixel >> 8),
            static_cast<std::uint8_t>(pixel)};
  }

  /// Whether the pixel at (x, y) has `colour`, within `tolerance` per 8-bit component.
  bool has_colour(int x, int y, const Colour& colour, int tolerance = 3) const {
    const Rgb8 pixel = at(x, y);
    const Rgb8 wanted = to_rgb8(colour);
    return std::abs(pixel.red - wanted.red) <= tolerance &&
           std::abs(pixel.green - wanted.green) <= tolerance &&
           std::abs(pixel.blue - wanted.blue) <= tolerance;
  }

  /// Pixels of `colour` in the rectangle [x0, x1) x [y0, y1).
  int count(const Colour& colour, int x0, int y0, int x1, int y1) const {
    int found = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) found += has_colour(x, y, colour) ? 1 : 0;
    }
    return found;
  }

 private:
  cairo_surface_t* surface_;
};

}  // namespace rodsort::render::testing
