#include "formats/plot/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocapfill {
namespace {

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgPlot, DrawsPanelsAxesLegendsAndMarkers) {
  PlotFigure figure;
  figure.title = "UpperLeg_L <z> & bands";
  figure.x_label = "time (s)";
  for (int p = 0; p < 3; ++p) {
    PlotPanel panel;
    panel.title = "panel " + std::to_string(p);
    panel.y_label = "angle (deg)";
    PlotSeries s;
    // Appended rather than "g" + to_string: GCC 12 at -O3 flags that operator+ with a false
    // -Wstringop-overflow (GCC bug 105329).
    s.label = "g";
    s.label += std::to_string(p);
    for (int i = 0; i <= 60; ++i) {
      s.x.push_back(i / 30.0);
      s.y.push_back(i == 30 ? NAN : 10.0 * std::sin(i / 5.0));
    }
    panel.series.push_back(s);
    panel.markers_x = {0.5, 1.25};
    figure.panels.push_back(panel);
  }
  const std::string svg = RenderSvg(figure);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("UpperLeg_L &lt;z&gt; &amp; bands"), std::string::npos);
  EXPECT_EQ(Count(svg, ">angle (deg)</text>"), 3u);
  EXPECT_EQ(Count(svg, ">time (s)</text>"), 1u);
  EXPECT_EQ(Count(svg, "stroke-dasharray"), 6u);
  // The NaN at frame 30 splits each curve into two polylines.
  EXPECT_EQ(Count(svg, "<polyline"), 6u);
  EXPECT_NE(svg.find(">-10</text>"), std::string::npos);  // a y tick at a 1/2/5 step
  EXPECT_NE(svg.find(">1.0</text>"), std::string::npos);  // an x tick in seconds
}

TEST(SvgPlot, EmptyAndFlatDataStillRender) {
  PlotFigure figure;
  PlotPanel flat;
  flat.series.push_back({"flat", {0, 1, 2}, {5, 5, 5}, ""});
  figure.panels.push_back(flat);
  figure.panels.push_back(PlotPanel{});
  const std::string svg = RenderSvg(figure);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
  EXPECT_EQ(Count(svg, "<polyline"), 1u);
}

}  // namespace
}  // namespace mocapfill
