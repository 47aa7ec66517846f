// Plots drawn with illum's own image code, for `illum eval --plot`: curves against a value on
// axes with ticks, and lobes in polar form around a surface point. Anti-aliased lines, the label
// font's text, a dark background as illum's sheets have.
#pragma once

#include <illum/image.h>
#include <illum/real.h>

#include <string>
#include <vector>

namespace illum {

struct PlotCurve {
  std::string name;  // in the legend
  Vec3 color;        // 0..1
  std::vector<Vec2> points;  // line plots: (x, y); polar plots: (angle from the normal in degrees, radius)
};

// Where a plot's data lands: pixel = origin + (value - min) · scale, y upwards.
struct PlotFrame {
  Vec2 min{0}, max{1};
  Vec2 originPixel{0}, pixelsPerUnit{1};  // pixelsPerUnit.y is negative: rows grow downwards
  Vec2 toPixel(Vec2 value) const { return originPixel + (value - min) * pixelsPerUnit; }
};

// Curves on axes in the box (x, y, width, height) of `image`, with ticks at round numbers, the
// axes' names and a legend; y always includes 0. Returns where the data landed.
PlotFrame drawLinePlot(Image& image, int x, int y, int width, int height, const std::string& title,
                       const std::string& xName, const std::string& yName, const std::vector<PlotCurve>& curves);

// Lobes around a surface point at the bottom middle of the box: each point of a curve at its angle
// from the normal (up), at its radius (1 = `radiusPixels`); arrows for the named directions (angle
// in degrees from the normal, positive to the right). Returns where the data landed (x, y in
// radius units from the surface point).
struct PlotArrow {
  std::string name;
  Real degrees;
  Vec3 color;
};
PlotFrame drawPolarPlot(Image& image, int x, int y, int width, int height, const std::string& title,
                        const std::vector<PlotCurve>& curves, const std::vector<PlotArrow>& arrows);

// A blank figure of the plots' background.
Image plotCanvas(int width, int height);

// Round tick values covering [lo, hi]: steps of 1, 2 or 5 times a power of ten, about `count` of them.
std::vector<Real> niceTicks(Real lo, Real hi, int count);

}  // namespace illum
