#include "raster/probe.h"

#include "raster/shade/draw.h"

#include <algorithm>

namespace illum {

void probePixel(const Scene& scene, const FrameContext& frame, PixelProbe& probe) {
  probe.hit = false;
  FrameContext pass = frame;
  const std::span<const SubpixelOffset> samples = frame.samples;
  pass.samples = {};
  if (samples.size() > 1) pass.sample = samples[0], pass.multisampled = true;
  // A framebuffer of the frame's size, of which only the watched pixel's tile is ever touched.
  Framebuffer fb;
  fb.reset(scene.width, scene.height, scene.background);
  const int row = scene.height - 1 - probe.y;  // GL rows run bottom up
  fb.clearTile(probe.x / kTileSize * kTileSize, row / kTileSize * kTileSize);
  const DrawTarget target(pass, scene, fb, &probe);
  const PixelRect pixel{probe.x, row, probe.x, row};
  std::vector<ShadedVertex> vertices;
  RecordArena records;
  std::size_t fragments = 0;
  for (const Object* object : drawingOrder(scene, pass)) {
    if (object->mesh->triangleCount() == 0) continue;
    const auto index = std::uint32_t(object - scene.objects.data());
    vertices.resize(object->mesh->positions.size());
    runVertexStage(pass, *object, index, vertices, 0, vertices.size());
    // A chunk of records at a time: a dense mesh's would not fit in memory at once.
    constexpr std::size_t kChunk = 4096;
    for (std::size_t first = 0, n = object->mesh->triangleCount(); first < n; first += kChunk) {
      records.reset(target.layouts[index]);
      setupTriangles(pass, *object, index, vertices, first, std::min(n, first + kChunk), records);
      for (std::size_t i = 0; i < records.size(); ++i) drawRecord(target, records[i], pixel, fragments);
    }
  }
}

}  // namespace illum
