#include "render/reference_render.h"

#include "raster/reference/reference_pipeline.h"
#include "render/finish.h"

namespace illum {

Image renderSceneReference(const Scene& scene, RenderStats* statsOut) {
  Image image;
  RenderStats stats;
  drawSceneReference(scene, image, stats);
  finishRasterPicture(scene, stats, image, nullptr);
  if (statsOut) *statsOut = stats;
  return image;
}

}  // namespace illum
