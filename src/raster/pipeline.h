// The rasterizer's frame on every core (pipeline.cpp): vertex → clip → setup → bin → tiles, then
// points, lines and overlay lines. It draws the scene's linear 8-bit picture; render/ finishes it
// (ambient occlusion, the display encoding, labels).
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include "shading/occlusion.h"

#include <atomic>
#include <memory>

namespace illum {

// Keeps its working memory (framebuffer, tile bins, triangle records, per-thread scratch) from one
// frame to the next: once warm, a frame of the same size allocates nothing but what the scene's
// meshes need.
class RasterPipeline {
 public:
  RasterPipeline();
  ~RasterPipeline();
  RasterPipeline(const RasterPipeline&) = delete;
  RasterPipeline& operator=(const RasterPipeline&) = delete;

  // Draws `scene` into `image` (its memory reused), row 0 at the top. `stats` is filled, its
  // pixelsDrawn with the pixels unlike the background; `probe`, if given, with the watched pixel's
  // last fragment. `occlusion`, if given, occludes the ambient term (the scene's ambient occlusion).
  // `cancel`, if set, stops the frame between tiles and batches (Renderer::setCancel).
  void draw(const Scene& scene, Image& image, RenderStats& stats, PixelProbe* probe,
            const OcclusionQuery* occlusion = nullptr, const std::atomic<bool>* cancel = nullptr);

  // How many tiles' worth of samples the framebuffer holds (its blocks: Framebuffer::blocksMade),
  // for the tests of what a frame keeps in memory.
  std::size_t tileBlocksMade() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace illum
