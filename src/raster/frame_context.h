// What every stage of one frame needs to know, computed once per frame.
#pragma once

#include <illum/lighting.h>
#include <illum/scene.h>

#include "shading/occlusion.h"

#include <cstdint>

#include <span>
#include <vector>

namespace illum {

// Where a multisample pass samples, from the pixel centre, in sub-pixel units (1/256 pixel).
struct SubpixelOffset {
  std::int64_t x = 0, y = 0;
};

// The most samples per pixel a frame takes (the standard patterns go up to 16).
constexpr int kSamplesMax = 16;

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
  // Multisampling in one pass (pipeline.cpp): the triangles are set up once, at the pixel
  // centres, and each tile keeps coverage, depth and colour per sample of this pattern (more
  // than one offset), resolved in the tile. Empty otherwise (and in a pass of one sample).
  std::span<const SubpixelOffset> samples;
  // The samples' offsets in sixteenths of a pixel (the standard patterns lie on them), repeated
  // lane after lane (lane k: sample k mod count), as the coverage kernel's vectors take them.
  struct SampleLanes {
    std::int32_t x[32] = {}, y[32] = {};
  } sampleLanes;
  void setSamples(std::span<const SubpixelOffset> pattern);
  // Ambient occlusion, when the scene asks for it (traced from above: render/): it scales the
  // ambient term of every point lit, each pixel's under Phong shading, each vertex's otherwise.
  const OcclusionQuery* occlusion = nullptr;

  // How far, in sub-pixel units, the samples of a pixel lie from its centre (setup widens a
  // triangle's pixel bounds by it, so that they hold every pixel with a covered sample).
  struct SampleReach {
    std::int64_t minX = 0, maxX = 0, minY = 0, maxY = 0;
  };
  SampleReach reach() const;

  // Phong shading lights each pixel at its own point (the material at that point, its maps).
  bool litPerPixel() const { return shading == Shading::Phong; }

  static FrameContext fromScene(const Scene& scene);
};

}  // namespace illum
