#include "raster/probe.h"

#include "raster/setup/setup.h"
#include "raster/shade/draw.h"

#include <algorithm>

namespace illum {

namespace {

// The fragments a pass of `pass` writes at the probe's pixel: every triangle of the scene, in the
// drawing order, over that one pixel; the probe keeps the last.
void drawOverPixel(const Scene& scene, const FrameContext& pass, PixelProbe& probe) {
  probe.hit = false;
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

}  // namespace

void probePixel(const Scene& scene, const FrameContext& frame, PixelProbe& probe) {
  FrameContext pass = frame;
  const std::span<const SubpixelOffset> samples = frame.samples;
  pass.samples = {};
  if (samples.size() > 1) pass.sample = samples[0], pass.multisampled = true;
  drawOverPixel(scene, pass, probe);
  probe.samples.clear();
  if (samples.size() <= 1) return;
  // Every sample, as a pass at its position draws it (the resolve is their mean).
  for (std::size_t s = 0; s < samples.size(); ++s) {
    PixelProbe at;
    at.x = probe.x, at.y = probe.y;
    pass.sample = samples[s];
    drawOverPixel(scene, pass, at);
    const Vec2 offset(Real(samples[s].x) / Real(kSubpixelOne), -Real(samples[s].y) / Real(kSubpixelOne));
    probe.samples.push_back({offset, at.hit, at.object, at.triangle, at.written, at.blended});
  }
}

}  // namespace illum
