#include "raster/labels.h"

#include "image/text.h"
#include "raster/overlay.h"

namespace illum {

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
    drawText(image, at.x, at.y, label.text, label.size, label.color);
  }
  return true;
}

}  // namespace illum
