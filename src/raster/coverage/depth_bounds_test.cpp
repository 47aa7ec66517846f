// Occlusion by blocks: a triangle behind everything drawn where its bounds lie is skipped, one
// in front or over a block not yet drawn is not, a block's depths changed by a single sample are
// worked out again, and a skip never hides a sample the depth pass would have let through.
#include "raster/coverage/depth_bounds.h"

#include "raster/coverage/tile_raster.h"
#include "raster/frame_context.h"
#include "raster/setup/setup.h"
#include "raster/tile/multisample.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace illum {
namespace {

constexpr int kSamples = 4;
constexpr PixelRect kTile{0, 0, kTileSize - 1, kTileSize - 1};

// A vertex at window position (x, y) in pixels and window depth z, in clip space with w = 1.
ShadedVertex atWindow(double x, double y, double z) {
  ShadedVertex v;
  v.clip = Vec4(Real(x / kTileSize * 2 - 1), Real(y / kTileSize * 2 - 1), Real(z * 2 - 1), 1);
  return v;
}

// One 64×64 tile at 4 samples, with the depth pass of the multisampled pipeline.
struct SampledTile {
  FrameContext frame;
  std::vector<Real> depth = std::vector<Real>(kTileBlock * kSamples, Real(1));
  std::vector<std::uint32_t> color = std::vector<std::uint32_t>(kTileBlock * kSamples, 0);
  std::vector<std::uint32_t> winners = std::vector<std::uint32_t>(kTileBlock * kSamples, kNoWinner);
  DepthBounds bounds{depth.data(), kSamples, kTile};

  SampledTile() { frame.setSamples(multisamplePattern(kSamples)); }

  TriangleSetup setUp(const ShadedVertex& a, const ShadedVertex& b, const ShadedVertex& c) const {
    TriangleSetup t;
    EXPECT_TRUE(setupTriangle(a, b, c, kTileSize, kTileSize, t, {}, frame.reach()));
    return t;
  }
  std::size_t draw(const TriangleSetup& t) {
    const SamplePlanes planes{kSamples, frame.samples.data(), frame.sampleLanes.x, frame.sampleLanes.y,
                              depth.data(), color.data(), winners.data()};
    bounds.hidden(t);  // (as a tile's loop asks before each draw: drawn() is about that triangle)
    const std::size_t passed = rasterizeSamples(t, kTile, planes, 0);
    if (passed != 0) bounds.drawn();
    return passed;
  }
  // A rectangle from (x0, y0) to (x1, y1) at depth z, as two triangles.
  void drawRectangle(double x0, double y0, double x1, double y1, double z) {
    draw(setUp(atWindow(x0, y0, z), atWindow(x1, y0, z), atWindow(x1, y1, z)));
    draw(setUp(atWindow(x0, y0, z), atWindow(x1, y1, z), atWindow(x0, y1, z)));
  }
  TriangleSetup triangle(double x, double y, double size, double z) const {
    return setUp(atWindow(x, y, z), atWindow(x + size, y, z), atWindow(x, y + size, z));
  }
};

TEST(DepthBounds, SkipsWhatIsBehindWhereItLiesAndNothingElse) {
  SampledTile tile;
  EXPECT_FALSE(tile.bounds.hidden(tile.triangle(10, 10, 20, 0.9)));  // nothing drawn yet
  tile.drawRectangle(0, 0, 32, 64, 0.5);                              // the left half
  EXPECT_TRUE(tile.bounds.hidden(tile.triangle(4, 4, 20, 0.6)));
  EXPECT_FALSE(tile.bounds.hidden(tile.triangle(4, 4, 20, 0.4)));    // in front
  EXPECT_FALSE(tile.bounds.hidden(tile.triangle(20, 4, 20, 0.6)));   // reaching the right half
  // Each skip agrees with the depth pass.
  EXPECT_EQ(tile.draw(tile.triangle(4, 4, 20, 0.6)), 0u);
  EXPECT_GT(tile.draw(tile.triangle(20, 4, 20, 0.6)), 0u);
}

TEST(DepthBounds, WorksOutABlockAgainWhenOneSampleChangedIt) {
  SampledTile tile;
  tile.drawRectangle(0, 0, 64, 64, 0.5);
  const TriangleSetup inBlock = tile.triangle(0.5, 0.5, 2.5, 0.3);  // within block (0, 0): pixels 0..3
  EXPECT_FALSE(tile.bounds.hidden(inBlock));
  // The block's every sample brought nearer, as tiny triangles' pixels would: each says so.
  for (int y = 0; y < DepthBounds::kBlock; ++y)
    for (int x = 0; x < DepthBounds::kBlock; ++x)
      for (int s = 0; s < kSamples; ++s) {
        const auto at = std::uint32_t((y * kTileSize + x) * kSamples + s);
        tile.depth[at] = Real(0.2);
        tile.bounds.drawnAt(at);
      }
  EXPECT_TRUE(tile.bounds.hidden(inBlock));
  EXPECT_EQ(tile.draw(inBlock), 0u);
}

TEST(DepthBounds, NeverSkipsATriangleWithASamplePassing) {
  // Triangles of all sizes at depths up to a few hundred units in the last place apart (about
  // the skip's margin), drawn in turn over a rectangle at the middle one: each skipped one is drawn
  // all the same and must pass no sample.
  SampledTile tile;
  tile.drawRectangle(0, 0, 64, 64, 0.5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(-8, 72), size(0.5, 40);
  std::uniform_int_distribution<int> ulps(-300, 300);
  int skipped = 0, drawn = 0;
  for (int i = 0; i < 4000; ++i) {
    // Half of them level (where a skip's margin is all that keeps an equal depth apart).
    const double z0 = 0.5 + ulps(random) * 6e-8;
    const bool level = i % 2 == 0;
    const double z1 = level ? z0 : 0.5 + ulps(random) * 6e-8, z2 = level ? z0 : 0.5 + ulps(random) * 6e-8;
    const double x = at(random), y = at(random), s = size(random);
    TriangleSetup t;
    if (!setupTriangle(atWindow(x, y, z0), atWindow(x + s, y + s * 0.3, z1), atWindow(x + s * 0.2, y + s, z2),
                       kTileSize, kTileSize, t, {}, tile.frame.reach()))
      continue;
    const bool hidden = tile.bounds.hidden(t);
    const std::size_t passed = tile.draw(t);
    if (hidden) {
      ++skipped;
      EXPECT_EQ(passed, 0u) << "triangle " << i;
    } else if (passed != 0) {
      ++drawn;
    }
  }
  EXPECT_GT(skipped, 400);
  EXPECT_GT(drawn, 200);
}

}  // namespace
}  // namespace illum
