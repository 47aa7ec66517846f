#include "raster/shade/shade_tile.h"

#include "raster/coverage/depth_bounds.h"
#include "raster/shade/fragment.h"
#include "raster/shade/shade_visible.h"
#include "shading/shade_points.h"

#include <cstdint>
#include <cstring>

namespace illum {

TileScratch::TileScratch() : visible_(std::make_unique<VisibleBatch>()) { owner.fill(kNoWinner); }
TileScratch::~TileScratch() = default;

namespace {

// Where a tiny triangle's pixel passes the depth test: depth[at] = z, and then write(at, pixel).
// The pixels come from memory (a 4K frame's are tens of megabytes), in runs a few hundred bytes
// to a few kilobytes long that lie apart: each is fetched ahead of its turn, its start two runs
// before, the rest kTinyAhead pixels before.
template <class Pixel, class Write>
class TinyDrawer {
 public:
  TinyDrawer(std::span<const TinyRun<Pixel>> runs, Real* depth, const Write& write)
      : runs_(runs), depth_(depth), write_(write) {}
  // The pixels that come before the tile's record `record`; returns how many passed.
  std::size_t drawUpTo(std::size_t record) {
    std::size_t passed = 0;
    for (; run_ < runs_.size(); ++run_, next_ = 0) {
      const TinyRun<Pixel>& run = runs_[run_];
      if (next_ == 0 && run_ + 2 < runs_.size()) {
        const Pixel* ahead = runs_[run_ + 2].first;
        prefetch(ahead, 0);
        prefetch(ahead, 64);
      }
      for (; next_ < run.count; ++next_) {
        const Pixel& p = run.first[next_];
        prefetch(&p, kTinyAhead * sizeof(Pixel));
        if (run.recordsBefore + TinyTag::recordsBefore(p.tag) > record) return passed;
        const std::uint32_t at = TinyTag::pixel(p.tag);
        if (!(p.z < depth_[at])) continue;
        depth_[at] = p.z;
        write_(at, p);
        ++passed;
      }
    }
    return passed;
  }

 private:
  static constexpr std::size_t kTinyAhead = 48;
  // The line `bytes` after `p`, wherever that is (an address only: no pointer past the run).
  static void prefetch(const Pixel* p, std::size_t bytes) {
    __builtin_prefetch(reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(p) + bytes));
  }
  std::span<const TinyRun<Pixel>> runs_;
  Real* depth_;
  const Write& write_;
  std::size_t run_ = 0;
  std::uint32_t next_ = 0;
};

// The lit colours of a Gouraud record's vertices, for the side shown; null for flat shading.
struct VertexColors {
  Color4 lit[3];
  const Color4* of(const DrawTarget& target, const DrawRecord& r) {
    if (target.frame.shading == Shading::Flat) return nullptr;
    const AttributeLayout& l = target.layout(r);
    for (int k = 0; k < 3; ++k) lit[k] = VertexValues{r.vertex(k, l), l}.lit();
    return lit;
  }
};

#if !ILLUM_USE_DOUBLE
// What a Surface record's pixels interpolate.
SurfaceVertices surfaceVertices(const DrawTarget& target, const DrawRecord& r) {
  const AttributeLayout& l = target.layout(r);
  SurfaceVertices v;
  for (int k = 0; k < 3; ++k) {
    const VertexValues values{r.vertex(k, l), l};
    v.position[std::size_t(k)] = values.position();
    v.normal[std::size_t(k)] = values.normal();
    v.color[std::size_t(k)] = values.color();
  }
  v.colors = target.colored[r.object];
  v.negate = target.frame.lightModel.twoSided && !r.setup.frontFacing;
  v.owner = target.shadeOwner[r.object];
  return v;
}
#endif

// The deferred colours: each record a pixel's samples show, shaded once at the pixel's centre
// (shade_visible.h).
void colorWinners(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                  TileScratch& scratch, const SampleTiles& tiles) {
  const VisibleSamples out{tiles.count, tiles.color, scratch.winners.data()};
  VisibleShader shader(target, records, rect, scratch.visible(), out);
  shader.shadeAll(scratch.shown);
}

// A tile's records lie all over the frame's arenas, set up long before: each is asked for from
// memory a few records ahead of its turn, so that its setup is in cache when it is drawn.
constexpr std::size_t kRecordsAhead = 4;
inline void prefetchRecord(std::span<const DrawRecord* const> records, std::size_t i) {
  if (i >= records.size()) return;
  const auto* bytes = reinterpret_cast<const char*>(records[i]);
  __builtin_prefetch(bytes);
  __builtin_prefetch(bytes + 64);
}

// Each Deferred record's pixels where some sample passed are listed record by record as its
// coverage finds them: once those a later draw took whole are dropped, they are the lists
// shownPairs and groupByRecord would sort out of the winners when the tile is done (at 4 samples,
// 1 thread: Wuson and the duck 4–7 % faster, the 48k-sphere Phong scenes 1–3 %). A tile of many
// records (a dense mesh's thin triangles, drawn over each other) lists many pixels that later
// draws take, and its coverage slows with the lists' stores: there the winners are sorted
// (2CylinderEngine, 1100 records a tile: 9 % slower listed; ClearCoatTest, 576: 4 %).
constexpr std::size_t kMostRecordsListed = 384;

// Multisampling in one pass: each record's coverage and depth tested at every sample of its
// pixels (rasterizeSamples: exactly as a pass at that sample would); Colored records coloured once
// per pixel at its centre as they are found, Deferred ones kept per sample (and their pixels
// listed, kMostRecordsListed) and each record a pixel shows shaded once afterwards. Tiny
// triangles' samples, worked out at setup, are depth-tested where their counts of records put them.
std::size_t drawMultisampledTile(const DrawTarget& target, std::span<const DrawRecord* const> records,
                                 const TinyPixels& tiny, const PixelRect& rect, TileScratch& scratch,
                                 const SampleTiles& tiles) {
  std::uint32_t* winners = scratch.winners.data();
  const SamplePlanes planes{tiles.count, target.frame.samples.data(), target.frame.sampleLanes.x,
                            target.frame.sampleLanes.y, tiles.depth, tiles.color, winners};
  std::size_t fragments = 0;
  bool anyWinner = false;
  DepthBounds bounds(tiles.depth, tiles.count, rect);
  const bool listing = records.size() <= kMostRecordsListed;
  ShownLists& lists = scratch.shown;
  lists.start.resize(records.size() + 1);
  std::size_t listed = 0;
  // (The depth bounds follow the tiny pixels only while a record may still ask them: a dense
  // mesh's tiles draw most of theirs after the last record.)
  bool recordsAfter = !records.empty();
  const auto writeTiny = [&](std::uint32_t at, const TinyFragment& f) {
    tiles.color[at] = f.color;
    if (anyWinner) winners[at] = kNoWinner;
    if (recordsAfter) bounds.drawnAt(at);
  };
  TinyDrawer<TinyFragment, decltype(writeTiny)> tinyFragments(tiny.fragments, tiles.depth, writeTiny);
  [[maybe_unused]] VertexColors vertexColors;  // (the double build has no Colored route)
  for (std::size_t i = 0; i < records.size(); ++i) {
    fragments += tinyFragments.drawUpTo(i);
    prefetchRecord(records, i + kRecordsAhead);
    const DrawRecord& r = *records[i];
    lists.start[i] = std::uint32_t(listed);
    if (bounds.hidden(r.setup)) continue;
    std::size_t passed = 0;
#if !ILLUM_USE_DOUBLE
    if (target.route[r.object] == Route::Colored) {
      passed = rasterizeSamplesColored(r.setup, rect, planes, vertexColors.of(target, r), packUnorm8(r.flat), anyWinner);
    } else
#endif
    if (!listing) {
      passed = rasterizeSamples(r.setup, rect, planes, std::uint32_t(i)), anyWinner = true;
    } else {
      const std::size_t room = listed + listedRoom(r.setup, rect);
      if (lists.pixels.size() < room) lists.pixels.resize(std::max(room, 2 * lists.pixels.size()));
      std::size_t found = 0;
      passed = rasterizeSamples(r.setup, rect, planes, std::uint32_t(i), lists.pixels.data() + listed, found);
      listed += found;
      anyWinner = true;
    }
    if (passed != 0) bounds.drawn();
    fragments += passed;
  }
  lists.start[records.size()] = std::uint32_t(listed);
  recordsAfter = false;
  fragments += tinyFragments.drawUpTo(records.size());
  if (!anyWinner) return fragments;
  if (listing) {
    // (The lists have room for a vector read past the last pixel.)
    if (lists.pixels.size() < listed + 16) lists.pixels.resize(listed + 16);
    const VisibleSamples out{tiles.count, tiles.color, winners};
    VisibleShader shader(target, records, rect, scratch.visible(), out);
    shader.shadeListed(lists);
  } else {
    colorWinners(target, records, rect, scratch, tiles);
  }
  std::fill_n(winners, kTileBlock * std::size_t(tiles.count), kNoWinner);
  return fragments;
}

}  // namespace

std::size_t drawBlendedTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                            TileScratch& scratch, const SampleTiles& tiles) {
  std::uint32_t* winners = scratch.winners.data();
  const SamplePlanes planes{tiles.count, target.frame.samples.data(), target.frame.sampleLanes.x,
                            target.frame.sampleLanes.y, tiles.depth, tiles.color, winners};
  const VisibleSamples out{tiles.count, tiles.color, winners};
  VisibleShader shader(target, records, rect, scratch.visible(), out);
  std::size_t fragments = 0;
  std::vector<std::uint32_t>& pixels = scratch.shown.pixels;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const TriangleSetup& t = records[i]->setup;
    if (tiles.count == 1) {
      const std::size_t passed = rasterizeDepth(t, rect, tiles.depth, std::uint32_t(i), winners);
      if (passed == 0) continue;
      fragments += passed;
      shader.blendRecord(std::uint32_t(i), scratch.shown);
      continue;
    }
    // Multisampled, the pixels its coverage lists are those it shows (nothing is drawn between).
    if (pixels.size() < listedRoom(t, rect)) pixels.resize(listedRoom(t, rect));
    std::size_t found = 0;
    const std::size_t passed = rasterizeSamples(t, rect, planes, std::uint32_t(i), pixels.data(), found);
    fragments += passed;
    shader.blendPixels(std::uint32_t(i), pixels.data(), found);
  }
  shader.finishBlending();
  return fragments;
}

// One sample: each record by its route, in submission order, with the tiny triangles' pixels
// where their counts of records put them. Colored pixels are written as found; a Surface pixel
// keeps its surface (and owner) to be lit once when the tile is done; a Deferred pixel keeps its
// record. A pixel holds one of the three: what wins it clears what the others kept there.
std::size_t drawOpaqueTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const TinyPixels& tiny,
                           const PixelRect& rect, TileScratch& scratch, const SampleTiles& tiles) {
  if (tiles.count > 1) return drawMultisampledTile(target, records, tiny, rect, scratch, tiles);
  Real* depth = tiles.depth;
  std::uint32_t* color = tiles.color;
  std::uint32_t* winners = scratch.winners.data();
  std::uint32_t* owner = scratch.owner.data();
  bool anyWinner = false, anySurface = false;
  std::size_t fragments = 0;
  // A tiny triangle's pixel, worked out at setup: only the depth test is left.
  const auto writeTiny = [&](std::uint32_t at, const TinyFragment& f) {
    color[at] = f.color;
    if (anyWinner) winners[at] = kNoWinner;
  };
  TinyDrawer<TinyFragment, decltype(writeTiny)> tinyFragments(tiny.fragments, depth, writeTiny);
#if !ILLUM_USE_DOUBLE
  Real (&plane)[10][kTileBlock] = scratch.surface;
  const SurfaceTile surface{{plane[0], plane[1], plane[2]},
                            {plane[3], plane[4], plane[5]},
                            {plane[6], plane[7], plane[8], plane[9]},
                            owner};
  const auto keepTiny = [&](std::uint32_t at, const TinySurface& p) {
    for (int c = 0; c < 3; ++c) surface.position[c][at] = p.position[c], surface.normal[c][at] = p.normal[c];
    owner[at] = p.owner;
    if (anyWinner) winners[at] = kNoWinner;
  };
  TinyDrawer<TinySurface, decltype(keepTiny)> tinySurfaces(tiny.surfaces, depth, keepTiny);
  if (!tiny.surfaces.empty()) anySurface = true;
#endif
  [[maybe_unused]] VertexColors vertexColors;  // (the double build has no Colored route)
  for (std::size_t i = 0; i < records.size(); ++i) {
    fragments += tinyFragments.drawUpTo(i);
#if !ILLUM_USE_DOUBLE
    fragments += tinySurfaces.drawUpTo(i);
#endif
    prefetchRecord(records, i + kRecordsAhead);
    const DrawRecord& r = *records[i];
    switch (target.route[r.object]) {
#if !ILLUM_USE_DOUBLE
      case Route::Colored: {
        const Color4* lit = vertexColors.of(target, r);
        std::uint32_t* clear = anyWinner ? winners : nullptr;
        fragments += lit ? rasterizeGouraud(r.setup, rect, depth, color, clear, lit)
                         : rasterizeFlat(r.setup, rect, depth, color, clear, packUnorm8(r.flat));
        break;
      }
      case Route::Surface:
        fragments += rasterizeSurface(r.setup, rect, depth, surfaceVertices(target, r), surface,
                                      anyWinner ? winners : nullptr);
        anySurface = true;
        break;
#endif
      default:  // Deferred (Blended records are drawn after the opaque ones, drawRecord)
        fragments += rasterizeDepth(r.setup, rect, depth, std::uint32_t(i), winners, anySurface ? owner : nullptr);
        anyWinner = true;
    }
  }
  fragments += tinyFragments.drawUpTo(records.size());
#if !ILLUM_USE_DOUBLE
  fragments += tinySurfaces.drawUpTo(records.size());
  if (anySurface) {
    // The Surface pixels, lit once each, a vector of one owner at a time.
    SurfacePoints points;
    points.count = std::size_t(kTileSize) * kTileSize;
    for (int c = 0; c < 3; ++c) points.position[c] = plane[c], points.normal[c] = plane[3 + c];
    for (int c = 0; c < 4; ++c) points.color[c] = plane[6 + c];
    shadeOwnedPoints(target.setups, target.colored, points, owner, color);
    std::fill_n(owner, points.count, kNoWinner);
  }
#endif
  if (anyWinner) {
    colorWinners(target, records, rect, scratch, tiles);
    std::fill_n(winners, kTileBlock, kNoWinner);
  }
  return fragments;
}

}  // namespace illum
