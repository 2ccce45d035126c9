// Minimal SVG line/point charts for `gab study` (no dependency, readable
// source). One chart = one panel with axes, ticks, and named series.
#pragma once

#include <string>
#include <vector>

namespace gab {
namespace cli {

struct Series {
  std::string name;
  std::string color;  // any SVG colour
  std::vector<double> x, y;
  bool points = false;  // markers instead of a polyline
  bool dashed = false;
};

struct Chart {
  std::string title, x_label, y_label;
  std::vector<Series> series;
  // Both axes logarithmic (ticks labelled with the values; points with a
  // coordinate <= 0 are left out). Linear axes start y at 0.
  bool log_axes = false;
};

// Renders charts stacked vertically, each width x height pixels.
std::string render_svg(const std::vector<Chart>& charts, int width = 800, int height = 320);

}  // namespace cli
}  // namespace gab
