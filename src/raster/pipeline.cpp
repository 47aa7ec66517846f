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

class BinnedRenderer {
 public:
  BinnedRenderer(const Scene& scene, const FrameContext& frame, Framebuffer& fb, PixelProbe* probe)
      : frame_(frame), target_(frame, scene, fb, probe), bins_(frame.width, frame.height),
        tileFragments_(std::size_t(bins_.tileCount()), 0) {}

  void drawObject(const Object& object, std::uint32_t index) {
    vertices_.resize(object.mesh->positions.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices_.size(), kVertexGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        runVertexStage(frame_, object, vertices_, r.begin(), r.end());
                      });
    const std::size_t triangles = object.mesh->triangleCount();
    stats_.trianglesIn += triangles;
    const std::size_t chunks = (triangles + kTriangleChunk - 1) / kTriangleChunk;
    // A slice of chunks is set up in parallel, each into a vector of its own, then binned in
    // chunk order; the records stay in their vectors until the batch is drawn.
    const std::size_t slice = std::max<std::size_t>(1, kBatchRecords / kTriangleChunk);
    for (std::size_t c0 = 0; c0 < chunks; c0 += slice) {
      const std::size_t c1 = std::min(chunks, c0 + slice);
      if (pool_.size() < used_ + (c1 - c0)) pool_.resize(used_ + (c1 - c0));
      tbb::parallel_for(c0, c1, [&](std::size_t c) {
        RecordArena& out = pool_[used_ + (c - c0)];
        out.reset(target_.layouts[index]);
        setupTriangles(frame_, object, index, vertices_, c * kTriangleChunk, std::min(triangles, (c + 1) * kTriangleChunk),
                       out);
      });
      for (std::size_t c = c0; c < c1; ++c) {
        const RecordArena& part = pool_[used_++];
        bins_.bin(part);
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
    tbb::parallel_for(0, bins_.tileCount(), [&](int tile) {
      const PixelRect rect = bins_.tileRect(tile);
      const auto& records = bins_.records(tile);
      if (records.empty()) return;
      std::size_t& fragments = tileFragments_[std::size_t(tile)];
      if (frame_.blend) {
        for (const DrawRecord* r : records) drawRecord(target_, *r, rect, fragments);
      } else {
        fragments += drawOpaqueTile(target_, records, rect, scratch_.local());
      }
    });
    bins_.clear();
    used_ = 0;
    batched_ = 0;
  }

  RenderStats stats() const {
    RenderStats s = stats_;
    for (std::size_t f : tileFragments_) s.fragmentsShaded += f;
    return s;
  }

 private:
  const FrameContext& frame_;
  DrawTarget target_;
  TileBins bins_;
  std::vector<std::size_t> tileFragments_;
  std::vector<ShadedVertex> vertices_;
  tbb::enumerable_thread_specific<TileScratch> scratch_;
  std::vector<RecordArena> pool_;  // per chunk; moving the outer vector keeps the records in place
  std::size_t used_ = 0, batched_ = 0;
  RenderStats stats_;
};

}  // namespace

Image renderScene(const Scene& scene, RenderStats* statsOut, PixelProbe* probe) {
  const FrameContext frame = FrameContext::fromScene(scene);
  Framebuffer fb(scene.width, scene.height, scene.background);
  if (probe) probe->hit = false;
  BinnedRenderer renderer(scene, frame, fb, probe);
  for (const Object* object : drawingOrder(scene, frame))
    renderer.drawObject(*object, std::uint32_t(object - scene.objects.data()));
  renderer.flush();
  RenderStats stats = renderer.stats();
  Image image = finishFrame(fb, scene, stats);
  if (statsOut) *statsOut = stats;
  return image;
}

}  // namespace illum
