// The renderers behind one door: the scene says which draws it (the rasterizer, Whitted's or
// Hall's ray tracer, the path tracer), and every picture is finished here the same way.
#include <illum/render.h>

#include "raster/pipeline.h"
#include "render/environment_behind.h"
#include "render/finish.h"
#include "shading/shade_points.h"
#include "trace/ambient_occlusion.h"
#include "trace/ray_tracer.h"

#include <optional>

namespace illum {

// What a Renderer keeps from frame to frame: the rasterizer's working memory.
struct Renderer::State {
  RasterPipeline raster;
};

Renderer::Renderer() : state_(std::make_unique<State>()) {}
Renderer::~Renderer() = default;

void Renderer::render(const Scene& scene, Image& image, RenderStats* statsOut, PixelProbe* probe, FloatImage* linear) {
  RenderStats stats;
  // The environment behind the scene: drawn over a transparent background, then laid over it.
  const bool environmentBehind = showsEnvironmentBehind(scene);
  std::optional<Scene> overTransparent;
  if (environmentBehind) overTransparent.emplace(scene).background = Color4(0);
  const Scene& drawn = environmentBehind ? *overTransparent : scene;
  if (scene.renderer == RendererKind::Raster) {
    // Ambient occlusion is traced for the points the rasterizer lights (trace/ambient_occlusion.h).
    std::unique_ptr<TracedOcclusion> occlusion;
    if (scene.ambientOcclusion.enabled && !scene.objects.empty()) occlusion = std::make_unique<TracedOcclusion>(scene);
    state_->raster.draw(drawn, image, stats, probe, occlusion.get(), cancel_);
    finishRasterPicture(drawn, stats, image, linear, environmentBehind);
  } else {
    traceScene(drawn, image, stats, probe, linear, progress_, cancel_);
    finishTracedPicture(drawn, stats, image, environmentBehind);
  }
  if (statsOut) *statsOut = stats;
}

const char* simdTarget() { return simdTargetName(); }

Image renderScene(const Scene& scene, RenderStats* stats, PixelProbe* probe, FloatImage* linear) {
  Renderer renderer;
  Image image;
  renderer.render(scene, image, stats, probe, linear);
  return image;
}

}  // namespace illum
