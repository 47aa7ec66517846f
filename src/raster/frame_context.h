// What every stage of one frame needs to know, computed once per frame.
#pragma once

#include <illum/lighting.h>
#include <illum/scene.h>

#include <vector>

namespace illum {

struct FrameContext {
  int width = 0, height = 0;
  Mat4 viewFromWorld{1};  // GL_MODELVIEW before any object transform
  Mat4 clipFromView{1};   // GL_PROJECTION
  std::vector<EyeLight> lights;
  LightModel lightModel;
  LightingModel model = LightingModel::BlinnPhong;
  Shading shading = Shading::Phong;
  bool blend = false;

  static FrameContext fromScene(const Scene& scene);
};

}  // namespace illum
