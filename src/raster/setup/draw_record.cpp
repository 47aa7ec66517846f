#include "raster/setup/draw_record.h"

#include "raster/setup/clip.h"
#include "raster/coverage/tile_raster.h"
#include "raster/setup/tiny_batch.h"
#include "shading/material_at.h"

#include <cstring>
#include <optional>

namespace illum {

AttributeLayout AttributeLayout::forObject(const FrameContext& frame, const Object& object, bool probe) {
  const bool textured = drawnTexture(object) != nullptr;
  const bool colors = !object.mesh->colors.empty();
  AttributeLayout l;
  l.probe = probe;
  const auto take = [&](int n) {
    const int at = l.stride;
    l.stride += n;
    return at;
  };
  if (probe || frame.shading == Shading::Gouraud) l.lit = take(4);
  if (probe || frame.shading == Shading::Phong) l.position = take(3), l.normal = take(3);
  if (probe || (frame.shading == Shading::Phong && colors)) l.color = take(4);
  if (textured || (object.maps.any() && !object.mesh->uvs.empty())) l.uv = take(2);
  return l;
}

void RecordArena::reset(const AttributeLayout& layout, std::size_t expected) {
  layout_ = layout;
  count_ = 0;
  const std::size_t bytes = sizeof(DrawRecord) + layout.reals() * sizeof(Real);
  // The memory already held serves records of any size, as far as it has room.
  const std::size_t room = capacity_ * blocksPerRecord_;
  blocksPerRecord_ = (bytes + sizeof(Block) - 1) / sizeof(Block);
  capacity_ = room / blocksPerRecord_;
  if (capacity_ < expected) grow(expected);
}

void RecordArena::grow(std::size_t capacity) {
  std::unique_ptr<Block[]> grown(new Block[capacity * blocksPerRecord_]);
  if (count_) std::memcpy(grown.get(), blocks_.get(), count_ * blocksPerRecord_ * sizeof(Block));
  blocks_ = std::move(grown);
  capacity_ = capacity;
}

DrawRecord& RecordArena::append() {
  if (count_ == capacity_) grow(std::max<std::size_t>(64, 2 * capacity_));
  return *new (blocks_.get() + count_++ * blocksPerRecord_) DrawRecord;
}

namespace {

// Copies the values the layout carries from vertex `v`, for the side the triangle shows.
void packVertex(const ShadedVertex& v, bool back, const AttributeLayout& l, Real* out) {
  const auto put = [&](int at, const auto& value, int n) {
    if (at >= 0)
      for (int k = 0; k < n; ++k) out[at + k] = value[k];
  };
  put(l.lit, back ? v.back : v.front, 4);
  put(l.position, v.eyePosition, 3);
  put(l.normal, v.eyeNormal, 3);
  put(l.color, v.color, 4);
  put(l.uv, v.uv, 2);
}

}  // namespace

std::size_t setupTriangles(const FrameContext& frame, const Object& object, std::uint32_t objectIndex,
                           std::span<const ShadedVertex> vertices, std::size_t first, std::size_t last,
                           RecordArena& out, const SetupBinning* binning) {
  std::size_t drawn = 0;
  const AttributeLayout& layout = out.layout();
  const auto& indices = object.mesh->indices;
  [[maybe_unused]] const bool tiny = binning && binning->tiny;
#if !ILLUM_USE_DOUBLE
  // Tiny triangles' pixels: colours (multisampled Phong's lit here), or Phong's visible surface.
  std::optional<TinyBatch<TinyFragment>> batch;
  std::optional<TinyBatch<TinySurface>> surfaces;
  const int samples = frame.samples.size() > 1 ? int(frame.samples.size()) : 1;
  if (tiny && frame.shading != Shading::Phong)
    batch.emplace(binning->bins.fragments, frame.shading == Shading::Flat, binning->bins.tilesX(), 0, samples);
  if (tiny && binning->lighting)
    batch.emplace(binning->bins.fragments, false, binning->bins.tilesX(), 0, samples, binning->lighting);
  if (tiny && frame.shading == Shading::Phong && !binning->lighting)
    surfaces.emplace(binning->bins.surfaces, false, binning->bins.tilesX(), binning->shadeOwner);
  // While a group of triangles set up at once (below) holds the batch's lanes, a tiny triangle
  // that comes one by one is covered alone.
  bool grouping = false;
#endif
  const FrameContext::SampleReach reach = frame.reach();
  ClippedPolygon polygon;
  const auto oneByOne = [&](std::size_t t) {
    const std::size_t i = 3 * t;
    const ShadedVertex &a = vertices[indices[i]], &b = vertices[indices[i + 1]], &c = vertices[indices[i + 2]];
    const ClipResult kind = classifyTriangle(a, b, c, frame.width, frame.height);
    if (kind == ClipResult::Outside) return;
    // c is the provoking vertex: flat shading shows its colour on every piece.
    const auto emit = [&](const ShadedVertex& v0, const ShadedVertex& v1, const ShadedVertex& v2, std::uint32_t piece) {
      DrawRecord& r = out.append();
      if (!setupTriangle(v0, v1, v2, frame.width, frame.height, r.setup, frame.sample, reach)) {
        out.drop();
        return;
      }
      ++drawn;
      const bool back = frame.lightModel.twoSided && !r.setup.frontFacing;
      // Counter-clockwise on screen: setup swapped the last two when the triangle came clockwise.
      const ShadedVertex* ordered[3] = {&v0, r.setup.swapped ? &v2 : &v1, r.setup.swapped ? &v1 : &v2};
#if !ILLUM_USE_DOUBLE
      // Multisampled, only a group's tiny triangles are worked out at setup (inGroups, below):
      // one alone is no cheaper than its record.
      if (tiny && samples == 1 && isTiny(r.setup)) {
        TileBins& bins = binning->bins;
        const bool flat = frame.shading == Shading::Flat;
        SurfaceVertices s;
        Color4 lit[3];
        std::uint32_t packed = 0;
        if (frame.shading == Shading::Phong) {
          for (int k = 0; k < 3; ++k) s.position[k] = ordered[k]->eyePosition, s.normal[k] = ordered[k]->eyeNormal;
          s.negate = back;
          s.owner = binning->shadeOwner;
        } else {
          for (int k = 0; k < 3; ++k) lit[k] = back ? ordered[k]->back : ordered[k]->front;
          packed = flat ? packUnorm8(back ? c.back : c.front) : 0;
        }
        forEachTilePiece(r.setup, [&](const TriangleSetup& piece) {
          const int tile = bins.tileOf(piece.minX, piece.minY);
          if (frame.shading == Shading::Phong && !grouping && TinyBatch<TinySurface>::joins(piece, nullptr)) {
            surfaces->add(piece, s, bins.recordsIn(tile), tile);
          } else if (frame.shading == Shading::Phong) {
            surfaces->flush();  // its pixels come first
            bins.surfaces.commit(coverTinySurface(piece, s, bins.recordsIn(tile), bins.surfaces.room(kTinyRoom)), tile);
          } else if (!grouping && TinyBatch<TinyFragment>::joins(piece, flat ? nullptr : lit)) {
            batch->add(piece, flat ? nullptr : lit, packed, bins.recordsIn(tile), tile);
          } else {
            batch->flush();  // its pixels come first
            TinyFragment* room = bins.fragments.room(kTinyRoom);
            bins.fragments.commit(flat ? coverTinyFlat(piece, packed, bins.recordsIn(tile), room)
                                       : coverTinyGouraud(piece, lit, bins.recordsIn(tile), room),
                                  tile);
          }
        });
        out.drop();
        return;
      }
#endif
      r.flat = back ? c.back : c.front;
      r.object = objectIndex;
      r.triangle = std::uint32_t(t);
      r.piece = piece;
      for (int k = 0; k < 3; ++k) packVertex(*ordered[k], back, layout, r.vertex(k, layout));
      if (layout.probe) {
        Real* p = r.vertex(3, layout);
        for (int k = 0; k < 3; ++k) p[k] = c.eyePosition[k], p[3 + k] = c.eyeNormal[k];
      }
      if (binning) binning->bins.addRecord(r.setup, std::uint32_t(out.size() - 1));
    };
    if (kind == ClipResult::Inside) {
      emit(a, b, c, 0);
      return;
    }
    if (clipTriangle({a, b, c}, frame.width, frame.height, polygon) == ClipResult::Outside) return;
    // The clipped polygon is convex: draw it as a fan.
    const auto& v = polygon.vertex;
    for (std::size_t k = 1; k + 1 < polygon.size; ++k) emit(v[0], v[k], v[k + 1], std::uint32_t(k));
  };
#if !ILLUM_USE_DOUBLE
  const auto inGroups = [&](auto& tinyBatch) {
    // Groups of triangles set up at once: the tiny ones join the batch in order, those that
    // cover nothing are dropped, the rest go one by one (which flushes the batch before it
    // appends tiny pixels of its own). Where few are tiny (a coarser mesh, or one seen close),
    // the next groups go one by one instead. Either way the same pixels in the same order.
    TinyGroupSource source{vertices.data(), nullptr, frame.width, frame.height, binning->bins.tilesX(),
                           frame.lightModel.twoSided, frame.shading == Shading::Flat,
                           frame.shading == Shading::Phong, vertices.size(), reach, samples,
                           frame.samples.data()};
    // Lit at setup, before the depth test, a back face would be lit for nothing where it is hidden
    // (as a closed mesh's nearly all are): it keeps its record, which the tile's depth bounds skip.
    source.frontOnly = binning->lighting != nullptr;
    const std::size_t group = std::size_t(tinyGroupCapacity());
    const auto recordsIn = [&](int tile) { return binning->bins.recordsIn(tile); };
    constexpr int kMostOneByOne = 5;  // at most 2^5 − 1 groups one by one between tries
    // A dense mesh's vertex array is far larger than the caches (and the tiny triangles' fragments,
    // written meanwhile, push it out): each group's setup gathers its vertices' first lines
    // (ShadedVertex) at once and waits for every miss. The lines of the group kGroupsAhead on
    // are asked for now. Measured, spheres_1m_8lights_gouraud at 1 thread: 4 samples 97 → 86 ms,
    // 8 samples 144 → 132 ms, 1 sample 50 → 50 ms.
    constexpr std::size_t kGroupsAhead = 2;
    const auto prefetchVertices = [&](std::size_t from, std::size_t to) {
      for (std::size_t k = 3 * from; k < 3 * to; ++k) __builtin_prefetch(vertices.data() + indices[k]);
    };
    int oneByOneGroups = 0, fewInARow = 0;
    for (std::size_t t0 = first; t0 < last; t0 += group) {
      const int count = int(std::min(group, last - t0));
      tinyBatch.flush();
      if (oneByOneGroups > 0) {
        --oneByOneGroups;
        grouping = false;
        for (int j = 0; j < count; ++j) oneByOne(t0 + std::size_t(j));
        continue;
      }
      grouping = true;
      prefetchVertices(t0 + kGroupsAhead * group, std::min(last, t0 + (kGroupsAhead + 1) * group));
      TinyGroupSource at = source;
      at.indices = indices.data() + 3 * t0;
      std::uint32_t fast = 0, empty = 0;
      tinyBatch.setGroupUp(at, count, fast, empty);
      if ((fast | empty) == (1u << count) - 1) {
        // None for the one-by-one path (a dense mesh's usual group): the fast ones taken bit by
        // bit, without a branch per triangle that would mispredict.
        for (std::uint32_t m = fast; m != 0; m &= m - 1) {
          const int j = __builtin_ctz(m);
          tinyBatch.take(j, recordsIn);
        }
        drawn += std::size_t(__builtin_popcount(fast));
        fewInARow = 0;
        continue;
      }
      for (int j = 0; j < count; ++j) {
        if (fast >> j & 1) {
          tinyBatch.take(j, recordsIn);
          ++drawn;
        } else if (!(empty >> j & 1)) {
          oneByOne(t0 + std::size_t(j));
        }
      }
      // Each group in a row with few tiny triangles sends twice as many after it one by one.
      if (2 * __builtin_popcount(fast | empty) >= count) fewInARow = 0;
      else oneByOneGroups = (1 << std::min(++fewInARow, kMostOneByOne)) - 1;
    }
    tinyBatch.flush();
  };
  if (frame.sample.x == 0 && frame.sample.y == 0 && (batch || surfaces)) {
    if (batch) inGroups(*batch);
    else inGroups(*surfaces);
    return drawn;
  }
  for (std::size_t t = first; t < last; ++t) oneByOne(t);
  if (batch) batch->flush();
  if (surfaces) surfaces->flush();
#else
  for (std::size_t t = first; t < last; ++t) oneByOne(t);
#endif
  return drawn;
}

}  // namespace illum
