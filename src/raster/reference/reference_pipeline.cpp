#include "raster/reference/reference_pipeline.h"

#include "raster/draw.h"
#include "raster/multisample.h"

namespace illum {

namespace {

// One pass: every triangle drawn in submission order over the whole viewport into `fb`, set up
// for the frame's sample position.
void drawPass(const Scene& scene, const FrameContext& frame, Framebuffer& fb, RenderStats& stats) {
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
}

}  // namespace

// Multisampled, the way multisampling was first done on one thread: one whole pass per sample
// position into a framebuffer of its own (coverage and depth at the sample, the colour at the
// pixel centre), then the passes averaged.
void drawSceneReference(const Scene& scene, Image& image, RenderStats& stats) {
  FrameContext frame = FrameContext::fromScene(scene);
  const std::span<const SubpixelOffset> samples = multisamplePattern(scene.multisample);
  frame.multisampled = samples.size() > 1;
  std::vector<Framebuffer> passes;
  for (const SubpixelOffset& sample : samples) {
    frame.sample = sample;
    passes.emplace_back(scene.width, scene.height, scene.background);
    RenderStats passStats;
    drawPass(scene, frame, passes.back(), passStats);
    if (passes.size() == 1) stats = passStats;
    else stats.fragmentsShaded += passStats.fragmentsShaded;
  }
  image = Image(scene.width, scene.height);
  const std::uint32_t background8 = packUnorm8(scene.background);
  stats.pixelsDrawn = 0;
  for (int tile = 0; tile < passes.front().tileCount(); ++tile)
    stats.pixelsDrawn += resolveTile(passes, tile, image, background8);
}

}  // namespace illum
