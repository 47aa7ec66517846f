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

// What happened at one pixel: the last fragment that passed the depth test there (--debug-pixel).
struct PixelProbe {
  int x = 0, y = 0;          // the pixel to watch, row 0 at the top
  bool hit = false;          // whether any fragment was written there
  std::size_t object = 0;    // index into Scene::objects
  std::size_t triangle = 0;  // triangle of that object's mesh
  bool frontFacing = true;
  // Where the equation was evaluated, in eye space: the pixel's perspective-correct position and
  // normal (Phong shading), or the provoking vertex's (flat shading); for Gouraud shading the
  // colours were lit at the vertices and this is the point between them.
  Vec3 eyePosition{0};
  Vec3 eyeNormal{0};         // unit; negated on a back face under two-sided lighting
  Material material;         // with vertex colours applied
  Color4 written{0};         // the fragment's colour before 8-bit conversion (and blending)
};

// Renders like OpenGL 2.1 fixed-function (or its per-pixel equivalent) into an RGBA8 image,
// row 0 at the top. The same scene gives the same bytes on every run.
Image renderScene(const Scene& scene, RenderStats* stats = nullptr, PixelProbe* probe = nullptr);

}  // namespace illum
