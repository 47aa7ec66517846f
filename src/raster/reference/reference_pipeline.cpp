#include "raster/reference/reference_pipeline.h"

#include "raster/shade/draw.h"
#include "raster/tile/multisample.h"

#include <cstring>

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
    runVertexStage(frame, *object, index, vertices, 0, vertices.size());
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
void drawSceneReference(const Scene& scene, Image& image, RenderStats& stats, const OcclusionQuery* occlusion) {
  FrameContext frame = FrameContext::fromScene(scene);
  frame.occlusion = occlusion;
  const std::span<const SubpixelOffset> samples = multisamplePattern(scene.multisample);
  frame.multisampled = samples.size() > 1;
  std::vector<Image> passes;
  for (const SubpixelOffset& sample : samples) {
    frame.sample = sample;
    Framebuffer fb(scene.width, scene.height, scene.background);
    RenderStats passStats;
    drawPass(scene, frame, fb, passStats);
    if (passes.empty()) stats = passStats;
    else stats.fragmentsShaded += passStats.fragmentsShaded;
    passes.push_back(fb.toImage());
  }
  image = Image(scene.width, scene.height);
  const std::uint32_t background8 = packUnorm8(scene.background);
  stats.pixelsDrawn = 0;
  std::vector<std::uint32_t> words(passes.size());
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    for (std::size_t s = 0; s < passes.size(); ++s) std::memcpy(&words[s], &passes[s].rgba[i], 4);
    const std::uint32_t word = resolvePixel(words.data(), int(words.size()));
    std::memcpy(&image.rgba[i], &word, 4);
    stats.pixelsDrawn += word != background8;
  }
}

}  // namespace illum
