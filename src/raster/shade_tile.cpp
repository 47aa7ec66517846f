#include "raster/shade_tile.h"

#include "raster/fragment.h"
#include "shading/shade_points.h"

#include <cstdint>
#include <cstring>

namespace illum {
namespace {

struct VisiblePixel {
  int x, y;
  Real l0, l1, l2;  // screen-space barycentrics, exactly as the rasterizer computes them
};

// The pixel of a tile index, and its centre's barycentrics (fragment.h).
VisiblePixel visiblePixel(const TriangleSetup& t, const PixelRect& rect, int index, SubpixelOffset sample) {
  const int x = rect.minX + index % kTileSize, y = rect.minY + index / kTileSize;
  const auto [l0, l1, l2] = centreBarycentrics(t, x, y, sample);
  return {x, y, l0, l1, l2};
}

// Where the deferred colours of a tile go: each sample's plane and winners (one of each without
// multisampling). A pixel's colour is shaded once per record it shows, at its centre, and goes to
// every sample that shows that record.
struct VisibleSamples {
  int count = 1;
  std::uint32_t* color;
  const std::uint32_t* winners;

  VisibleSamples(const SampleTiles& tiles, const TileScratch& scratch)
      : count(tiles.count), color(tiles.color), winners(scratch.winners.data()) {}
  // f(index, slot) once for each record that some sample of pixel `index` shows, in sample order.
  template <class F>
  void forEachShown(int index, F&& f) const {
    const std::uint32_t* shown = winners + std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s) {
      const std::uint32_t slot = shown[s];
      if (slot == kNoWinner) continue;
      bool earlier = false;
      for (int e = 0; e < s && !earlier; ++e) earlier = shown[e] == slot;
      if (!earlier) f(index, slot);
    }
  }
  void write(int index, std::uint32_t slot, std::uint32_t rgba) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s)
      if (winners[at + std::size_t(s)] == slot) color[at + std::size_t(s)] = rgba;
  }
  // The watched pixel reports what its first sample shows.
  bool reported(int index, std::uint32_t slot) const { return winners[std::size_t(index) * std::size_t(count)] == slot; }
};

// Writes a coloured pixel: GL_MODULATE by the texel (unless the texel was the base colour), then
// the samples that show the record, then the probe.
void writePixel(const DrawTarget& target, const VisibleSamples& out, int index, std::uint32_t slot,
                const DrawRecord& r, const VisiblePixel& p, const Color4& lit, const Vec4* texel,
                bool texelIsBaseColor = false, const MappedSurface* mapped = nullptr) {
  const Color4 c = texel && !texelIsBaseColor ? lit * *texel : lit;
  out.write(index, slot, packUnorm8(c));
  if (target.probe && p.x == target.probe->x && p.y == target.frame.height - 1 - target.probe->y &&
      out.reported(index, slot))
    recordProbe(target, r, perspectiveWeights(r.setup, p.l0, p.l1, p.l2), lit, texel, c, texelIsBaseColor, mapped);
}

// Flat and Gouraud: the colours were lit at the vertices.
void colorVertexLit(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                    const VisibleSamples& out) {
  for (int i = 0; i < kTileSize * kTileSize; ++i) {
    out.forEachShown(i, [&](int index, std::uint32_t slot) {
      const DrawRecord& r = *records[slot];
      const VisiblePixel p = visiblePixel(r.setup, rect, index, target.frame.sample);
      const Color4 lit = target.frame.shading == Shading::Flat
                             ? r.flat
                             : gouraudColor(r, target.layout(r), perspectiveWeights(r.setup, p.l0, p.l1, p.l2));
      const Texture* texture = drawnTexture(target.scene.objects[r.object]);
      if (!texture) return writePixel(target, out, index, slot, r, p, lit, nullptr);
      const Vec4 texel = sampleDiffuseTexture(*texture, r, target.layout(r), p.l0, p.l1, p.l2);
      writePixel(target, out, index, slot, r, p, lit, &texel);
    });
  }
}

// Phong: the pixels of one object at a time gathered into a batch and lit together.
class PhongBatch {
 public:
  PhongBatch(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
             TileScratch& scratch, const VisibleSamples& out)
      : target_(target), records_(records), rect_(rect), s_(scratch), out_(out) {}

  void add(int index, std::uint32_t slot) {
    const DrawRecord& r = *records_[slot];
    const Object& object = target_.scene.objects[r.object];
    const VisiblePixel p = visiblePixel(r.setup, rect_, index, target_.frame.sample);
    if (mapsDrawn(object, target_.frame.litPerPixel())) return shadeMapped(object, index, slot, r, p);
    if (n_ == TileScratch::kBatch || (n_ > 0 && r.object != object_)) flush();
    object_ = r.object;
    const PhongSurface surface =
        phongSurface(target_.frame, !object.mesh->colors.empty(), r, target_.layout(r),
                     perspectiveWeights(r.setup, p.l0, p.l1, p.l2));
    for (int c = 0; c < 3; ++c) s_.soa[c][n_] = surface.position[c], s_.soa[3 + c][n_] = surface.normal[c];
    Color4 color = surface.color;
    if (const Texture* texture = drawnTexture(object)) {
      const Vec4 texel = sampleDiffuseTexture(*texture, r, target_.layout(r), p.l0, p.l1, p.l2);
      for (int c = 0; c < 4; ++c) s_.soa[10 + c][n_] = texel[c];
      // A base colour texture tints the material's (or the vertex's) colour before lighting, as
      // withBaseTexel does.
      if (texelIsBaseColor(object, target_.frame.model, target_.frame.litPerPixel())) {
        const Material& m = object.material;
        color = (object.mesh->colors.empty() ? Color4(physicalOf(m).baseColor, m.diffuse.a) : color) * texel;
      }
    }
    for (int c = 0; c < 4; ++c) s_.soa[6 + c][n_] = color[c];
    s_.pixel[n_] = std::uint16_t(index);
    s_.slot[n_] = slot;
    ++n_;
  }

  void flush() {
    if (n_ == 0) return;
    const Object& object = target_.scene.objects[object_];
    const ShadeSetup setup{target_.frame.lights, target_.frame.lightModel, modelOf(object.material, target_.frame.model),
                           object.material};
    const bool textured = drawnTexture(object) != nullptr,
               baseTexture = texelIsBaseColor(object, target_.frame.model, target_.frame.litPerPixel());
    SurfacePoints points;
    points.count = n_;
    for (int c = 0; c < 3; ++c) points.position[c] = s_.soa[c], points.normal[c] = s_.soa[3 + c];
    if (!object.mesh->colors.empty() || baseTexture)
      for (int c = 0; c < 4; ++c) points.color[c] = s_.soa[6 + c];
    Real* const lit[4] = {s_.soa[14], s_.soa[15], s_.soa[16], s_.soa[17]};
    shadePoints(setup, points, lit);
    for (std::size_t k = 0; k < n_; ++k) {
      const DrawRecord& r = *records_[s_.slot[k]];
      const VisiblePixel p = visiblePixel(r.setup, rect_, s_.pixel[k], target_.frame.sample);
      const Color4 color(lit[0][k], lit[1][k], lit[2][k], lit[3][k]);
      const Vec4 texel(s_.soa[10][k], s_.soa[11][k], s_.soa[12][k], s_.soa[13][k]);
      writePixel(target_, out_, s_.pixel[k], s_.slot[k], r, p, color, textured ? &texel : nullptr, baseTexture);
    }
    n_ = 0;
  }

 private:
  // A pixel whose material or normal comes from glTF's maps: lit on its own (fragment.h).
  void shadeMapped(const Object& object, int index, std::uint32_t slot, const DrawRecord& r, const VisiblePixel& p) {
    const MappedSurface surface = mappedSurface(target_.frame, object, r, target_.layout(r), p.l0, p.l1, p.l2);
    writePixel(target_, out_, index, slot, r, p, shadeMappedFragment(target_.frame, surface),
               surface.point.textured ? &surface.point.texel : nullptr, surface.point.texelIsBaseColor, &surface);
  }

  const DrawTarget& target_;
  std::span<const DrawRecord* const> records_;
  const PixelRect& rect_;
  TileScratch& s_;
  const VisibleSamples& out_;
  std::size_t n_ = 0;
  std::uint32_t object_ = 0;
};

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

#if !ILLUM_USE_DOUBLE
// Flat and Gouraud coloured in the depth pass itself; `winners` (or null) cleared where drawn.
std::size_t drawColored(const DrawTarget& target, const DrawRecord& r, const PixelRect& rect, Real* depth,
                        std::uint32_t* color, std::uint32_t* winners) {
  if (target.frame.shading == Shading::Flat) {
    return rasterizeFlat(r.setup, rect, depth, color, winners, packUnorm8(r.flat));
  }
  const AttributeLayout& l = target.layout(r);
  const Color4 lit[3] = {VertexValues{r.vertex(0, l), l}.lit(), VertexValues{r.vertex(1, l), l}.lit(),
                         VertexValues{r.vertex(2, l), l}.lit()};
  return rasterizeGouraud(r.setup, rect, depth, color, winners, lit);
}

// Phong from the tile's visible surface: interpolated in the depth pass, lit once per pixel.
std::size_t drawLitSurface(const DrawTarget& target, std::span<const DrawRecord* const> records,
                           std::span<const TinyRun<TinySurface>> tiny, const PixelRect& rect, Real* depth,
                           std::uint32_t* color, TileScratch& scratch) {
  Real (&plane)[10][kTileBlock] = scratch.surface;
  const SurfaceTile out{{plane[0], plane[1], plane[2]},
                        {plane[3], plane[4], plane[5]},
                        {plane[6], plane[7], plane[8], plane[9]},
                        scratch.owner.data()};
  const auto keep = [&](std::uint32_t at, const TinySurface& p) {
    for (int c = 0; c < 3; ++c) out.position[c][at] = p.position[c], out.normal[c][at] = p.normal[c];
    out.owner[at] = p.owner;
  };
  TinyDrawer<TinySurface, decltype(keep)> tinyPixels(tiny, depth, keep);
  const bool twoSided = target.frame.lightModel.twoSided;
  std::size_t fragments = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    fragments += tinyPixels.drawUpTo(i);
    const DrawRecord* r = records[i];
    const AttributeLayout& l = target.layout(*r);
    SurfaceVertices v;
    for (int k = 0; k < 3; ++k) {
      const VertexValues values{r->vertex(k, l), l};
      v.position[std::size_t(k)] = values.position();
      v.normal[std::size_t(k)] = values.normal();
      v.color[std::size_t(k)] = values.color();
    }
    v.colors = target.colored[r->object];
    v.negate = twoSided && !r->setup.frontFacing;
    v.owner = target.shadeOwner[r->object];
    fragments += rasterizeSurface(r->setup, rect, depth, v, out);
  }
  fragments += tinyPixels.drawUpTo(records.size());
  if (fragments == 0) return 0;
  SurfacePoints points;
  points.count = std::size_t(kTileSize) * kTileSize;
  for (int c = 0; c < 3; ++c) points.position[c] = plane[c], points.normal[c] = plane[3 + c];
  for (int c = 0; c < 4; ++c) points.color[c] = plane[6 + c];
  shadeOwnedPoints(target.setups, target.colored, points, scratch.owner.data(), color);
  std::fill_n(scratch.owner.begin(), points.count, kNoWinner);
  return fragments;
}
#endif  // !ILLUM_USE_DOUBLE

// The deferred colours: each record a pixel's samples show, shaded once at the pixel's centre.
void colorWinners(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                  TileScratch& scratch, const VisibleSamples& out) {
  if (target.frame.shading != Shading::Phong) return colorVertexLit(target, records, rect, out);
  PhongBatch batch(target, records, rect, scratch, out);
  for (int i = 0; i < kTileSize * kTileSize; ++i)
    out.forEachShown(i, [&](int index, std::uint32_t slot) { batch.add(index, slot); });
  batch.flush();
}

// Multisampling in one pass: each record's coverage and depth tested at every sample of its
// pixels (rasterizeSamples: exactly as a pass at that sample would), flat and Gouraud colours
// worked out once per pixel at its centre as they are found, the other records kept per sample
// and each record a pixel shows shaded once afterwards.
std::size_t drawMultisampledTile(const DrawTarget& target, std::span<const DrawRecord* const> records,
                                 const PixelRect& rect, TileScratch& scratch, const SampleTiles& tiles) {
  std::uint32_t* winners = scratch.winners.data();
  const SamplePlanes planes{tiles.count, target.frame.samples.data(), tiles.depth, tiles.color, winners};
  std::size_t fragments = 0;
  bool anyWinner = false;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const DrawRecord& r = *records[i];
#if !ILLUM_USE_DOUBLE
    if (target.colorsInDepthPass && !drawnTexture(target.scene.objects[r.object])) {
      if (target.frame.shading == Shading::Flat) {
        fragments += rasterizeSamplesColored(r.setup, rect, planes, nullptr, packUnorm8(r.flat), anyWinner);
        continue;
      }
      const AttributeLayout& l = target.layout(r);
      const Color4 lit[3] = {VertexValues{r.vertex(0, l), l}.lit(), VertexValues{r.vertex(1, l), l}.lit(),
                             VertexValues{r.vertex(2, l), l}.lit()};
      fragments += rasterizeSamplesColored(r.setup, rect, planes, lit, 0, anyWinner);
      continue;
    }
#endif
    fragments += rasterizeSamples(r.setup, rect, planes, std::uint32_t(i));
    anyWinner = true;
  }
  if (!anyWinner) return fragments;
  colorWinners(target, records, rect, scratch, VisibleSamples(tiles, scratch));
  std::fill_n(winners, kTileBlock * std::size_t(tiles.count), kNoWinner);
  return fragments;
}

}  // namespace

std::size_t drawOpaqueTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const TinyPixels& tiny,
                           const PixelRect& rect, TileScratch& scratch, const SampleTiles& tiles) {
  if (tiles.count > 1) return drawMultisampledTile(target, records, rect, scratch, tiles);
  Real* depth = tiles.depth;
  std::uint32_t* color = tiles.color;
#if !ILLUM_USE_DOUBLE
  if (target.litFromSurface) return drawLitSurface(target, records, tiny.surfaces, rect, depth, color, scratch);
#endif
  // Flat and Gouraud colour their pixels in the depth pass itself, unless a texel or the probe
  // needs the second pass (or the channels are double, which the SIMD conversion does not take).
  std::uint32_t* winners = scratch.winners.data();
  bool anyWinner = false;
  std::size_t fragments = 0;
  // A tiny triangle's pixel, coloured at setup: only the depth test is left.
  const auto write = [&](std::uint32_t at, const TinyFragment& f) {
    color[at] = f.color;
    if (anyWinner) winners[at] = kNoWinner;
  };
  TinyDrawer<TinyFragment, decltype(write)> tinyPixels(tiny.fragments, depth, write);
  for (std::size_t i = 0; i < records.size(); ++i) {
    fragments += tinyPixels.drawUpTo(i);
    const DrawRecord& r = *records[i];
#if !ILLUM_USE_DOUBLE
    if (target.colorsInDepthPass && !drawnTexture(target.scene.objects[r.object])) {
      fragments += drawColored(target, r, rect, depth, color, anyWinner ? winners : nullptr);
      continue;
    }
#endif
    fragments += rasterizeDepth(r.setup, rect, depth, std::uint32_t(i), winners);
    anyWinner = true;
  }
  fragments += tinyPixels.drawUpTo(records.size());
  if (!anyWinner) return fragments;
  colorWinners(target, records, rect, scratch, VisibleSamples(tiles, scratch));
  std::fill_n(winners, kTileBlock, kNoWinner);
  return fragments;
}

}  // namespace illum
