// Rendering a scene to an image: with the rasterizer (flat, Gouraud or Phong shading) or, as the
// scene's "renderer" says, with Whitted's or Hall's ray tracer.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

#include <array>
#include <cstdint>
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace illum {

struct RenderStats {
  std::size_t trianglesIn = 0;       // triangles submitted
  std::size_t trianglesDrawn = 0;    // triangles after clipping that reached the rasterizer
  std::size_t fragmentsShaded = 0;   // fragments that passed the depth test
  std::size_t pixelsDrawn = 0;       // pixels whose colour differs from the background (labels aside)
  bool labelsSkipped = false;        // the scene has labels but the label font is not installed
  // The ray tracers ("renderer": "whitted" or "hall"):
  std::uint64_t primaryRays = 0;     // camera rays, one per pixel and sample
  std::uint64_t secondaryRays = 0;   // reflected, refracted and see-through rays
  std::uint64_t shadowRays = 0;
  double primaryRaySeconds = 0;      // CPU time in the primary rays' BVH queries, summed over threads
  double bvhMs = 0;                  // building the BVH, part of the frame
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
  // What the fragment stage computed, step by step:
  //   flat:    `lit` is the colour lit at the provoking (last) vertex, used as it is;
  //   gouraud: `vertexColors` were lit at the drawn (clipped) triangle's vertices, and `lit` is
  //            their perspective-correct blend with `weights`;
  //   phong:   `lit` is the equation evaluated here (clamped), as `eyePosition` and `eyeNormal` say.
  std::array<Color4, 3> vertexColors{};
  std::array<Vec3, 3> vertexPositions{}, vertexNormals{};  // eye space, as lit (normals facing the lit side)
  std::array<Material, 3> vertexMaterials{};               // with each vertex's colour applied
  std::array<Real, 3> weights{};
  Color4 lit{0};
  bool textured = false;
  Vec4 texel{1};             // GL_MODULATE's factor, when textured
  bool texelIsBaseColor = false;  // cook-torrance per pixel: the texel tinted the base colour instead
  Color4 written{0};         // the fragment's colour: lit × texel, before 8-bit conversion and blending
  bool blended = false;      // source-over blending mixed it with what was there
  // Ray tracers: `lit` is the local equation with shadows (× texel), `written` what the ray brought
  // back (with mirror, glass and see-through rays, unclamped), and each light's visibility from here.
  std::vector<Color3> lightVisibility;
  // Multisampled rasterizer: what a pass at each sample position writes at the pixel, in the
  // pattern's order (the fields above are sample 0's).
  struct Sample {
    Vec2 offset{0};  // from the pixel's centre, in pixels (x right, y down)
    bool hit = false;
    std::size_t object = 0, triangle = 0;
    Color4 written{0};
    bool blended = false;
  };
  std::vector<Sample> samples;
};

// Renders frame after frame, keeping its working memory (framebuffer, tile bins, triangle
// records, per-thread scratch) from one frame to the next: once warm, a frame of the same size
// allocates nothing but what the scene's meshes need.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // As renderScene, into `image` (its memory reused).
  // With `linear`, the unclamped values too (for OpenEXR output and tests).
  void render(const Scene& scene, Image& image, RenderStats* stats = nullptr, PixelProbe* probe = nullptr,
              FloatImage* linear = nullptr);

  // Called with the fraction of the picture done, from the rendering threads (the ray and path
  // tracers, tile by tile, one call at a time, each fraction larger than the last), so that a long
  // render can show its progress.
  void onProgress(std::function<void(double)> progress) { progress_ = std::move(progress); }
  // A flag read between tiles (and between a frame's batches of triangles): once it is set, the
  // frame in flight stops early and render() returns a picture that is not to be used. A viewer
  // sets it when a newer frame is wanted. Null: never.
  void setCancel(const std::atomic<bool>* cancel) { cancel_ = cancel; }

  struct State;  // defined by render/renderer.cpp

 private:
  std::unique_ptr<State> state_;
  std::function<void(double)> progress_;
  const std::atomic<bool>* cancel_ = nullptr;
};

// The picture at 16 bits per channel, for a 16-bit PNG: `linear` (the values render() gives) through
// the scene's display encoding at full precision, with the scene's labels over it; RGBA, rows top
// to bottom.
std::vector<std::uint16_t> picture16(const Scene& scene, const FloatImage& linear);

// What is drawn over pixel (x, y) after the picture (the scene's labels, as their text says, and
// the axes gizmo), each drawn alone: for `--debug-pixel`'s last step.
std::vector<std::string> overlaysCovering(const Scene& scene, int x, int y);

// The SIMD instruction set the renderer's kernels run with on this CPU, chosen at run time
// ("AVX3" is AVX-512, then "AVX2", "SSE4", ...).
const char* simdTarget();

// Renders like OpenGL 2.1 fixed-function (or its per-pixel equivalent) into an RGBA8 image,
// row 0 at the top. The same scene gives the same bytes on every run.
Image renderScene(const Scene& scene, RenderStats* stats = nullptr, PixelProbe* probe = nullptr,
                  FloatImage* linear = nullptr);

}  // namespace illum
