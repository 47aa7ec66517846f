#include "raster/reference/reference_pipeline.h"

#include "raster/draw.h"

namespace illum {

void drawSceneReference(const Scene& scene, Image& image, RenderStats& stats) {
  const FrameContext frame = FrameContext::fromScene(scene);
  Framebuffer fb(scene.width, scene.height, scene.background);
  const DrawTarget target(frame, scene, fb, nullptr);
  const PixelRect viewport{0, 0, scene.width - 1, scene.height - 1};
  std::vector<ShadedVertex> vertices;
  RecordArena records;
  for (const Object* object : drawingOrder(scene, frame)) {
    if (object->mesh->triangleCount() == 0) continue;  // the oracle is for triangles
    const auto index = std::uint32_t(object - scene.objects.data());
    vertices.resize(object->mesh->positions.size());
    runVertexStage(frame, *object, vertices, 0, vertices.size());
    records.reset(target.layouts[index]);
    stats.trianglesIn += object->mesh->triangleCount();
    stats.trianglesDrawn += setupTriangles(frame, *object, index, vertices, 0, object->mesh->triangleCount(), records);
    for (std::size_t i = 0; i < records.size(); ++i) drawRecord(target, records[i], viewport, stats.fragmentsShaded);
  }
  stats.pixelsDrawn = fb.toImage(image, scene.background);
}

}  // namespace illum
