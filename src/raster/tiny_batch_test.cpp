// A batch of tiny triangles writes, on every SIMD target, exactly the fragments that covering them
// one by one writes (coverTinyGouraud, coverTinyFlat), in the same order, with the same runs per
// tile: random tiny triangles of both windings and every bounds shape up to kTinyPixels pixels,
// some covering nothing, some with edges through pixel centres, in several tiles, more than a batch holds.
#include "raster/tiny_batch.h"

#include "raster/tile_raster.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <random>
#include <vector>

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
    if (!setupTriangle(v[0], v[1], v[2], 256, 256, t.setup) || !isTiny(t.setup) || !t.setup.floatExact) continue;
    for (Color4& c : t.lit) c = {unit(rng), unit(rng), unit(rng), 1};
    t.packed = std::uint32_t(rng());
    t.recordsBefore = std::uint32_t(rng() % 1000);
    t.tile = (t.setup.minY / kTileSize) * 4 + t.setup.minX / kTileSize;
    tiny.push_back(t);
  }
  return tiny;
}

// The pixels of each tile's runs, in order.
std::vector<std::vector<TinyFragment>> byTile(TinyRuns<TinyFragment>& runs) {
  runs.finish(16);
  std::vector<std::vector<TinyFragment>> tiles(16);
  for (int tile = 0; tile < 16; ++tile)
    runs.forEachRun(tile, [&](const TinyFragment* first, std::uint32_t count) {
      tiles[std::size_t(tile)].insert(tiles[std::size_t(tile)].end(), first, first + count);
    });
  return tiles;
}

bool same(const TinyFragment& a, const TinyFragment& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(TinyBatch, WritesWhatCoveringOneByOneWritesOnEveryTarget) {
  const std::vector<Tiny> triangles = randomTinyTriangles(203);
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (const bool flat : {false, true}) {
      TinyRuns<TinyFragment> single, batched;
      TinyBatch batch(batched, flat);
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
      const auto expected = byTile(single), actual = byTile(batched);
      for (std::size_t tile = 0; tile < expected.size(); ++tile) {
        ASSERT_EQ(actual[tile].size(), expected[tile].size()) << hwy::TargetName(target) << " tile " << tile;
        for (std::size_t k = 0; k < expected[tile].size(); ++k)
          EXPECT_TRUE(same(actual[tile][k], expected[tile][k]))
              << hwy::TargetName(target) << (flat ? " flat" : " Gouraud") << " tile " << tile << " pixel " << k;
      }
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace illum
