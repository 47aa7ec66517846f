// Rendering a scene to an image with the rasterizer (flat, Gouraud or Phong shading).
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum {

struct RenderStats {
  std::size_t trianglesIn = 0;       // triangles submitted
  std::size_t trianglesDrawn = 0;    // triangles after clipping that reached the rasterizer
  std::size_t fragmentsShaded = 0;   // fragments that passed the depth test
  bool labelsSkipped = false;        // the scene has labels but the label font is not installed
};

// Renders like OpenGL 2.1 fixed-function (or its per-pixel equivalent) into an RGBA8 image,
// row 0 at the top. The same scene gives the same bytes on every run.
Image renderScene(const Scene& scene, RenderStats* stats = nullptr);

}  // namespace illum
