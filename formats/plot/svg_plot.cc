#include "formats/plot/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mocapfill {

namespace {

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                    "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
constexpr double kLeft = 78, kRight = 24, kTop = 44, kGap = 34, kBottom = 52;

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f", v);
  return buffer;
}

std::string Label(double v, double step) {
  // Enough decimals to tell neighbouring ticks apart, never "-0".
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
  if (std::abs(v) < 0.5 * step) v = 0.0;
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, v);
  return buffer;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  // Empty ranges become [0, 1]; flat ones get a unit width; others are padded by 5%.
  Range Padded(double fraction) const {
    if (!(lo <= hi)) return {0.0, 1.0};
    if (hi - lo < 1e-12) return {lo - 0.5, hi + 0.5};
    const double pad = fraction * (hi - lo);
    return {lo - pad, hi + pad};
  }
};

// A 1/2/5 x 10^n step giving about `target` ticks over the range.
double TickStep(const Range& r, int target) {
  const double raw = (r.hi - r.lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

struct Frame {
  double x0, x1, y0, y1;  // pixel box of the plot area
  Range xr, yr;
  double X(double x) const { return x0 + (x - xr.lo) / (xr.hi - xr.lo) * (x1 - x0); }
  double Y(double y) const { return y1 - (y - yr.lo) / (yr.hi - yr.lo) * (y1 - y0); }
};

void DrawAxes(std::string& svg, const Frame& f, const PlotPanel& panel, bool x_labels) {
  const double ystep = TickStep(f.yr, 4), xstep = TickStep(f.xr, 10);
  for (double y = std::ceil(f.yr.lo / ystep) * ystep; y <= f.yr.hi + 1e-9 * ystep; y += ystep) {
    svg += "<line x1=\"" + Num(f.x0) + "\" y1=\"" + Num(f.Y(y)) + "\" x2=\"" + Num(f.x1) + "\" y2=\"" + Num(f.Y(y)) +
           "\" stroke=\"#e4e4e4\"/>\n";
    svg += "<text x=\"" + Num(f.x0 - 6) + "\" y=\"" + Num(f.Y(y) + 4) + "\" text-anchor=\"end\">" + Label(y, ystep) +
           "</text>\n";
  }
  for (double x = std::ceil(f.xr.lo / xstep) * xstep; x <= f.xr.hi + 1e-9 * xstep; x += xstep) {
    svg += "<line x1=\"" + Num(f.X(x)) + "\" y1=\"" + Num(f.y1) + "\" x2=\"" + Num(f.X(x)) + "\" y2=\"" +
           Num(f.y1 + 4) + "\" stroke=\"#333\"/>\n";
    if (x_labels)
      svg += "<text x=\"" + Num(f.X(x)) + "\" y=\"" + Num(f.y1 + 17) + "\" text-anchor=\"middle\">" + Label(x, xstep) +
             "</text>\n";
  }
  svg += "<rect x=\"" + Num(f.x0) + "\" y=\"" + Num(f.y0) + "\" width=\"" + Num(f.x1 - f.x0) + "\" height=\"" +
         Num(f.y1 - f.y0) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  const double mid = 0.5 * (f.y0 + f.y1);
  svg += "<text x=\"16\" y=\"" + Num(mid) + "\" text-anchor=\"middle\" transform=\"rotate(-90 16 " + Num(mid) + ")\">" +
         Escape(panel.y_label) + "</text>\n";
  svg += "<text x=\"" + Num(f.x0 + 6) + "\" y=\"" + Num(f.y0 - 6) + "\" font-weight=\"bold\">" + Escape(panel.title) +
         "</text>\n";
}

void DrawSeries(std::string& svg, const Frame& f, const PlotSeries& s, const std::string& color) {
  std::string points;
  auto flush = [&] {
    if (!points.empty())
      svg += "<polyline fill=\"none\" stroke=\"" + color + "\" stroke-width=\"1.4\" points=\"" + points + "\"/>\n";
    points.clear();
  };
  const size_t n = std::min(s.x.size(), s.y.size());
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      flush();
      continue;
    }
    points += Num(f.X(s.x[i])) + "," + Num(f.Y(s.y[i])) + " ";
  }
  flush();
}

void DrawPanel(std::string& svg, const PlotPanel& panel, const Frame& f, bool x_labels) {
  svg += "<clipPath id=\"clip" + Num(f.y0) + "\"><rect x=\"" + Num(f.x0) + "\" y=\"" + Num(f.y0) + "\" width=\"" +
         Num(f.x1 - f.x0) + "\" height=\"" + Num(f.y1 - f.y0) + "\"/></clipPath>\n";
  DrawAxes(svg, f, panel, x_labels);
  svg += "<g clip-path=\"url(#clip" + Num(f.y0) + ")\">\n";
  for (double x : panel.markers_x)
    if (std::isfinite(x))
      svg += "<line x1=\"" + Num(f.X(x)) + "\" y1=\"" + Num(f.y0) + "\" x2=\"" + Num(f.X(x)) + "\" y2=\"" + Num(f.y1) +
             "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
  std::vector<std::string> colors;
  for (size_t i = 0; i < panel.series.size(); ++i) {
    colors.push_back(panel.series[i].color.empty() ? kPalette[i % std::size(kPalette)] : panel.series[i].color);
    DrawSeries(svg, f, panel.series[i], colors.back());
  }
  svg += "</g>\n";
  double x = f.x1 - 8;  // legend, right-aligned along the top edge, last series rightmost
  for (size_t i = panel.series.size(); i-- > 0;) {
    const std::string& label = panel.series[i].label;
    if (label.empty()) continue;
    svg += "<text x=\"" + Num(x) + "\" y=\"" + Num(f.y0 - 6) + "\" text-anchor=\"end\">" + Escape(label) + "</text>\n";
    x -= 7.0 * label.size() + 6;
    svg += "<line x1=\"" + Num(x - 18) + "\" y1=\"" + Num(f.y0 - 10) + "\" x2=\"" + Num(x) + "\" y2=\"" +
           Num(f.y0 - 10) + "\" stroke=\"" + colors[i] + "\" stroke-width=\"2\"/>\n";
    x -= 30;
  }
}

}  // namespace

std::string RenderSvg(const PlotFigure& figure) {
  const double width = figure.width_px;
  const double height = kTop + figure.panels.size() * (figure.panel_height_px + kGap) - kGap + kBottom;
  Range xr;
  for (const PlotPanel& p : figure.panels) {
    for (const PlotSeries& s : p.series)
      for (double x : s.x) xr.Add(x);
    for (double x : p.markers_x) xr.Add(x);
  }
  xr = xr.Padded(0.0);
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                    Num(width) + "\" height=\"" + Num(height) + "\" viewBox=\"0 0 " + Num(width) + " " + Num(height) +
                    "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + Num(width / 2) + "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" + Escape(figure.title) +
         "</text>\n";
  for (size_t i = 0; i < figure.panels.size(); ++i) {
    const PlotPanel& panel = figure.panels[i];
    Range yr;
    for (const PlotSeries& s : panel.series)
      for (double y : s.y) yr.Add(y);
    Frame f;
    f.x0 = kLeft;
    f.x1 = width - kRight;
    f.y0 = kTop + i * (figure.panel_height_px + kGap);
    f.y1 = f.y0 + figure.panel_height_px;
    f.xr = xr;
    f.yr = yr.Padded(0.05);
    DrawPanel(svg, panel, f, true);
  }
  svg += "<text x=\"" + Num(0.5 * (kLeft + width - kRight)) + "\" y=\"" + Num(height - 12) +
         "\" text-anchor=\"middle\">" + Escape(figure.x_label) + "</text>\n";
  svg += "</svg>\n";
  return svg;
}

}  // namespace mocapfill
