// The pixels the multisampled depth pass lists for the shade hand-off: on every SIMD target and
// sample count (4, 8, 16), triangles of all sizes and depths drawn one after another over a tile, each
// lists exactly the pixels where some sample of it passed the depth test, in row order, once
// each; and its passes, depths and winners are those of the pass that lists nothing.
#include "raster/coverage/tile_raster.h"
#include "raster/frame_context.h"
#include "raster/setup/setup.h"
#include "raster/tile/multisample.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <random>
#include <vector>

namespace illum {
namespace {

constexpr PixelRect kTile{64, 128, 64 + kTileSize - 1, 128 + kTileSize - 1};  // away from the frame's corner

// A vertex at window position (x, y) in pixels of a 256×256 frame and window depth z (w = 1).
ShadedVertex atWindow(double x, double y, double z) {
  ShadedVertex v;
  v.clip = Vec4(Real(x / 256 * 2 - 1), Real(y / 256 * 2 - 1), Real(z * 2 - 1), 1);
  return v;
}

struct Planes {
  std::vector<Real> depth;
  std::vector<std::uint32_t> color, winners;
  explicit Planes(int samples)
      : depth(kTileBlock * std::size_t(samples), Real(1)),
        color(kTileBlock * std::size_t(samples), 0),
        winners(kTileBlock * std::size_t(samples), kNoWinner) {}
  SamplePlanes of(const FrameContext& frame, int samples) {
    return {samples, frame.samples.data(), frame.sampleLanes.x, frame.sampleLanes.y, depth.data(), color.data(), winners.data()};
  }
};

TEST(ListedSamples, AreThePixelsWhereASamplePassedInRowOrderOnEveryTarget) {
  for (const int samples : {4, 8, 16}) {
    FrameContext frame;
    frame.setSamples(multisamplePattern(samples));
    ASSERT_EQ(frame.samples.size(), std::size_t(samples));  // (the sample counts with a pattern)
    std::mt19937 random{std::uint32_t(samples)};
    std::uniform_real_distribution<double> atX(40, 128), atY(104, 192), size(0.3, 50), depth(0.2, 0.8);
    std::vector<TriangleSetup> triangles;
    while (triangles.size() < 300) {
      const double x = atX(random), y = atY(random), s = size(random);
      TriangleSetup t;
      if (setupTriangle(atWindow(x, y, depth(random)), atWindow(x + s, y + s * 0.4, depth(random)),
                        atWindow(x + s * 0.3, y + s * 1.2, depth(random)), 256, 256, t, {}, frame.reach()))
        triangles.push_back(t);
    }
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      Planes plain(samples), listing(samples);
      std::size_t lists = 0, pixels = 0;
      for (std::size_t i = 0; i < triangles.size(); ++i) {
        const TriangleSetup& t = triangles[i];
        const std::vector<Real> before = plain.depth;
        const std::size_t passed = rasterizeSamples(t, kTile, plain.of(frame, samples), std::uint32_t(i));
        std::vector<std::uint32_t> listed(listedRoom(t, kTile), 0xDEAD);
        std::size_t count = 0;
        EXPECT_EQ(rasterizeSamples(t, kTile, listing.of(frame, samples), std::uint32_t(i), listed.data(), count), passed);
        // The pixels some sample of which the triangle brought nearer, in index (row) order.
        std::vector<std::uint32_t> expected;
        for (std::uint32_t p = 0; p < std::uint32_t(kTileSize * kTileSize); ++p)
          for (int s = 0; s < samples; ++s)
            if (plain.depth[p * std::uint32_t(samples) + std::uint32_t(s)] != before[p * std::uint32_t(samples) + std::uint32_t(s)]) {
              expected.push_back(p);
              break;
            }
        listed.resize(count);
        EXPECT_EQ(listed, expected) << hwy::TargetName(target) << ", " << samples << " samples, triangle " << i;
        lists += count != 0, pixels += count;
      }
      EXPECT_EQ(listing.depth, plain.depth) << hwy::TargetName(target);
      EXPECT_EQ(listing.winners, plain.winners) << hwy::TargetName(target);
      EXPECT_GT(lists, 100u);   // a third of the triangles pass somewhere,
      EXPECT_GT(pixels, 3000u); // some of them over many pixels
    }
    hwy::SetSupportedTargetsForTest(0);
  }
}

}  // namespace
}  // namespace illum
