#include "render/reference_render.h"

#include "raster/reference/reference_pipeline.h"
#include "render/finish.h"
#include "trace/ambient_occlusion.h"

#include <memory>

namespace illum {

Image renderSceneReference(const Scene& scene, RenderStats* statsOut) {
  Image image;
  RenderStats stats;
  std::unique_ptr<TracedOcclusion> occlusion;
  if (scene.ambientOcclusion.enabled && !scene.objects.empty()) occlusion = std::make_unique<TracedOcclusion>(scene);
  drawSceneReference(scene, image, stats, occlusion.get());
  finishRasterPicture(scene, stats, image, nullptr);
  if (statsOut) *statsOut = stats;
  return image;
}

}  // namespace illum
