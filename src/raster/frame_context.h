// What every stage of one frame needs to know, computed once per frame.
#pragma once

#include <illum/lighting.h>
#include <illum/scene.h>

#include <cstdint>

#include <vector>

namespace illum {

// Where a multisample pass samples, from the pixel centre, in sub-pixel units (1/256 pixel).
struct SubpixelOffset {
  std::int64_t x = 0, y = 0;
};

struct FrameContext {
  int width = 0, height = 0;
  Mat4 viewFromWorld{1};  // GL_MODELVIEW before any object transform
  Mat4 clipFromView{1};   // GL_PROJECTION
  std::vector<EyeLight> lights;
  LightModel lightModel;
  LightingModel model = LightingModel::BlinnPhong;
  Shading shading = Shading::Phong;
  bool blend = false;
  // Multisampling: this pass's sample position from the pixel centre; coverage and depth are
  // tested there, while the pixel is shaded at its centre (so a pixel a triangle covers whole
  // gets the colour one sample gives). {0, 0} without multisampling.
  SubpixelOffset sample;
  bool multisampled = false;

  // Phong shading lights each pixel at its own point (the material at that point, its maps).
  bool litPerPixel() const { return shading == Shading::Phong; }

  static FrameContext fromScene(const Scene& scene);
};

}  // namespace illum
