// The pixel samples' stratification: Sobol's points and their Owen scrambling keep every
// elementary interval filled once, pixel by pixel, and no two pixels share a pattern.
#include "trace/sampling.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace illum {
namespace {

// Whether the points fill each cell of every grid of 2^k × 2^(m−k) cells (k = 0..m) exactly once.
bool IsNet(const std::vector<Vec2>& points, int m) {
  for (int k = 0; k <= m; ++k) {
    const int columns = 1 << k, rows = 1 << (m - k);
    std::set<int> cells;
    for (const Vec2& p : points) {
      if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) return false;
      cells.insert(int(p.y * Real(rows)) * columns + int(p.x * Real(columns)));
    }
    if (int(cells.size()) != columns * rows) return false;
  }
  return true;
}

TEST(Sobol, FirstPointsAreTheKnownOnes) {
  // Sobol's second dimension: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8 (Joe and Kuo's table).
  const double expected[8][2] = {{0, 0},         {0.5, 0.5},     {0.25, 0.75},   {0.75, 0.25},
                                 {0.125, 0.625}, {0.625, 0.125}, {0.375, 0.375}, {0.875, 0.875}};
  for (std::uint32_t i = 0; i < 8; ++i) {
    const auto p = sobol2D(i);
    EXPECT_EQ(p[0], std::uint32_t(expected[i][0] * 4294967296.0)) << i;
    EXPECT_EQ(p[1], std::uint32_t(expected[i][1] * 4294967296.0)) << i;
  }
}

TEST(PixelSamples, EveryPowerOfTwoPrefixIsANetInEveryPixel) {
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int m = 1; m <= 8; ++m) {
        std::vector<Vec2> points;
        for (int s = 0; s < (1 << m); ++s) points.push_back(pixelSampleOffset(x, y, s));
        EXPECT_TRUE(IsNet(points, m)) << "pixel " << x << "," << y << ", " << (1 << m) << " samples";
      }
}

TEST(PixelSamples, StratifiedPairsAreNetsInEveryDimension) {
  for (std::uint32_t dimension = 1; dimension <= 3; ++dimension)
    for (int pixel = 0; pixel < 8; ++pixel)
      for (int m = 1; m <= 7; ++m) {
        std::vector<Vec2> points;
        for (std::uint32_t s = 0; s < (1u << m); ++s) points.push_back(stratifiedPair(sampleSeed(pixel, 3, 0, 1), dimension, s));
        EXPECT_TRUE(IsNet(points, m)) << "dimension " << dimension << ", pixel " << pixel << ", " << (1 << m) << " samples";
      }
}

TEST(PixelSamples, DimensionsAreShuffledApart) {
  // Without the shuffle, sample s's first coordinate in one dimension would fix its quarter in any
  // other (each is Sobol's point s, scrambled digit by digit): of the 16 combinations of quarters
  // only 4 would ever occur. Shuffled, 64 samples meet nearly all of them.
  const std::uint64_t seed = sampleSeed(5, 7, 0, 1);
  std::set<std::pair<int, int>> quarters12, quarters01;
  for (std::uint32_t s = 0; s < 64; ++s) {
    const Vec2 p0 = pixelSampleOffset(5, 7, int(s)), p1 = stratifiedPair(seed, 1, s), p2 = stratifiedPair(seed, 2, s);
    quarters12.insert({int(p1.x * 4), int(p2.x * 4)});
    quarters01.insert({int(p0.x * 4), int(p1.x * 4)});
  }
  EXPECT_GE(quarters12.size(), 12u);
  EXPECT_GE(quarters01.size(), 12u);
}

TEST(PixelSamples, IndependentPointsAreNoNet) {
  // The test itself can tell: 16 independent points fill a 4×4 grid only once in ~10^5 tries.
  int nets = 0;
  for (int pixel = 0; pixel < 64; ++pixel) {
    std::vector<Vec2> points;
    Rng rng(sampleSeed(pixel, 0, 0, 5), 1);
    for (int s = 0; s < 16; ++s) points.push_back({rng.uniform(), rng.uniform()});
    nets += IsNet(points, 4) ? 1 : 0;
  }
  EXPECT_EQ(nets, 0);
}

TEST(PixelSamples, PixelsHaveTheirOwnPatterns) {
  std::set<std::pair<Real, Real>> first;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const Vec2 p = pixelSampleOffset(x, y, 0);
      first.insert({p.x, p.y});
    }
  EXPECT_EQ(first.size(), 256u);
  // Over many pixels each sample's offset is uniform: its mean is about 1/2 in both axes.
  for (int s : {0, 1, 5}) {
    double sx = 0, sy = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const Vec2 p = pixelSampleOffset(x, y, s);
        sx += p.x, sy += p.y;
      }
    EXPECT_NEAR(sx / 4096, 0.5, 0.015) << s;
    EXPECT_NEAR(sy / 4096, 0.5, 0.015) << s;
  }
}

}  // namespace
}  // namespace illum
