// The pipeline in order: vertex → clip → setup → bin → rasterize → fragment → framebuffer, on
// every core (oneTBB). Vertices are shaded in parallel ranges; triangles are clipped and set up
// in parallel chunks into self-contained records, concatenated in submission order; the records
// are binned into 64×64 tiles and each tile is drawn by one thread, its records in order. Every
// pixel therefore sees the same fragments in the same order as on one thread: the same bytes for
// any thread count, and the same as the reference driver (reference/).
#include "raster/pipeline.h"

#include "raster/setup/bin.h"
#include "raster/setup/object_reach.h"
#include "raster/shade/draw.h"
#include "raster/tile/multisample.h"
#include "raster/lines/overlay.h"
#include "raster/lines/points_lines.h"
#include "raster/probe.h"
#include "raster/shade/shade_tile.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <atomic>
#include <span>

namespace illum {
namespace {

constexpr std::size_t kVertexGrain = 512;        // vertices per parallel task
constexpr std::size_t kTriangleChunk = 1024;     // triangles set up per parallel task
constexpr std::size_t kSmallRun = 1 << 15;       // vertices of a run of objects shaded together
// What is gathered before it is binned and drawn: records, or tiny triangles (whose pixels take
// less memory than a record, but whose chunks each keep per-tile lists).
constexpr std::size_t kBatchRecords = 1 << 15;
constexpr std::size_t kBatchTiny = 1 << 16;

}  // namespace

// What the pipeline keeps from frame to frame.
struct RasterPipeline::State {
  // Every sample of the pixels of the tiles in progress. A tile drawn once, in the frame's last
  // flush, lives in its thread's memory instead (Framebuffer::lendTile); one that no object still
  // to come can reach is finished when its last one is drawn and gives its block back
  // (BinnedFrame::finishEarly): the framebuffer's blocks are those of tiles that several flushes draw.
  Framebuffer fb;
  std::vector<std::size_t> tileFragments;
  std::vector<ShadedVertex> vertices;  // a run of objects' (BinnedFrame::drawObjects)
  struct Member {
    const Object* object;
    std::uint32_t index;  // in the scene
    std::uint32_t order;  // in the drawing order
    std::size_t base;     // its first vertex in `vertices`
  };
  std::vector<Member> group;
  // Vertices or triangles [first, last) of a member: the parallel tasks of a run.
  struct Range {
    const Member* member;
    std::size_t first, last;
  };
  std::vector<Range> ranges;
  tbb::enumerable_thread_specific<TileScratch> scratch;
  // Per chunk of triangles: its records and which tiles each touches, filled by one task.
  struct Chunk {
    RecordArena records;  // moving a Chunk keeps the records in place
    TileBins bins;
    std::size_t drawn = 0;  // pieces drawn: records and tiny triangles
  };
  std::vector<Chunk> pool;
  // Per chunk of the pool, the tiles it touched: a tile looks through these, side by side in
  // memory, rather than through every chunk's bins (a 4K frame has two thousand tiles).
  std::vector<TileSpan> spans;
  // One tile's lists, gathered from the chunks: its records, and its tiny triangles' pixels,
  // each counting the records before it in `records`.
  struct TileList {
    std::vector<const DrawRecord*> records;
    std::vector<TinyRun<TinyFragment>> fragments;
    std::vector<TinyRun<TinySurface>> surfaces;
  };
  tbb::enumerable_thread_specific<TileList> tileLists;
  tbb::affinity_partitioner tileAffinity;
  // Per tile: the last object that can reach it, and whether it is in the image already
  // (BinnedFrame::finishEarly).
  TileReach reach;
  std::vector<std::uint8_t> finished;
};

namespace {

// One frame through the pipeline, in the renderer's working memory.
class BinnedFrame {
 public:
  // `image`, when given, takes the tiles that are finished before the frame is (finishEarly):
  // only when nothing is drawn after the triangles.
  BinnedFrame(RasterPipeline::State& state, const Scene& scene, const FrameContext& frame,
              const std::atomic<bool>* cancel, Image* image)
      : s_(state), frame_(frame), target_(frame, scene, state.fb, nullptr), cancel_(cancel),
        samples_(std::max<int>(1, int(frame.samples.size()))), image_(image),
        background8_(packUnorm8(scene.background)) {
    s_.fb.reset(scene.width, scene.height, scene.background, samples_);
    tiles_.reset(frame.width, frame.height);
    s_.tileFragments.assign(std::size_t(tiles_.tileCount()), 0);
    s_.finished.assign(std::size_t(tiles_.tileCount()), 0);
    if (image_) s_.fb.imageOf(*image_);
  }

  // Draws the objects in the order given. A run of small objects goes through the vertex stage and
  // the set-up together, one parallel pass each for the run: a sphere of a few thousand vertices
  // alone would leave a core waiting at each pass's end.
  void drawObjects(const Scene& scene, std::span<const Object* const> order) {
    if (image_ && !s_.reach.find(frame_, order)) image_ = nullptr;  // (one object: its tiles finish at the end)
    auto& group = s_.group;
    group.clear();
    std::size_t vertices = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const Object* object = order[k];
      if (object->mesh->triangleCount() == 0) continue;  // points and lines only: drawn after the triangles
      const std::size_t n = object->mesh->positions.size();
      if (!group.empty() && vertices + n > kSmallRun) {
        drawGroup(vertices);
        group.clear();
        vertices = 0;
      }
      group.push_back({object, std::uint32_t(object - scene.objects.data()), std::uint32_t(k), vertices});
      vertices += n;
    }
    if (!group.empty()) drawGroup(vertices);
  }

  // Draws every tile of what has been binned, each tile on one thread, its records in order:
  // opaque objects shade each visible pixel once (shade_tile.h), translucent ones blend fragment by fragment.
  // The affinity partitioner gives a tile to the thread that drew it in the previous flush, while
  // its pixels are still in that core's cache.
  void flush() {
    if (used_ == 0) return;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tiles_.tileCount()),
        [&](const tbb::blocked_range<int>& range) {
          for (int tile = range.begin(); tile < range.end(); ++tile) {
            drawTile(tile);
            finishEarly(tile);
          }
        },
        s_.tileAffinity);
    used_ = 0;
    batchedRecords_ = batchedTiny_ = 0;
    flushed_ = true;
  }

  // The last flush, when nothing is drawn after the triangles: each tile, once drawn, is copied
  // into `image` by the thread that drew it (Framebuffer::toImage tile by tile), a tile that no
  // earlier flush drew in that thread's own memory (Framebuffer::lendTile). Returns the pixels
  // unlike the background; the framebuffer keeps only what earlier flushes drew.
  std::size_t flushInto(Image& image) {
    std::atomic<std::size_t> unlike{0};
    const auto drawAndCopy = [&](const tbb::blocked_range<int>& range) {
      std::size_t n = 0;
      for (int tile = range.begin(); tile < range.end(); ++tile) {
        if (s_.finished[std::size_t(tile)]) continue;
        const bool lent = used_ > 0 && !s_.fb.drawn(tile);
        if (lent) s_.fb.lendTile(tile, s_.scratch.local().pixels);
        if (used_ > 0) drawTile(tile);
        n += s_.fb.copyTile(tile, image, background8_);
        if (lent) s_.fb.returnTile(tile);
      }
      unlike += n;
    };
    // A frame drawn in one flush (a model's preview) has no tile in any core's cache to go back
    // to: its tiles, of very different costs, go to whichever thread is free, one at a time
    // (Wuson at 2 threads: 1 sample 1.24-1.30 -> 1.22 ms, 4 samples 2.09-2.10 -> 1.96-1.99 ms).
    if (flushed_)
      tbb::parallel_for(tbb::blocked_range<int>(0, tiles_.tileCount()), drawAndCopy, s_.tileAffinity);
    else
      tbb::parallel_for(tbb::blocked_range<int>(0, tiles_.tileCount(), 1), drawAndCopy, tbb::simple_partitioner());
    used_ = 0;
    batchedRecords_ = batchedTiny_ = 0;
    return unlike + unlikeEarly_;
  }

  // Points, lines and overlay lines, after the triangles: into each sample's framebuffer, as a
  // pass at that sample draws them.
  void drawAfterTriangles(const Scene& scene, std::span<const OverlayLine> overlay) {
    for (int s = 0; s < samples_; ++s) {
      FrameContext pass = frame_;
      if (samples_ > 1) pass.sample = frame_.samples[std::size_t(s)];
      drawPointsAndLines(s_.fb, pass, scene, s_.vertices, s);
      drawOverlayLines(s_.fb, pass, overlay, 1, s);
    }
  }

  // A newer frame is wanted: what is left of this one is not drawn.
  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }

  void drawTile(int tile) {
    if (cancelled()) return;
    auto& list = s_.tileLists.local();
    list.records.clear();
    list.fragments.clear();
    list.surfaces.clear();
    for (std::size_t c = 0; c < used_; ++c) {
      if (!s_.spans[c].holds(std::uint32_t(tile))) continue;
      const RasterPipeline::State::Chunk& chunk = s_.pool[c];
      // (A batch holds far fewer records than a tiny pixel's tag can count: kBatchRecords plus a
      // slice of chunks.)
      const auto before = std::uint32_t(list.records.size());
      chunk.bins.fragments.forEachRun(tile, [&](const TinyFragment* first, std::uint32_t count) {
        list.fragments.push_back({first, count, before});
      });
      chunk.bins.surfaces.forEachRun(tile, [&](const TinySurface* first, std::uint32_t count) {
        list.surfaces.push_back({first, count, before});
      });
      for (std::uint32_t index : chunk.bins.records(tile)) list.records.push_back(&chunk.records[index]);
    }
    const TinyPixels tiny{list.fragments, list.surfaces};
    if (list.records.empty() && tiny.empty()) return;
    const PixelRect rect = tiles_.tileRect(tile);
    s_.fb.clearTile(rect.minX, rect.minY);
    const SampleTiles planes{samples_, s_.fb.depthTile(rect.minX, rect.minY), s_.fb.colorTile(rect.minX, rect.minY)};
    TileScratch& scratch = s_.scratch.local();
    scratch.reserveSamples(samples_);
    std::size_t& fragments = s_.tileFragments[std::size_t(tile)];
    // The opaque objects come first (drawingOrder): each visible pixel shaded once
    // (shade_tile.h); then the translucent ones, blended fragment by fragment (tiny triangles
    // are all opaque), sample by sample.
    std::size_t opaque = 0;
    while (opaque < list.records.size() && !target_.blends(*list.records[opaque])) ++opaque;
    if (opaque > 0 || !tiny.empty())
      fragments += drawOpaqueTile(target_, std::span(list.records).first(opaque), tiny, rect, scratch, planes);
    if (opaque < list.records.size())
      fragments += drawBlendedTile(target_, std::span(list.records).subspan(opaque), rect, scratch, planes);
  }

  // A tile drawn by this flush or an earlier one, that no object still to be set up can reach,
  // goes into the image now and gives its memory back (Framebuffer::releaseTile): a scene of many
  // objects holds the samples of the tiles its objects in progress reach, not of the whole frame.
  void finishEarly(int tile) {
    const auto t = std::size_t(tile);
    if (!image_ || s_.finished[t] || !s_.fb.drawn(tile) || !s_.reach.reachedOnlyBefore(tile, setUp_) || cancelled()) return;
    unlikeEarly_ += s_.fb.copyTile(tile, *image_, background8_);
    s_.fb.releaseTile(tile);
    s_.finished[t] = 1;
  }

  RenderStats stats() const {
    RenderStats s = stats_;
    for (std::size_t f : s_.tileFragments) s.fragmentsShaded += f;
    return s;
  }

 private:
  // The objects in s_.group, `count` vertices in all, each object's at its `base` in s_.vertices.
  void drawGroup(std::size_t count) {
    auto& vertices = s_.vertices;
    vertices.resize(count);
    auto& ranges = s_.ranges;
    ranges.clear();
    for (const auto& member : s_.group)
      for (std::size_t v = 0, n = member.object->mesh->positions.size(); v < n; v += kVertexGrain)
        ranges.push_back({&member, v, std::min(n, v + kVertexGrain)});
    tbb::parallel_for(std::size_t(0), ranges.size(), [&](std::size_t r) {
      const auto& [member, first, last] = ranges[r];
      runVertexStage(frame_, *member->object, member->index, ofMember(*member), first, last);
    });
    // The chunks of triangles, in submission order.
    ranges.clear();
    for (const auto& member : s_.group) {
      const std::size_t triangles = member.object->mesh->triangleCount();
      stats_.trianglesIn += triangles;
      for (std::size_t t = 0; t < triangles; t += kTriangleChunk)
        ranges.push_back({&member, t, std::min(triangles, t + kTriangleChunk)});
    }
    // A slice of chunks is set up and binned in parallel, each chunk into an arena and bins of its
    // own; a tile then draws its records chunk by chunk, in submission order.
    const std::size_t chunks = ranges.size();
    const std::size_t slice = std::max<std::size_t>(1, kBatchTiny / kTriangleChunk);
    for (std::size_t c0 = 0; c0 < chunks && !cancelled(); c0 += slice) {
      // A full batch is drawn when more is to come, not at once: the last one is left to
      // flushInto, which draws a tile no earlier batch touched in memory that stays in cache.
      if (batchedRecords_ >= kBatchRecords || batchedTiny_ >= kBatchTiny) flush();
      const std::size_t c1 = std::min(chunks, c0 + slice);
      if (s_.pool.size() < used_ + (c1 - c0)) s_.pool.resize(used_ + (c1 - c0));
      // A chunk at a time to whichever thread is free: chunks differ in cost (multisampled Phong
      // lights the pixels of its tiny front faces at setup, and a mesh's back half has none), and
      // a static split left a core idle for a fifth of a frame.
      tbb::parallel_for(tbb::blocked_range<std::size_t>(c0, c1, 1), [&](const tbb::blocked_range<std::size_t>& range) {
       for (std::size_t c = range.begin(); c < range.end(); ++c) {
        const auto& [member, first, last] = ranges[c];
        RasterPipeline::State::Chunk& chunk = s_.pool[used_ + (c - c0)];
        chunk.records.reset(target_.layouts[member->index], last - first);
        chunk.bins.reset(frame_.width, frame_.height);
        const std::uint32_t i = member->index;
        const SetupBinning binning{chunk.bins, target_.tiny[i] != 0, target_.shadeOwner[i],
                                   target_.tinyLit[i] ? &target_.setups[i] : nullptr};
        chunk.drawn = setupTriangles(frame_, *member->object, member->index, ofMember(*member), first, last,
                                     chunk.records, &binning);
        chunk.bins.finish();
       }
      }, tbb::simple_partitioner());
      if (s_.spans.size() < s_.pool.size()) s_.spans.resize(s_.pool.size());
      for (std::size_t c = c0; c < c1; ++c) {
        const auto& [member, first, last] = ranges[c];
        if (last == member->object->mesh->triangleCount()) setUp_ = member->order + 1;
        s_.spans[used_] = s_.pool[used_].bins.span();
        const RasterPipeline::State::Chunk& chunk = s_.pool[used_++];
        batchedRecords_ += chunk.records.size();
        batchedTiny_ += chunk.drawn - chunk.records.size();
        stats_.trianglesDrawn += chunk.drawn;
      }
    }
  }

  std::span<ShadedVertex> ofMember(const RasterPipeline::State::Member& member) {
    return std::span(s_.vertices).subspan(member.base, member.object->mesh->positions.size());
  }

  RasterPipeline::State& s_;
  const FrameContext& frame_;
  DrawTarget target_;
  const std::atomic<bool>* cancel_;
  int samples_;     // per pixel, kept in the tile
  TileBins tiles_;  // only its tile rectangles: the records are binned per chunk
  std::size_t used_ = 0, batchedRecords_ = 0, batchedTiny_ = 0;
  bool flushed_ = false;  // an earlier flush of this frame drew tiles (flush)
  RenderStats stats_;
  Image* image_;                 // where tiles finished early go (none: they are not)
  std::uint32_t background8_;    // the background as an RGBA8 word
  std::uint32_t setUp_ = 0;      // objects [0, setUp_) of the drawing order are set up in full
  std::atomic<std::size_t> unlikeEarly_{0};  // pixels of the tiles finished early unlike the background
};

}  // namespace

RasterPipeline::RasterPipeline() : state_(std::make_unique<State>()) {}
RasterPipeline::~RasterPipeline() = default;

std::size_t RasterPipeline::tileBlocksMade() const { return state_->fb.blocksMade(); }

void RasterPipeline::draw(const Scene& scene, Image& image, RenderStats& stats, PixelProbe* probe,
                          const OcclusionQuery* occlusion, const std::atomic<bool>* cancel) {
  FrameContext frame = FrameContext::fromScene(scene);
  frame.occlusion = occlusion;
  const std::span<const SubpixelOffset> samples = multisamplePattern(scene.multisample);
  const std::vector<OverlayLine> overlay = overlayLines(scene);
  if (hasPointsOrLines(scene)) checkPointAndLineFill(frame, scene, int(samples.size()));
  // Multisampling in one pass: the triangles set up once at the pixel centres, each tile keeping
  // coverage, depth and colour per sample and resolving them (shade_tile.h); each pixel shaded at
  // its centre, once per triangle that it shows.
  if (samples.size() > 1) frame.setSamples(samples);
  const bool afterTriangles = hasPointsOrLines(scene) || !overlay.empty();
  BinnedFrame pass(*state_, scene, frame, cancel, afterTriangles ? nullptr : &image);
  pass.drawObjects(scene, drawingOrder(scene, frame));
  if (afterTriangles) {
    pass.flush();
    pass.drawAfterTriangles(scene, overlay);
    stats = pass.stats();
    stats.pixelsDrawn = state_->fb.toImage(image, scene.background);
  } else {
    const std::size_t unlike = pass.flushInto(image);
    stats = pass.stats();
    stats.pixelsDrawn = unlike;
  }
  if (probe) probePixel(scene, frame, *probe);
}

}  // namespace illum
