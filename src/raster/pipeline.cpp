// The pipeline in order: vertex → clip → setup → bin → rasterize → fragment → framebuffer, on
// every core (oneTBB). Vertices are shaded in parallel ranges; triangles are clipped and set up
// in parallel chunks into self-contained records, concatenated in submission order; the records
// are binned into 64×64 tiles and each tile is drawn by one thread, its records in order. Every
// pixel therefore sees the same fragments in the same order as on one thread: the same bytes for
// any thread count, and the same as the reference driver (reference/).
#include <illum/render.h>

#include "raster/bin.h"
#include "raster/draw.h"
#include "raster/shade_tile.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace illum {
namespace {

constexpr std::size_t kVertexGrain = 4096;       // vertices per parallel task
constexpr std::size_t kTriangleChunk = 1024;     // triangles set up per parallel task
constexpr std::size_t kBatchRecords = 1 << 13;   // records gathered before they are binned and drawn

}  // namespace

// What a Renderer keeps from frame to frame.
struct Renderer::State {
  Framebuffer fb;
  TileBins bins;
  std::vector<std::size_t> tileFragments;
  std::vector<ShadedVertex> vertices;
  tbb::enumerable_thread_specific<TileScratch> scratch;
  std::vector<RecordArena> pool;  // per chunk; moving the outer vector keeps the records in place
};

namespace {

// One frame through the pipeline, in the renderer's working memory.
class BinnedFrame {
 public:
  BinnedFrame(Renderer::State& state, const Scene& scene, const FrameContext& frame, PixelProbe* probe)
      : s_(state), frame_(frame), target_(frame, scene, state.fb, probe) {
    s_.fb.reset(scene.width, scene.height, scene.background);
    s_.bins.reset(frame.width, frame.height);
    s_.tileFragments.assign(std::size_t(s_.bins.tileCount()), 0);
  }

  void drawObject(const Object& object, std::uint32_t index) {
    auto& vertices = s_.vertices;
    vertices.resize(object.mesh->positions.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), kVertexGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        runVertexStage(frame_, object, vertices, r.begin(), r.end());
                      });
    const std::size_t triangles = object.mesh->triangleCount();
    stats_.trianglesIn += triangles;
    const std::size_t chunks = (triangles + kTriangleChunk - 1) / kTriangleChunk;
    // A slice of chunks is set up in parallel, each into an arena of its own, then binned in
    // chunk order; the records stay in their arenas until the batch is drawn.
    const std::size_t slice = std::max<std::size_t>(1, kBatchRecords / kTriangleChunk);
    for (std::size_t c0 = 0; c0 < chunks; c0 += slice) {
      const std::size_t c1 = std::min(chunks, c0 + slice);
      if (s_.pool.size() < used_ + (c1 - c0)) s_.pool.resize(used_ + (c1 - c0));
      tbb::parallel_for(c0, c1, [&](std::size_t c) {
        RecordArena& out = s_.pool[used_ + (c - c0)];
        out.reset(target_.layouts[index]);
        setupTriangles(frame_, object, index, vertices, c * kTriangleChunk, std::min(triangles, (c + 1) * kTriangleChunk),
                       out);
      });
      for (std::size_t c = c0; c < c1; ++c) {
        const RecordArena& part = s_.pool[used_++];
        s_.bins.bin(part);
        batched_ += part.size();
        stats_.trianglesDrawn += part.size();
      }
      if (batched_ >= kBatchRecords) flush();
    }
  }

  // Draws every tile of what has been binned, each tile on one thread, its records in order:
  // opaque drawing shades each visible pixel once (shade_tile.h), blending fragment by fragment.
  void flush() {
    if (batched_ == 0) return;
    tbb::parallel_for(0, s_.bins.tileCount(), [&](int tile) {
      const PixelRect rect = s_.bins.tileRect(tile);
      const auto& records = s_.bins.records(tile);
      if (records.empty()) return;
      std::size_t& fragments = s_.tileFragments[std::size_t(tile)];
      if (frame_.blend) {
        for (const DrawRecord* r : records) drawRecord(target_, *r, rect, fragments);
      } else {
        fragments += drawOpaqueTile(target_, records, rect, s_.scratch.local());
      }
    });
    s_.bins.clear();
    used_ = 0;
    batched_ = 0;
  }

  RenderStats stats() const {
    RenderStats s = stats_;
    for (std::size_t f : s_.tileFragments) s.fragmentsShaded += f;
    return s;
  }

 private:
  Renderer::State& s_;
  const FrameContext& frame_;
  DrawTarget target_;
  std::size_t used_ = 0, batched_ = 0;
  RenderStats stats_;
};

}  // namespace

Renderer::Renderer() : state_(std::make_unique<State>()) {}
Renderer::~Renderer() = default;

void Renderer::render(const Scene& scene, Image& image, RenderStats* statsOut, PixelProbe* probe) {
  const FrameContext frame = FrameContext::fromScene(scene);
  if (probe) probe->hit = false;
  BinnedFrame pass(*state_, scene, frame, probe);
  for (const Object* object : drawingOrder(scene, frame))
    pass.drawObject(*object, std::uint32_t(object - scene.objects.data()));
  pass.flush();
  RenderStats stats = pass.stats();
  finishFrame(state_->fb, scene, stats, image);
  if (statsOut) *statsOut = stats;
}

Image renderScene(const Scene& scene, RenderStats* stats, PixelProbe* probe) {
  Renderer renderer;
  Image image;
  renderer.render(scene, image, stats, probe);
  return image;
}

}  // namespace illum
