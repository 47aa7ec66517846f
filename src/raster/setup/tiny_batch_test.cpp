// A batch of tiny triangles writes, on every SIMD target, exactly the fragments that covering them
// one by one writes (coverTinyGouraud, coverTinyFlat), in the same order, with the same runs per
// tile: random tiny triangles of both windings and every bounds shape up to kTinyPixels pixels,
// some covering nothing, some with edges through pixel centres, in several tiles, more than a batch holds.
#include "raster/setup/tiny_batch.h"

#include "raster/coverage/tile_raster.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <random>
#include <vector>

// (Tiny triangles are worked out at setup for float channels only: ILLUM_DOUBLE=OFF.)
#if !ILLUM_USE_DOUBLE
namespace illum {
namespace {

struct Tiny {
  TriangleSetup setup;
  Color4 lit[3];
  std::uint32_t packed, recordsBefore;
  int tile;
};

std::vector<Tiny> randomTinyTriangles(int count) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pixel(0, 250), offset(-3 * kSubpixelOne, 3 * kSubpixelOne);
  std::uniform_real_distribution<Real> unit(0, 1), w(0.2f, 3);
  std::vector<Tiny> tiny;
  while (int(tiny.size()) < count) {
    ShadedVertex v[3];
    const std::int64_t x = std::int64_t(pixel(rng)) * kSubpixelOne, y = std::int64_t(pixel(rng)) * kSubpixelOne;
    // A third on the half-pixel grid: edges through pixel centres (the top-left rule decides).
    const std::int64_t grid = tiny.size() % 3 == 0 ? kSubpixelOne / 2 : 1;
    for (ShadedVertex& vertex : v) {
      vertex.hasWindow = true;
      vertex.window = {x + offset(rng) / grid * grid, y + offset(rng) / grid * grid, unit(rng), 1 / w(rng)};
    }
    Tiny t;
    if (!setupTriangle(v[0], v[1], v[2], 256, 256, t.setup) || !isTiny(t.setup) || !inOneTile(t.setup) ||
        !t.setup.floatExact)
      continue;
    for (Color4& c : t.lit) c = {unit(rng), unit(rng), unit(rng), 1};
    t.packed = std::uint32_t(rng());
    t.recordsBefore = std::uint32_t(rng() % 1000);
    t.tile = (t.setup.minY / kTileSize) * 4 + t.setup.minX / kTileSize;
    tiny.push_back(t);
  }
  return tiny;
}

// The pixels of each tile's runs, in order.
template <class Pixel>
std::vector<std::vector<Pixel>> byTile(TinyRuns<Pixel>& runs) {
  runs.finish();
  std::vector<std::vector<Pixel>> tiles(16);
  for (int tile = 0; tile < 16; ++tile)
    runs.forEachRun(tile, [&](const Pixel* first, std::uint32_t count) {
      tiles[std::size_t(tile)].insert(tiles[std::size_t(tile)].end(), first, first + count);
    });
  return tiles;
}

template <class Pixel>
bool same(const Pixel& a, const Pixel& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every tile's pixels in `batched` are `single`'s, bit for bit, in the same order.
template <class Pixel>
void expectSameByTile(TinyRuns<Pixel>& single, TinyRuns<Pixel>& batched, const std::string& where) {
  const auto expected = byTile(single), actual = byTile(batched);
  for (std::size_t tile = 0; tile < expected.size(); ++tile) {
    ASSERT_EQ(actual[tile].size(), expected[tile].size()) << where << " tile " << tile;
    for (std::size_t k = 0; k < expected[tile].size(); ++k)
      EXPECT_TRUE(same(actual[tile][k], expected[tile][k])) << where << " tile " << tile << " pixel " << k;
  }
}

TEST(TinyBatch, WritesWhatCoveringOneByOneWritesOnEveryTarget) {
  const std::vector<Tiny> triangles = randomTinyTriangles(203);
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (const bool flat : {false, true}) {
      TinyRuns<TinyFragment> single, batched;
      TinyBatch batch(batched, flat, 4);
      std::size_t covered = 0;
      for (const Tiny& t : triangles) {
        TinyFragment* room = single.room(kTinyRoom);
        const std::size_t n = flat ? coverTinyFlat(t.setup, t.packed, t.recordsBefore, room)
                                   : coverTinyGouraud(t.setup, t.lit, t.recordsBefore, room);
        single.commit(n, t.tile);
        covered += n;
        batch.add(t.setup, flat ? nullptr : t.lit, t.packed, t.recordsBefore, t.tile);
      }
      batch.flush();
      ASSERT_GT(covered, triangles.size());  // most cover a pixel or more, some none
      expectSameByTile(single, batched, std::string(hwy::TargetName(target)) + (flat ? " flat" : " Gouraud"));
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

// Phong's tiny triangles added one at a time: the surface batch writes what coverTinySurface
// writes, positions and renormalized normals (some of zero length), negated on some.
TEST(TinyBatch, SurfacesAddedOneByOneWriteWhatCoveringEachWrites) {
  const std::vector<Tiny> triangles = randomTinyTriangles(203);
  std::mt19937 rng(29);
  std::uniform_real_distribution<Real> signedUnit(-1, 1);
  std::vector<SurfaceVertices> surfaces(triangles.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    SurfaceVertices& v = surfaces[i];
    for (int k = 0; k < 3; ++k) {
      v.position[k] = {signedUnit(rng), signedUnit(rng), signedUnit(rng) - 2};
      v.normal[k] = i % 10 == 0 ? Vec3(0) : Vec3(signedUnit(rng), signedUnit(rng), signedUnit(rng));
    }
    v.negate = i % 3 == 1;
    v.owner = 9;
  }
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    TinyRuns<TinySurface> single, batched;
    TinyBatch batch(batched, false, 4, 9);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const Tiny& t = triangles[i];
      const std::size_t n = coverTinySurface(t.setup, surfaces[i], t.recordsBefore, single.room(kTinyRoom));
      single.commit(n, t.tile);
      covered += n;
      batch.add(t.setup, surfaces[i], t.recordsBefore, t.tile);
    }
    batch.flush();
    ASSERT_GT(covered, triangles.size());
    expectSameByTile(single, batched, hwy::TargetName(target));
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

// setupTinyGroup sets up on every target what setupTriangle and setTinyLanes set up one by one:
// the same verdicts (fast: inside, tiny, float-exact, opaque; empty: inside, no pixel centre) and
// the same bits in every lane of every fast triangle, for triangles of both windings, two-sided
// lighting, translucent vertices, horizontal and vertical edges, degenerate and big ones, slivers
// the viewport cuts small, vertices outside the clip volume, and groups that are not whole vectors;
// with the vertices' fields gathered into lanes and read one by one.
TEST(TinyBatch, GroupSetupEqualsOneByOneSetupOnEveryTarget) {
  std::mt19937 rng(5);
  const int width = 300, height = 200;
  std::uniform_int_distribution<int> pixelX(-2, width + 2), pixelY(-2, height + 2), near(-4 * kSubpixelOne, 4 * kSubpixelOne);
  std::uniform_real_distribution<Real> unit(0, 1), w(0.2f, 3);
  std::vector<ShadedVertex> vertices;
  std::vector<std::uint32_t> indices;
  for (int t = 0; t < 997; ++t) {
    const std::int64_t x = std::int64_t(pixelX(rng)) * kSubpixelOne, y = std::int64_t(pixelY(rng)) * kSubpixelOne;
    // 0: big; 1: degenerate; 2: a long sliver; 3: outside; 4: a horizontal edge (top or bottom),
    // 5: a vertical one; others tiny.
    const int kind = t % 10;
    for (int k = 0; k < 3; ++k) {
      ShadedVertex v;
      std::int64_t vx = x + near(rng), vy = y + near(rng);
      if (kind == 0) vx += near(rng) * 20, vy += near(rng) * 20;
      if (kind == 1 && k == 2) vx = x, vy = y;
      if (kind == 1 && k == 1) vx = x + 2 * (vertices.back().window.x - x), vy = y + 2 * (vertices.back().window.y - y);
      if (kind == 2 && k == 1) vx -= 5000 * kSubpixelOne;
      if (kind == 4 && k == 1) vy = vertices.back().window.y;
      if (kind == 5 && k == 1) vx = vertices.back().window.x;
      v.outcode = kind == 3 && k == 0 ? 4 : 0;
      v.hasWindow = v.outcode == 0;
      v.window = {vx, vy, unit(rng), 1 / w(rng)};
      v.front = {unit(rng), unit(rng), unit(rng), t % 7 == 0 && k == 1 ? Real(0.5) : Real(1)};
      v.back = {unit(rng), unit(rng), unit(rng), t % 9 == 0 ? Real(0.5) : Real(1)};
      indices.push_back(std::uint32_t(vertices.size()));
      vertices.push_back(v);
    }
  }
  const int triangles = int(indices.size() / 3), tilesX = (width + kTileSize - 1) / kTileSize;
  int targets = 0, fastSeen = 0, emptySeen = 0, othersSeen = 0, crossingSeen = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    const int group = tinyGroupCapacity();
    for (const bool gathered : {false, true})  // the vertices' fields gathered into lanes, or read one by one
      for (const bool twoSided : {false, true})
        for (const bool flat : {false, true})
          for (int t0 = 0; t0 < triangles; t0 += group) {
            const int count = std::min(group, triangles - t0);
            const TinyGroupSource source{vertices.data(), indices.data() + 3 * t0, width, height,
                                         tilesX, twoSided, flat, false,
                                         gathered ? vertices.size() : 0, {}, 1};
            TinyBatchLanes lanes, expected;
            int tile[TinyBatchLanes::kCapacity];
            std::uint32_t fast = 0, empty = 0;
            setupTinyGroup(source, count, lanes, tile, fast, empty);
            for (int j = 0; j < count; ++j) {
              const std::uint32_t* at = indices.data() + 3 * (t0 + j);
              const ShadedVertex &a = vertices[at[0]], &b = vertices[at[1]], &c = vertices[at[2]];
              const std::string where = std::string(hwy::TargetName(target)) + (gathered ? " gathered" : "") +
                                        " triangle " + std::to_string(t0 + j);
              TriangleSetup s;
              const bool inside = a.outcode == 0 && b.outcode == 0 && c.outcode == 0;
              const bool drawn = inside && setupTriangle(a, b, c, width, height, s);
              EXPECT_EQ(bool(empty >> j & 1), inside && !drawn) << where;
              const bool back = twoSided && drawn && !s.frontFacing;
              const ShadedVertex* ordered[3] = {&a, drawn && s.swapped ? &c : &b, drawn && s.swapped ? &b : &c};
              const Color4 lit[3] = {back ? ordered[0]->back : ordered[0]->front,
                                     back ? ordered[1]->back : ordered[1]->front,
                                     back ? ordered[2]->back : ordered[2]->front};
              const bool isFast = drawn && isTiny(s) && TinyBatch<TinyFragment>::joins(s, flat ? nullptr : lit);
              ASSERT_EQ(bool(fast >> j & 1), isFast) << where;
              fastSeen += isFast, emptySeen += inside && !drawn, othersSeen += !isFast && drawn;
              if (!isFast) continue;
              setTinyLanes(expected, j, s, flat ? nullptr : lit, packUnorm8(back ? c.back : c.front), 0);
              EXPECT_EQ(tile[j], (s.minY / kTileSize) * tilesX + s.minX / kTileSize) << where;
              const auto sameLane = [&](const auto& x, const auto& y) {
                return std::memcmp(&x[j], &y[j], sizeof x[j]) == 0;
              };
              for (int i = 0; i < 3; ++i) {
                EXPECT_TRUE(sameLane(lanes.edge[i], expected.edge[i]) && sameLane(lanes.stepX[i], expected.stepX[i]) &&
                            sameLane(lanes.stepY[i], expected.stepY[i]) && sameLane(lanes.bias[i], expected.bias[i]))
                    << where << " edge " << i;
                EXPECT_TRUE(sameLane(lanes.z[i], expected.z[i]) && sameLane(lanes.invW[i], expected.invW[i])) << where;
                for (int k = 0; k < 3; ++k) {
                  if (!flat) {
                    EXPECT_TRUE(sameLane(lanes.lit[i][k], expected.lit[i][k])) << where << " colour " << i << k;
                  }
                }
              }
              EXPECT_TRUE(sameLane(lanes.invArea, expected.invArea)) << where;
              if (flat) {
                EXPECT_EQ(lanes.packed[j], expected.packed[j]) << where;
              }
              EXPECT_EQ(lanes.firstTag[j], expected.firstTag[j]) << where;
              EXPECT_EQ(lanes.width[j], expected.width[j]) << where;
              EXPECT_EQ(lanes.count[j], expected.count[j]) << where;
              const int crosses =
                  int(s.minX / kTileSize != s.maxX / kTileSize) | int(s.minY / kTileSize != s.maxY / kTileSize) << 1;
              EXPECT_EQ(lanes.crosses[j], crosses) << where;
              crossingSeen += crosses != 0;
            }
          }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
  EXPECT_GT(fastSeen, 1000);
  EXPECT_GT(emptySeen, 100);
  EXPECT_GT(othersSeen, 100);
  EXPECT_GT(crossingSeen, 20);
}

// Takes the triangles of `source` (indices from its first triangle on) into `batch` a group at a
// time, as setupTriangles does, flushing after each group: each fast one is taken, then, whether
// fast or not, handed to reference(a, b, c, fast) with its vertices, before its group is flushed.
template <class Pixel, class RecordsIn, class Reference>
void takeInGroups(TinyBatch<Pixel>& batch, const TinyGroupSource& source, int triangles, const RecordsIn& recordsIn,
                  const Reference& reference) {
  const int group = tinyGroupCapacity();
  for (int t0 = 0; t0 < triangles; t0 += group) {
    const int count = std::min(group, triangles - t0);
    TinyGroupSource at = source;
    at.indices = source.indices + 3 * t0;
    std::uint32_t fast = 0, empty = 0;
    batch.setGroupUp(at, count, fast, empty);
    for (int j = 0; j < count; ++j) {
      const bool isFast = fast >> j & 1;
      if (isFast) batch.take(j, recordsIn);
      const std::uint32_t* v = at.indices + 3 * j;
      reference(source.vertices[v[0]], source.vertices[v[1]], source.vertices[v[2]], isFast);
    }
    batch.flush();
  }
}

// A group's tiny triangles whose bounds run across tile edges: the batch sorts their pixels into
// the tiles, each after that tile's records, exactly as covering each tile's piece of them one by
// one (forEachTilePiece) writes them.
TEST(TinyBatch, GroupAcrossTilesWritesWhatCoveringEachTilesPieceWrites) {
  std::mt19937 rng(17);
  const int width = 200, height = 150, tilesX = (width + kTileSize - 1) / kTileSize;
  std::uniform_int_distribution<int> edge(0, 3), along(2, 140), near(-3 * kSubpixelOne, 3 * kSubpixelOne);
  std::uniform_real_distribution<Real> unit(0, 1), w(0.2f, 3);
  std::vector<ShadedVertex> vertices;
  std::vector<std::uint32_t> indices;
  for (int t = 0; t < 800; ++t) {  // about a tile edge or corner: x or y near 64 or 128
    const int which = edge(rng);
    const std::int64_t cx = which & 1 ? kTileSize * (1 + which / 2) : along(rng);
    const std::int64_t cy = which & 1 ? along(rng) % 140 : kTileSize * (1 + which / 2) % 128;
    for (int k = 0; k < 3; ++k) {
      ShadedVertex v;
      v.outcode = 0;
      v.hasWindow = true;
      const std::int64_t y = t % 5 == 0 ? kTileSize : cy;  // a fifth about the corners' row
      v.window = {cx * kSubpixelOne + near(rng), y * kSubpixelOne + near(rng), unit(rng), 1 / w(rng)};
      v.front = {unit(rng), unit(rng), unit(rng), 1};
      indices.push_back(std::uint32_t(vertices.size()));
      vertices.push_back(v);
    }
  }
  const auto recordsIn = [](int tile) { return std::uint32_t(7 * tile + 3); };
  const int triangles = int(indices.size() / 3);
  int targets = 0, crossing = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (const bool flat : {false, true}) {
      TinyRuns<TinyFragment> single, batched;
      TinyBatch batch(batched, flat, tilesX);
      const TinyGroupSource source{vertices.data(), indices.data(), width, height, tilesX, false, flat, false,
                                   vertices.size(), {}, 1};
      takeInGroups(batch, source, triangles, recordsIn, [&](const ShadedVertex& a, const ShadedVertex& b,
                                                            const ShadedVertex& c, bool fast) {
        if (!fast) return;
        TriangleSetup s;
        ASSERT_TRUE(setupTriangle(a, b, c, width, height, s));
        crossing += !inOneTile(s);
        const Color4 lit[3] = {a.front, s.swapped ? c.front : b.front, s.swapped ? b.front : c.front};
        forEachTilePiece(s, [&](const TriangleSetup& piece) {
          const int tile = (piece.minY / kTileSize) * tilesX + piece.minX / kTileSize;
          TinyFragment* room = single.room(kTinyRoom);
          single.commit(flat ? coverTinyFlat(piece, packUnorm8(c.front), recordsIn(tile), room)
                             : coverTinyGouraud(piece, lit, recordsIn(tile), room),
                        tile);
        });
      });
      expectSameByTile(single, batched, std::string(hwy::TargetName(target)) + (flat ? " flat" : " Gouraud"));
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
  EXPECT_GT(crossing, 200);
}

// Phong's tiny triangles: the surface batch writes, tile by tile, what covering each tile's piece
// one by one (coverTinySurface) writes: positions and renormalized normals (some interpolating to
// zero length), negated on the back faces under two-sided lighting, in one tile or across several.
TEST(TinyBatch, SurfaceBatchWritesWhatCoveringEachPieceOneByOneWrites) {
  std::mt19937 rng(23);
  const int width = 200, height = 150, tilesX = (width + kTileSize - 1) / kTileSize;
  std::uniform_int_distribution<int> x(2, 190), y(2, 140), near(-3 * kSubpixelOne, 3 * kSubpixelOne);
  std::uniform_real_distribution<Real> unit(0, 1), w(0.2f, 3), signedUnit(-1, 1);
  std::vector<ShadedVertex> vertices;
  std::vector<std::uint32_t> indices;
  for (int t = 0; t < 900; ++t) {
    // A third about the tile edges at 64 and 128, the rest anywhere.
    const std::int64_t cx = t % 3 == 0 ? kTileSize * (1 + t % 2) : x(rng), cy = t % 3 == 0 ? kTileSize : y(rng);
    for (int k = 0; k < 3; ++k) {
      ShadedVertex v;
      v.outcode = 0;
      v.hasWindow = true;
      v.window = {cx * kSubpixelOne + near(rng), cy * kSubpixelOne + near(rng), unit(rng), 1 / w(rng)};
      v.eyePosition = {signedUnit(rng), signedUnit(rng), -1 - unit(rng)};
      // Every tenth triangle's normals cancel out: the renormalized normal falls back to +z.
      v.eyeNormal = t % 10 == 0 ? Vec3(0) : Vec3(signedUnit(rng), signedUnit(rng), signedUnit(rng));
      indices.push_back(std::uint32_t(vertices.size()));
      vertices.push_back(v);
    }
  }
  const auto recordsIn = [](int tile) { return std::uint32_t(5 * tile + 1); };
  const std::uint32_t owner = 77;
  const int triangles = int(indices.size() / 3);
  int targets = 0, crossing = 0, backs = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (const bool twoSided : {false, true}) {
      TinyRuns<TinySurface> single, batched;
      TinyBatch batch(batched, false, tilesX, owner);
      const TinyGroupSource source{vertices.data(), indices.data(), width, height, tilesX, twoSided, false, true,
                                   vertices.size(), {}, 1};
      takeInGroups(batch, source, triangles, recordsIn, [&](const ShadedVertex& a, const ShadedVertex& b,
                                                            const ShadedVertex& c, bool fast) {
        TriangleSetup s;
        const bool drawn = setupTriangle(a, b, c, width, height, s);
        ASSERT_EQ(fast, drawn && isTiny(s) && s.floatExact);
        if (!fast) return;
        crossing += !inOneTile(s);
        SurfaceVertices v;
        const ShadedVertex* ordered[3] = {&a, s.swapped ? &c : &b, s.swapped ? &b : &c};
        for (int k = 0; k < 3; ++k) v.position[k] = ordered[k]->eyePosition, v.normal[k] = ordered[k]->eyeNormal;
        v.negate = twoSided && !s.frontFacing;
        v.owner = owner;
        backs += v.negate;
        forEachTilePiece(s, [&](const TriangleSetup& piece) {
          const int tile = (piece.minY / kTileSize) * tilesX + piece.minX / kTileSize;
          single.commit(coverTinySurface(piece, v, recordsIn(tile), single.room(kTinyRoom)), tile);
        });
      });
      expectSameByTile(single, batched, std::string(hwy::TargetName(target)) + (twoSided ? " two-sided" : ""));
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
  EXPECT_GT(crossing, 100);
  EXPECT_GT(backs, 200);
}

}  // namespace
}  // namespace illum
#endif  // !ILLUM_USE_DOUBLE
