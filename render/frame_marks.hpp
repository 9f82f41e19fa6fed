#pragma once
// What a frame's picture says beyond the rods' positions: which rods are stationary, and the
// trapping efficiency. The metrics layer decides both (render/run_frames.hpp asks it); a frame
// without a frame tau earlier has neither, and its picture says so.

#include <optional>
#include <vector>

namespace rodsort::render {

struct FrameMarks {
  std::vector<bool> stationary;    ///< per rod; empty when unknown
  std::optional<double> eta;       ///< N0 a / A_t; absent when unknown or without a trap
  std::optional<double> eta_trap;  ///< the same, stationary rods inside the trap only
};

}  // namespace rodsort::render
