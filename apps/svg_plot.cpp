#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gab {
namespace cli {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", v);
  return buf;
}

// A "nice" tick step (1, 2 or 5 times a power of ten) for about 5 ticks.
double tick_step(double span) {
  if (!(span > 0)) return 1.0;
  const double raw = span / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / mag;
  return (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * mag;
}

// The chart with every coordinate replaced by its base-10 logarithm, points
// with a coordinate <= 0 dropped.
Chart log10_chart(const Chart& chart) {
  Chart out = chart;
  for (Series& s : out.series) {
    Series kept = s;
    kept.x.clear();
    kept.y.clear();
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!(s.x[i] > 0) || !(s.y[i] > 0)) continue;
      kept.x.push_back(std::log10(s.x[i]));
      kept.y.push_back(std::log10(s.y[i]));
    }
    s = kept;
  }
  return out;
}

}  // namespace

std::string render_svg(const std::vector<Chart>& charts, int width, int height) {
  std::string svg;
  const int total = height * static_cast<int>(charts.size());
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%%\" "
                "height=\"100%%\" fill=\"white\"/>\n",
                width, total);
  svg += buf;
  const double left = 80, right = 20, top = 30, bottom = 45;
  for (size_t ci = 0; ci < charts.size(); ++ci) {
    // A log-log chart is drawn as the linear chart of the logarithms.
    const Chart ch = charts[ci].log_axes ? log10_chart(charts[ci]) : charts[ci];
    const bool log_axes = charts[ci].log_axes;
    auto label = [&](double v) { return fmt(log_axes ? std::pow(10.0, v) : v); };
    const double y0 = static_cast<double>(ci) * height;
    double xmin = INFINITY, xmax = -INFINITY, ymin = log_axes ? INFINITY : 0.0, ymax = -INFINITY;
    for (const Series& s : ch.series) {
      for (double v : s.x) xmin = std::min(xmin, v), xmax = std::max(xmax, v);
      for (double v : s.y) ymin = std::min(ymin, v), ymax = std::max(ymax, v);
    }
    if (!(xmax > xmin)) xmax = xmin + 1.0;
    if (!(ymax > ymin)) ymax = ymin + 1.0;
    const double pw = width - left - right, ph = height - top - bottom;
    auto px = [&](double v) { return left + (v - xmin) / (xmax - xmin) * pw; };
    auto py = [&](double v) { return y0 + top + ph - (v - ymin) / (ymax - ymin) * ph; };
    std::snprintf(buf, sizeof(buf), "<text x=\"%g\" y=\"%g\" font-size=\"14\">%s</text>\n", left,
                  y0 + 18, escape(ch.title).c_str());
    svg += buf;
    std::snprintf(buf, sizeof(buf),
                  "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"#444\"/>\n",
                  left, y0 + top, pw, ph);
    svg += buf;
    const double xs = tick_step(xmax - xmin), ys = tick_step(ymax - ymin);
    for (double v = std::ceil(xmin / xs) * xs; v <= xmax + 1e-9 * xs; v += xs) {
      std::snprintf(buf, sizeof(buf),
                    "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/><text x=\"%g\" "
                    "y=\"%g\" text-anchor=\"middle\">%s</text>\n",
                    px(v), y0 + top, px(v), y0 + top + ph, px(v), y0 + top + ph + 15, label(v).c_str());
      svg += buf;
    }
    for (double v = std::ceil(ymin / ys) * ys; v <= ymax + 1e-9 * ys; v += ys) {
      std::snprintf(buf, sizeof(buf),
                    "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ddd\"/><text x=\"%g\" "
                    "y=\"%g\" text-anchor=\"end\">%s</text>\n",
                    left, py(v), left + pw, py(v), left - 5, py(v) + 4, label(v).c_str());
      svg += buf;
    }
    std::snprintf(buf, sizeof(buf), "<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">%s</text>\n",
                  left + pw / 2, y0 + height - 8, escape(ch.x_label).c_str());
    svg += buf;
    std::snprintf(buf, sizeof(buf),
                  "<text transform=\"translate(14,%g) rotate(-90)\" text-anchor=\"middle\">%s</text>\n",
                  y0 + top + ph / 2, escape(ch.y_label).c_str());
    svg += buf;
    double legend_y = y0 + top + 14;
    for (const Series& s : ch.series) {
      if (s.points) {
        for (size_t i = 0; i < s.x.size(); ++i) {
          std::snprintf(buf, sizeof(buf), "<circle cx=\"%g\" cy=\"%g\" r=\"3\" fill=\"%s\"/>\n",
                        px(s.x[i]), py(s.y[i]), s.color.c_str());
          svg += buf;
        }
      } else if (!s.x.empty()) {
        std::string pts;
        for (size_t i = 0; i < s.x.size(); ++i) {
          std::snprintf(buf, sizeof(buf), "%.1f,%.1f ", px(s.x[i]), py(s.y[i]));
          pts += buf;
        }
        svg += "<polyline fill=\"none\" stroke=\"" + s.color + "\" stroke-width=\"1\"" +
               (s.dashed ? " stroke-dasharray=\"6,4\"" : "") + " points=\"" + pts + "\"/>\n";
      }
      std::snprintf(buf, sizeof(buf), "<text x=\"%g\" y=\"%g\" fill=\"%s\">%s</text>\n",
                    left + pw - 260, legend_y, s.color.c_str(), escape(s.name).c_str());
      svg += buf;
      legend_y += 15;
    }
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace cli
}  // namespace gab
