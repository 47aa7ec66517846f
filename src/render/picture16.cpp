// 16 bits per channel: the display encoding applied to the linear values themselves, then the
// labels, drawn on a transparent layer of their own and laid over.
#include <illum/display.h>
#include <illum/render.h>

#include "render/labels.h"

#include <algorithm>
#include <cmath>

namespace illum {

std::vector<std::uint16_t> picture16(const Scene& scene, const FloatImage& linear) {
  const std::size_t pixels = std::size_t(linear.width) * std::size_t(linear.height);
  std::vector<std::uint16_t> out(pixels * 4);
  const auto word = [](Real v) { return std::uint16_t(std::lround(double(std::clamp(v, Real(0), Real(1))) * 65535.0)); };
  // The rasterizer's values are its framebuffer's, tone mapped already (LightModel::toneMap).
  const Display display = scene.renderer == RendererKind::Raster ? encodingOnly(scene.display) : scene.display;
  for (std::size_t i = 0; i < pixels * 4; ++i)
    out[i] = word(i % 4 == 3 ? Real(linear.rgba[i]) : displayValue(Real(linear.rgba[i]), display));
  Image layer(linear.width, linear.height);  // transparent black: text leaves premultiplied colour
  if (scene.labels.empty() || !drawLabels(layer, scene)) return out;
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t* l = &layer.rgba[4 * i];
    if (l[3] == 0) continue;
    const double a = l[3] / 255.0;
    for (std::size_t c = 0; c < 4; ++c) {
      const double over = c < 3 ? l[c] / 255.0 : a;
      out[4 * i + c] = std::uint16_t(std::lround((over + out[4 * i + c] / 65535.0 * (1 - a)) * 65535.0));
    }
  }
  return out;
}

}  // namespace illum
