#include "raster/frame_context.h"

#include "scene/environment_use.h"

#include <algorithm>
#include <stdexcept>

namespace illum {

FrameContext FrameContext::fromScene(const Scene& scene) {
  FrameContext f;
  f.width = scene.width;
  f.height = scene.height;
  f.viewFromWorld = scene.camera.viewFromWorld();
  f.clipFromView = scene.camera.clipFromView(Real(scene.width) / Real(scene.height));
  // Lights are given in world space: GL would see glLight called with GL_MODELVIEW = the view.
  for (const Light& l : scene.lights) f.lights.push_back(toEyeSpace(l, f.viewFromWorld));
  f.lightModel = scene.lightModel;
  f.lightModel.environment = eyeImageLight(scene, f.viewFromWorld);
  f.lightModel.toneMap = scene.display.toneMap;  // lit colours tone mapped before they are quantised
  f.model = scene.model;
  f.shading = scene.shading;
  f.blend = scene.blend;
  return f;
}

void FrameContext::setSamples(std::span<const SubpixelOffset> pattern) {
  samples = pattern;
  multisampled = pattern.size() > 1;
  for (std::size_t k = 0; k < 32 && !pattern.empty(); ++k) {
    const SubpixelOffset& o = pattern[k % pattern.size()];
    if (o.x % 16 != 0 || o.y % 16 != 0) throw std::logic_error("sample offsets must lie on sixteenths of a pixel");
    sampleLanes.x[k] = std::int32_t(o.x / 16), sampleLanes.y[k] = std::int32_t(o.y / 16);
  }
}

FrameContext::SampleReach FrameContext::reach() const {
  SampleReach r;
  for (const SubpixelOffset& o : samples) {
    r.minX = std::min(r.minX, o.x), r.maxX = std::max(r.maxX, o.x);
    r.minY = std::min(r.minY, o.y), r.maxY = std::max(r.maxY, o.y);
  }
  return r;
}

}  // namespace illum
