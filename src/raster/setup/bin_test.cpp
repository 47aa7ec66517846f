// Binning: each tile lists the records whose bounds overlap it, in the order they were added,
// whichever tiles a chunk touched and whatever the previous chunk left behind.
#include "raster/setup/bin.h"

#include "raster/setup/setup.h"
#include "raster/setup/vertex.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace illum {
namespace {

TriangleSetup boundsOnly(int minX, int minY, int maxX, int maxY) {
  TriangleSetup t{};
  t.minX = minX, t.minY = minY, t.maxX = maxX, t.maxY = maxY;
  return t;
}

std::vector<std::uint32_t> recordsOf(const TileBins& bins, int tile) {
  const auto records = bins.records(tile);
  return {records.begin(), records.end()};
}

TEST(TileBins, ListsEachTilesRecordsInOrderAndNothingElsewhere) {
  TileBins bins;
  bins.reset(5 * kTileSize, 3 * kTileSize);  // tiles 0..4 in the bottom row, 5..9, 10..14
  ASSERT_EQ(bins.tileCount(), 15);
  bins.addRecord(boundsOnly(70, 70, 140, 80), 0);  // tiles 6 and 7
  bins.addRecord(boundsOnly(130, 10, 135, 12), 1);  // tile 2
  bins.addRecord(boundsOnly(60, 60, 70, 70), 2);    // tiles 0, 1, 5, 6
  EXPECT_EQ(bins.recordsIn(6), 2u);
  EXPECT_EQ(bins.recordsIn(2), 1u);
  EXPECT_EQ(bins.recordsIn(14), 0u);
  bins.finish();
  const std::vector<std::vector<std::uint32_t>> expected = {{2}, {2}, {1}, {}, {}, {2}, {0, 2}, {0}, {}, {},
                                                            {}, {}, {}, {}, {}};
  for (int tile = 0; tile < bins.tileCount(); ++tile)
    EXPECT_EQ(recordsOf(bins, tile), expected[std::size_t(tile)]) << tile;
  EXPECT_EQ(bins.span().first, 0u);
  EXPECT_EQ(bins.span().last, 8u);
  // Tiny pixels in tile 12 widen it.
  bins.reset(5 * kTileSize, 3 * kTileSize);
  bins.addRecord(boundsOnly(70, 70, 80, 80), 0);  // tile 6
  TinyFragment* room = bins.fragments.room(1);
  room[0] = {0, 0.5f, 0};
  bins.fragments.commit(1, 12);
  bins.finish();
  EXPECT_EQ(bins.span().first, 6u);
  EXPECT_EQ(bins.span().last, 13u);
}

TEST(TileBins, ResetForgetsTheLastChunksCounts) {
  TileBins bins;
  bins.reset(4 * kTileSize, 4 * kTileSize);
  bins.addRecord(boundsOnly(0, 0, 4 * kTileSize - 1, 4 * kTileSize - 1), 0);  // every tile
  bins.finish();
  bins.reset(4 * kTileSize, 4 * kTileSize);
  bins.addRecord(boundsOnly(200, 200, 210, 210), 7);  // tile 15 only
  for (int tile = 0; tile < 15; ++tile) EXPECT_EQ(bins.recordsIn(tile), 0u) << tile;
  EXPECT_EQ(bins.recordsIn(15), 1u);
  bins.finish();
  for (int tile = 0; tile < 15; ++tile) EXPECT_TRUE(recordsOf(bins, tile).empty()) << tile;
  EXPECT_EQ(recordsOf(bins, 15), std::vector<std::uint32_t>{7});
  bins.reset(4 * kTileSize, 4 * kTileSize);  // nothing added
  bins.finish();
  for (int tile = 0; tile < 16; ++tile) EXPECT_TRUE(recordsOf(bins, tile).empty()) << tile;
  EXPECT_FALSE(bins.span().holds(0));
  EXPECT_FALSE(bins.span().holds(15));
}

TEST(TileBins, LeavesOutTheTilesOfItsBoundsATriangleMisses) {
  // A thin triangle across the diagonal of 5×3 tiles: its bounds hold all 15, it reaches 7. Each
  // tile it covers a pixel centre of is listed, and no other (its edges pass far from the tiles'
  // corners, so pixel squares and centres tell the same).
  constexpr int kW = 5 * kTileSize, kH = 3 * kTileSize;
  const auto at = [](double x, double y) {
    ShadedVertex v;
    v.clip = Vec4(Real(x / kW * 2 - 1), Real(y / kH * 2 - 1), 0, 1);
    return v;
  };
  TriangleSetup t;
  ASSERT_TRUE(setupTriangle(at(2, 3), at(317, 185), at(310, 189), kW, kH, t));
  TileBins bins;
  bins.reset(kW, kH);
  bins.addRecord(t, 0);
  bins.finish();
  std::set<int> covered, binned;
  for (int y = t.minY; y <= t.maxY; ++y)
    for (int x = t.minX; x <= t.maxX; ++x) {
      bool inside = true;
      for (const EdgeFunction& e : t.edge)
        inside = inside && e.at(x * kSubpixelOne + kSubpixelOne / 2, y * kSubpixelOne + kSubpixelOne / 2) + e.bias >= 0;
      if (inside) covered.insert(y / kTileSize * 5 + x / kTileSize);
    }
  for (int tile = 0; tile < bins.tileCount(); ++tile)
    if (!recordsOf(bins, tile).empty()) binned.insert(tile);
  EXPECT_EQ(binned, covered);
  EXPECT_EQ(binned.size(), 7u);
}

TEST(TinyRuns, KeepsEachTilesRunsInOrderOutsideNoneTouched) {
  TinyRuns<TinyFragment> runs;
  const auto add = [&](int tile, std::uint32_t tag, std::size_t n) {
    TinyFragment* room = runs.room(n);
    for (std::size_t i = 0; i < n; ++i) room[i] = {tag + std::uint32_t(i), 0.5f, 0};
    runs.commit(n, tile);
  };
  add(9, 100, 2);
  add(4, 200, 1);
  add(9, 300, 3);
  add(9, 400, 1);  // joins the run before it
  runs.finish();
  std::vector<std::vector<std::uint32_t>> tags(12);
  for (int tile = 0; tile < 12; ++tile)
    runs.forEachRun(tile, [&](const TinyFragment* first, std::uint32_t count) {
      for (std::uint32_t i = 0; i < count; ++i) tags[std::size_t(tile)].push_back(first[i].tag);
    });
  for (int tile = 0; tile < 12; ++tile) {
    if (tile == 4) EXPECT_EQ(tags[4], (std::vector<std::uint32_t>{200}));
    else if (tile == 9) EXPECT_EQ(tags[9], (std::vector<std::uint32_t>{100, 101, 300, 301, 302, 400}));
    else EXPECT_TRUE(tags[std::size_t(tile)].empty()) << tile;
  }
}

}  // namespace
}  // namespace illum
