#include "render/labels.h"

#include <illum/captions.h>
#include <illum/error.h>

#include "image/text.h"
#include "raster/lines/wide_segment.h"

#include <algorithm>
#include <cmath>

namespace illum {

void drawAxesGizmo(Image& image, const Scene& scene) {
  const Real size = std::clamp(Real(std::min(image.width, image.height)) / 10, Real(14), Real(48));
  const Vec2 origin(size * Real(1.4), Real(image.height) - size * Real(1.4));  // row 0 at the top
  const Mat3 viewFromWorld(scene.camera.viewFromWorld());
  const Vec3 colours[3] = {{0.95f, 0.25f, 0.25f}, {0.3f, 0.85f, 0.3f}, {0.35f, 0.5f, 1}};
  const char* names[3] = {"X", "Y", "Z"};
  // The axis pointing most away from the viewer first, so the nearer ones are drawn over it.
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return (viewFromWorld * Vec3(i == 0, i == 1, i == 2)).z <
                                                         (viewFromWorld * Vec3(j == 0, j == 1, j == 2)).z; });
  for (int i : order) {
    const Vec3 d = viewFromWorld * Vec3(i == 0, i == 1, i == 2);
    const Vec2 tip = origin + size * Vec2(d.x, -d.y);
    const int x0 = std::max(0, int(std::floor(std::min(origin.x, tip.x) - 2))),
              x1 = std::min(image.width - 1, int(std::ceil(std::max(origin.x, tip.x) + 2)));
    const int y0 = std::max(0, int(std::floor(std::min(origin.y, tip.y) - 2))),
              y1 = std::min(image.height - 1, int(std::ceil(std::max(origin.y, tip.y) + 2)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        // Coverage of a line 2 pixels wide, by the pixel centre's distance from it.
        const Real cover = std::clamp(Real(1.5) - toSegment(Vec2(Real(x) + 0.5f, Real(y) + 0.5f), origin, tip).first,
                                      Real(0), Real(1));
        if (cover <= 0) continue;
        std::uint8_t* p = image.pixel(x, y);
        for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround(p[c] * (1 - cover) + colours[i][c] * 255 * cover));
        p[3] = std::uint8_t(std::lround(p[3] * (1 - cover) + 255 * cover));
      }
    const Vec2 label = origin + (size + 9) * Vec2(d.x, -d.y);
    drawText(image, label.x, label.y + 5, names[i], 13, colours[i]);
  }
}


bool drawLabels(Image& image, const Scene& scene) {
  if (scene.overlays.axes) drawAxesGizmo(image, scene);
  if (scene.labels.empty()) return true;
  if (!labelFontAvailable()) return false;
  const Mat4 clipFromWorld =
      scene.camera.clipFromView(Real(scene.width) / Real(scene.height)) * scene.camera.viewFromWorld();
  for (const Label& label : scene.labels) {
    Vec2 at(0);
    if (label.pixel) {
      at = *label.pixel;
    } else {
      const Vec4 clip = clipFromWorld * Vec4(*label.position, 1);
      if (!(clip.w > 0)) continue;  // behind the camera
      // Window coordinates with row 0 at the top; the text hangs just below the point.
      at = Vec2((clip.x / clip.w + 1) * Real(0.5) * Real(scene.width),
                (1 - clip.y / clip.w) * Real(0.5) * Real(scene.height) + label.size);
    }
    // A caption is filled in from the scene as drawn; one whose light or object an override took
    // away (a sheet's light-count axis) has nothing left to describe and is left out.
    std::string text;
    try {
      text = expandCaption(label.text, scene);
    } catch (const InputError&) {
      continue;
    }
    drawText(image, at.x, at.y, text, label.size, label.color);
  }
  return true;
}

std::vector<std::string> overlaysCovering(const Scene& scene, int x, int y) {
  std::vector<std::string> over;
  Image blank(scene.width, scene.height);
  const auto touched = [&](const Scene& only) {
    std::fill(blank.rgba.begin(), blank.rgba.end(), std::uint8_t(0));
    drawLabels(blank, only);
    const std::uint8_t* p = blank.pixel(x, y);
    return p[0] || p[1] || p[2] || p[3];
  };
  Scene one = scene;
  one.labels.clear();
  if (scene.overlays.axes && touched(one)) over.push_back("the axes gizmo");
  one.overlays.axes = false;
  for (const Label& label : scene.labels) {
    one.labels = {label};
    if (!touched(one)) continue;
    std::string text;
    try {
      text = expandCaption(label.text, scene);
    } catch (const InputError&) {
      continue;
    }
    over.push_back("the label \"" + text + "\"");
  }
  return over;
}

}  // namespace illum
