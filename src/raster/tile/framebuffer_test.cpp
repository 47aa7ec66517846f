// The framebuffer's tiles: cleared when first drawn, copied into an image with its rows flipped
// and the pixels unlike the background counted, a tile drawn in lent memory (the last pass of
// a frame) copied from there without touching the framebuffer's blocks, and a tile released once
// it is finished giving its block to the next tile drawn.
#include "raster/tile/framebuffer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace illum {
namespace {

std::uint32_t pixelOf(const Image& image, int x, int y) {
  std::uint32_t p;
  std::memcpy(&p, image.pixel(x, y), 4);
  return p;
}

// 70×66: partial tiles on the right and at the top, and rows whose length is no multiple of any
// vector's lanes.
constexpr int kWidth = 70, kHeight = 66;
const Color4 kClear(0, 0, 1, 1);
const Color4 kRed(1, 0, 0, 1);

TEST(Framebuffer, CopiesEachTileFlippedAndCountsPixelsUnlikeTheBackground) {
  Framebuffer fb;
  fb.reset(kWidth, kHeight, kClear);
  ASSERT_EQ(fb.tileCount(), 4);
  fb.clearTile(64, 0);  // tile 1, bottom right
  fb.writeColor(69, 0, kRed);
  fb.writeColor(65, 63, kRed);
  EXPECT_TRUE(fb.depthTest(69, 0, Real(0.5)));
  EXPECT_FALSE(fb.depthTest(69, 0, Real(0.5)));
  EXPECT_EQ(fb.depth(68, 0), Real(1));  // cleared
  Image image;
  // Against black every pixel counts, drawn tile or not; against the clear colour only the two red ones.
  EXPECT_EQ(fb.toImage(image, Color4(0, 0, 0, 1)), std::size_t(kWidth * kHeight));
  EXPECT_EQ(fb.toImage(image, kClear), 2u);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  EXPECT_EQ(pixelOf(image, 69, kHeight - 1), packUnorm8(kRed));
  EXPECT_EQ(pixelOf(image, 65, kHeight - 64), packUnorm8(kRed));
  EXPECT_EQ(pixelOf(image, 68, kHeight - 1), packUnorm8(kClear));
  EXPECT_EQ(pixelOf(image, 0, 0), packUnorm8(kClear));  // tile 2, never drawn
}

TEST(Framebuffer, LentTileIsDrawnAndCopiedFromItsMemoryAndForgottenWhenReturned) {
  Framebuffer fb;
  fb.reset(kWidth, kHeight, kClear);
  fb.clearTile(0, 0);
  fb.writeColor(3, 3, kRed);  // in the framebuffer's own block of tile 0
  auto memory = std::make_unique<TileMemory>();
  const int tile = 3;  // top right: 6 × 2 pixels
  ASSERT_FALSE(fb.drawn(tile));
  fb.lendTile(tile, *memory);
  fb.clearTile(64, 64);
  EXPECT_TRUE(fb.drawn(tile));
  EXPECT_EQ(fb.depthTile(64, 64), memory->depth.data());
  fb.writeColor(69, 65, kRed);
  EXPECT_TRUE(fb.depthTest(69, 65, Real(0.25)));
  EXPECT_EQ(memory->depth[1 * kTileSize + 5], Real(0.25));
  EXPECT_EQ(memory->depth[0], Real(1));
  Image image;
  fb.imageOf(image);
  EXPECT_EQ(fb.copyTile(tile, image, packUnorm8(kClear)), 1u);
  EXPECT_EQ(pixelOf(image, 69, 0), packUnorm8(kRed));
  EXPECT_EQ(pixelOf(image, 64, 1), packUnorm8(kClear));
  fb.returnTile(tile);
  EXPECT_FALSE(fb.drawn(tile));
  EXPECT_EQ(fb.toImage(image, kClear), 1u);  // tile 0's pixel; tile 3 is background again
  EXPECT_EQ(pixelOf(image, 3, kHeight - 4), packUnorm8(kRed));
  EXPECT_EQ(pixelOf(image, 69, 0), packUnorm8(kClear));
}

TEST(Framebuffer, ReleasedTileGivesItsBlockToTheNextTileAndIsBackgroundAgain) {
  Framebuffer fb;
  fb.reset(kWidth, kHeight, kClear, 4);
  EXPECT_EQ(fb.blocksMade(), 0u);
  fb.clearTile(0, 0);  // tile 0
  EXPECT_TRUE(fb.depthTest(3, 3, Real(0.5), 2));
  fb.writeColor(3, 3, kRed, 2);
  fb.clearTile(64, 0);  // tile 1
  EXPECT_EQ(fb.blocksMade(), 2u);
  Image image;
  fb.imageOf(image);
  EXPECT_EQ(fb.copyTile(0, image, packUnorm8(kClear)), 1u);  // a quarter red: the tile is finished
  EXPECT_NE(pixelOf(image, 3, kHeight - 4), packUnorm8(kClear));
  fb.releaseTile(0);
  EXPECT_FALSE(fb.drawn(0));
  fb.clearTile(0, 64);  // tile 2 takes tile 0's block, cleared
  EXPECT_EQ(fb.blocksMade(), 2u);
  EXPECT_EQ(fb.depth(3, 67, 2), Real(1));
  EXPECT_EQ(fb.toImage(image, kClear), 0u);  // tile 0 is the clear colour again, as is all else
  fb.clearTile(0, 0);  // tile 0 again: no block is free
  EXPECT_EQ(fb.blocksMade(), 3u);
  EXPECT_EQ(fb.depth(3, 3, 2), Real(1));
  // A new frame of the same samples keeps the blocks; of other samples, makes new ones.
  fb.reset(kWidth, kHeight, kClear, 4);
  for (int tile = 0; tile < 3; ++tile) fb.clearTile(tile % 2 * 64, tile / 2 * 64);
  EXPECT_EQ(fb.blocksMade(), 3u);
  fb.reset(kWidth, kHeight, kClear, 8);
  EXPECT_EQ(fb.blocksMade(), 0u);
}

}  // namespace
}  // namespace illum
