#include <illum/plot.h>

#include "image/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace illum {
namespace {

const Vec3 kBackground(0.11, 0.11, 0.13), kAxis(0.55, 0.55, 0.6), kGrid(0.2, 0.2, 0.23), kText(0.9, 0.9, 0.92);
constexpr Real kTextSize = 14, kTitleSize = 16;

// Blends `color` over a pixel with coverage `a`.
void blend(Image& image, int x, int y, const Vec3& color, Real a) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || a <= 0) return;
  std::uint8_t* p = image.pixel(x, y);
  for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(double(Real(p[k]) * (1 - a) + color[k] * 255 * a)));
}

// An anti-aliased segment `width` pixels wide: each pixel near it covered by how far it lies
// inside the stroke (its distance to the segment against half the width, over one pixel).
void line(Image& image, Vec2 a, Vec2 b, const Vec3& color, Real width) {
  const Real half = width / 2;
  const int x0 = int(std::floor(std::min(a.x, b.x) - half - 1)), x1 = int(std::ceil(std::max(a.x, b.x) + half + 1));
  const int y0 = int(std::floor(std::min(a.y, b.y) - half - 1)), y1 = int(std::ceil(std::max(a.y, b.y) + half + 1));
  const Vec2 ab = b - a;
  const Real length2 = glm::dot(ab, ab);
  for (int y = std::max(y0, 0); y <= std::min(y1, image.height - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, image.width - 1); ++x) {
      const Vec2 p(Real(x) + Real(0.5), Real(y) + Real(0.5));
      const Real t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, Real(0), Real(1)) : Real(0);
      const Real distance = glm::length(p - (a + t * ab));
      blend(image, x, y, color, std::clamp(half + Real(0.5) - distance, Real(0), Real(1)));
    }
}

void polyline(Image& image, const std::vector<Vec2>& points, const Vec3& color, Real width) {
  for (std::size_t i = 1; i < points.size(); ++i) line(image, points[i - 1], points[i], color, width);
}

std::string tickText(Real v, Real step) {
  if (std::abs(v) < step * Real(1e-6)) v = 0;  // no "-0.0"
  char buf[32];
  const int decimals = step >= 1 ? 0 : int(std::ceil(-std::log10(double(step)) - 1e-9));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, double(v));
  return std::string(buf) == "-0" ? "0" : buf;
}

// The legend: a short stroke of each curve's colour and its name, a row each, from (x, y).
void legend(Image& image, Real x, Real y, const std::vector<PlotCurve>& curves) {
  // A box of the background under it, so that curves passing behind do not cross its text.
  Real widest = 0;
  for (const PlotCurve& c : curves) widest = std::max(widest, textWidth(c.name, kTextSize));
  const int boxRight = int(x + 30 + widest + 6), boxBottom = int(y + Real(curves.size()) * (kTextSize + 6) - kTextSize + 2);
  for (int py = int(y - kTextSize - 2); py <= boxBottom; ++py)
    for (int px = int(x - 6); px <= boxRight; ++px) blend(image, px, py, kBackground, Real(0.85));
  for (const PlotCurve& c : curves) {
    line(image, {x, y - 5}, {x + 22, y - 5}, c.color, 3);
    const Real w = textWidth(c.name, kTextSize);
    drawText(image, x + 30 + w / 2, y, c.name, kTextSize, kText);
    y += kTextSize + 6;
  }
}

}  // namespace

Image plotCanvas(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(double(kBackground[k] * 255)));
      p[3] = 255;
    }
  return image;
}

std::vector<Real> niceTicks(Real lo, Real hi, int count) {
  const Real span = hi > lo ? hi - lo : Real(1);
  const Real rough = span / Real(std::max(count, 1));
  const Real power = std::pow(Real(10), std::floor(std::log10(rough)));
  Real step = power;
  for (const Real m : {Real(1), Real(2), Real(5), Real(10)})
    if (m * power >= rough) {
      step = m * power;
      break;
    }
  std::vector<Real> ticks;
  for (Real v = std::ceil(lo / step - Real(1e-6)) * step; v <= hi + step * Real(1e-6); v += step) ticks.push_back(v);
  return ticks;
}

PlotFrame drawLinePlot(Image& image, int x, int y, int width, int height, const std::string& title,
                       const std::string& xName, const std::string& yName, const std::vector<PlotCurve>& curves) {
  PlotFrame f;
  f.min = Vec2(std::numeric_limits<Real>::max(), 0);
  f.max = Vec2(std::numeric_limits<Real>::lowest(), 0);
  for (const PlotCurve& c : curves)
    for (const Vec2& p : c.points) {
      f.min = glm::min(f.min, p);
      f.max = glm::max(f.max, p);
    }
  if (!(f.max.x > f.min.x)) f.max.x = f.min.x + 1;
  if (!(f.max.y > f.min.y)) f.max.y = f.min.y + 1;
  const std::vector<Real> xTicks = niceTicks(f.min.x, f.max.x, 6);
  std::vector<Real> yTicks = niceTicks(f.min.y, f.max.y, 5);
  // The y axis reaches the round tick at or above the data, so that the top curve is not cut.
  if (yTicks.size() > 1 && yTicks.back() < f.max.y - Real(1e-6) * (f.max.y - f.min.y))
    yTicks.push_back(yTicks.back() + (yTicks[1] - yTicks[0]));
  f.max.y = std::max(f.max.y, yTicks.back());
  const Real left = Real(x + 60), right = Real(x + width - 20), top = Real(y + 60), bottom = Real(y + height - 50);
  f.originPixel = Vec2(left, bottom);
  f.pixelsPerUnit = Vec2((right - left) / (f.max.x - f.min.x), -(bottom - top) / (f.max.y - f.min.y));
  const Real yStep = yTicks.size() > 1 ? yTicks[1] - yTicks[0] : Real(1);
  const Real xStep = xTicks.size() > 1 ? xTicks[1] - xTicks[0] : Real(1);
  for (const Real v : yTicks) {
    const Real py = f.toPixel({f.min.x, v}).y;
    line(image, {left, py}, {right, py}, kGrid, 1);
    drawText(image, left - 24, py + 5, tickText(v, yStep), kTextSize, kText);
  }
  for (const Real v : xTicks) {
    const Real px = f.toPixel({v, 0}).x;
    line(image, {px, top}, {px, bottom}, kGrid, 1);
    drawText(image, px, bottom + 20, tickText(v, xStep), kTextSize, kText);
  }
  line(image, {left, top}, {left, bottom}, kAxis, 1.5);
  line(image, {left, bottom}, {right, bottom}, kAxis, 1.5);
  drawText(image, (left + right) / 2, bottom + 42, xName, kTextSize, kText);
  drawText(image, Real(x) + Real(width) / 2, Real(y + 24), title, kTitleSize, kText);
  drawText(image, left + textWidth(yName, kTextSize) / 2 - 40, top - 14, yName, kTextSize, kText);
  for (const PlotCurve& c : curves) {
    std::vector<Vec2> pixels;
    for (const Vec2& p : c.points) pixels.push_back(f.toPixel(p));
    polyline(image, pixels, c.color, 2.5);
  }
  legend(image, right - 150, top + 20, curves);
  return f;
}

PlotFrame drawPolarPlot(Image& image, int x, int y, int width, int height, const std::string& title,
                        const std::vector<PlotCurve>& curves, const std::vector<PlotArrow>& arrows) {
  PlotFrame f;
  const Real radius = std::min(Real(width) / 2 - 40, Real(height) - 110);
  f.originPixel = Vec2(Real(x) + Real(width) / 2, Real(y + height - 50));
  f.pixelsPerUnit = Vec2(radius, -radius);
  f.min = Vec2(0);
  const auto at = [&](Real degrees, Real r) {
    const Real a = glm::radians(degrees);
    return f.toPixel({std::sin(a) * r, std::cos(a) * r});
  };
  // Rings at radius 0.25 .. 1 and the surface.
  for (int ring = 1; ring <= 4; ++ring) {
    std::vector<Vec2> arc;
    for (int d = -90; d <= 90; d += 2) arc.push_back(at(Real(d), Real(ring) / 4));
    polyline(image, arc, kGrid, 1);
  }
  line(image, at(-90, Real(1.1)), at(90, Real(1.1)), kAxis, 2);
  drawText(image, at(90, Real(1.05)).x - 10, f.originPixel.y + 20, "surface", kTextSize, kText);
  for (const PlotArrow& arrow : arrows) {
    const Vec2 tip = at(arrow.degrees, Real(1.08));
    line(image, f.originPixel, tip, arrow.color, 1.5);
    drawText(image, at(arrow.degrees, Real(1.16)).x, at(arrow.degrees, Real(1.16)).y + 5, arrow.name, kTextSize, arrow.color);
  }
  for (const PlotCurve& c : curves) {
    std::vector<Vec2> pixels;
    for (const Vec2& p : c.points) pixels.push_back(at(p.x, p.y));
    polyline(image, pixels, c.color, 2.5);
  }
  drawText(image, Real(x) + Real(width) / 2, Real(y + 24), title, kTitleSize, kText);
  legend(image, Real(x + 16), Real(y + 56), curves);
  return f;
}

}  // namespace illum
