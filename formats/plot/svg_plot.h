// SVG line plots in the spirit of the thesis figures (a DOF curve over time, its Gaussian
// and Laplacian bands, fragment boundaries): stacked panels sharing one time axis, each with
// labelled axes, tick values, a legend and optional vertical marker lines. The output is a
// self-contained SVG 1.1 string any browser shows; the caller writes it to disk.
#pragma once

#include <string>
#include <vector>

namespace mocapfill {

struct PlotSeries {
  std::string label;          // legend text
  std::vector<double> x;      // same length as y; non-finite points break the line
  std::vector<double> y;
  std::string color;          // CSS colour; empty = next colour of the default palette
};

struct PlotPanel {
  std::string title;                // drawn at the panel's top left
  std::string y_label;              // with unit, e.g. "angle (deg)"
  std::vector<PlotSeries> series;
  std::vector<double> markers_x;    // vertical dashed lines (e.g. phase boundaries), x units
};

struct PlotFigure {
  std::string title;
  std::string x_label;              // shared by all panels, with unit, e.g. "time (s)"
  std::vector<PlotPanel> panels;    // drawn top to bottom
  int width_px = 960;
  int panel_height_px = 170;
};

// Renders the figure. Axis ranges come from the data (padded; a flat series gets a unit
// range); ticks are at 1/2/5 x 10^n steps. Text is XML-escaped.
std::string RenderSvg(const PlotFigure& figure);

}  // namespace mocapfill
