#include <illum/texture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace illum {
namespace {

Image checker2x2() {
  // Top row (image row 0): red, green; bottom row: blue, white.
  Image img(2, 2);
  const std::uint8_t texels[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) img.rgba[std::size_t(i * 4 + c)] = texels[i][c];
  return img;
}

TEST(Texture, TexelCentresAndGlOrientation) {
  const Texture t(checker2x2());
  // v = 0 is the image's bottom row (GL convention): texel centres at 1/4 and 3/4.
  EXPECT_EQ(t.sampleLevel({0.25, 0.25}, 0), Vec4(0, 0, 1, 1));  // bottom left: blue
  EXPECT_EQ(t.sampleLevel({0.25, 0.75}, 0), Vec4(1, 0, 0, 1));  // top left: red
  EXPECT_EQ(t.sampleLevel({0.75, 0.75}, 0), Vec4(0, 1, 0, 1));  // top right: green
}

TEST(Texture, BilinearBetweenTexelsAndRepeat) {
  const Texture t(checker2x2());
  const Vec4 centre = t.sampleLevel({0.5, 0.5}, 0);
  EXPECT_NEAR(centre.r, 0.5, 1e-6);
  EXPECT_NEAR(centre.g, 0.5, 1e-6);
  EXPECT_NEAR(centre.b, 0.5, 1e-6);
  // GL_REPEAT: u = 1.25 is u = 0.25; at u = 0 the left and right columns blend.
  EXPECT_EQ(t.sampleLevel({1.25, 0.25}, 0), t.sampleLevel({0.25, 0.25}, 0));
  const Vec4 seam = t.sampleLevel({0.0, 0.25}, 0);
  EXPECT_NEAR(seam.r, 0.5, 1e-6);  // blue and white
  EXPECT_NEAR(seam.b, 1.0, 1e-6);
}

// GL_MIRRORED_REPEAT: every other period the texture is read backwards, the edge texel twice at
// the turn; GL_CLAMP_TO_EDGE: outside [0, 1] the edge texel, and no blend across the seam.
TEST(Texture, MirroredRepeatAndClampToEdge) {
  const Texture mirrored(checker2x2(), TexelEncoding::Linear, {TextureWrap::MirroredRepeat, TextureWrap::MirroredRepeat});
  EXPECT_EQ(mirrored.sampleLevel({1.25, 0.25}, 0), Vec4(1, 1, 1, 1));  // u = 0.75 read backwards: white
  EXPECT_EQ(mirrored.sampleLevel({1.75, 0.25}, 0), Vec4(0, 0, 1, 1));  // and 0.25: blue
  EXPECT_EQ(mirrored.sampleLevel({-0.25, 0.25}, 0), Vec4(0, 0, 1, 1));
  EXPECT_EQ(mirrored.sampleLevel({2.25, 0.25}, 0), mirrored.sampleLevel({0.25, 0.25}, 0));  // period 2
  EXPECT_EQ(mirrored.sampleLevel({1.0, 0.25}, 0), Vec4(1, 1, 1, 1));  // the turn: the edge texel, unblended
  EXPECT_EQ(mirrored.sampleLevel({0.25, 1.25}, 0), Vec4(1, 0, 0, 1));  // v too: 1.25 reads 0.75, the top row's red
  const Texture clamped(checker2x2(), TexelEncoding::Linear, {TextureWrap::ClampToEdge, TextureWrap::Repeat});
  EXPECT_EQ(clamped.sampleLevel({0.0, 0.25}, 0), Vec4(0, 0, 1, 1));  // no blend with the right column
  EXPECT_EQ(clamped.sampleLevel({-3.0, 0.25}, 0), Vec4(0, 0, 1, 1));
  EXPECT_EQ(clamped.sampleLevel({7.0, 0.25}, 0), Vec4(1, 1, 1, 1));
  EXPECT_EQ(clamped.sampleLevel({1.25, 0.25}, 0), Vec4(1, 1, 1, 1));
  // Repeat stays what it was: u = 0 blends both columns.
  EXPECT_NEAR(clamped.sampleLevel({0.25, 0.0}, 0).r, 0.5, 1e-6);  // v repeats: red over blue
}

// GL pairs rows for the next level from its first row, the image's bottom one: of an odd column of
// 3 texels, level 1 is the mean of the bottom two, and the top texel is left out.
TEST(Texture, MipmapRowsPairFromTheBottom) {
  Image column(1, 3);
  column.rgba = {255, 0, 0, 255, /**/ 0, 0, 255, 255, /**/ 0, 0, 200, 255};  // top red, then blue
  const Texture t(column);
  EXPECT_EQ(t.levelCount(), 2);
  EXPECT_EQ(t.sampleLevel({0.5, 0.5}, 1), Vec4(0, 0, Real(228) / Real(255), 1));  // (255 + 200 + 2) / 4 twice over
}

TEST(Texture, MipmapsAverageAndTrilinearPicksByFootprint) {
  const Texture t(checker2x2());
  EXPECT_EQ(t.levelCount(), 2);
  // Level 1 keeps the mean as GL keeps an RGBA8 level: rounded to a byte, 510/4 → 128.
  const Vec4 mean(128 / 255.0, 128 / 255.0, 128 / 255.0, 1);
  const Vec4 level1 = t.sampleLevel({0.3, 0.9}, 1);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(level1[c], mean[c], 1e-6);
  // A footprint of 2 texels per pixel is level 1 exactly; of 1 texel, level 0.
  EXPECT_EQ(t.sample({0.25, 0.25}, 2), t.sampleLevel({0.25, 0.25}, 1));
  EXPECT_EQ(t.sample({0.25, 0.25}, 1), t.sampleLevel({0.25, 0.25}, 0));
  // Halfway (√2 texels) is the mean of both levels.
  const Vec4 half = t.sample({0.25, 0.25}, std::sqrt(Real(2)));
  EXPECT_NEAR(half.b, 0.5 * (1 + 128 / 255.0), 1e-5);
}

TEST(Texture, TheMipLevelIsLog2OfTheFootprint) {
  // At the blue texel's centre level 0 reads 1 and level 1 reads 128/255: the blue channel gives
  // the weight of level 1, which is the level's fraction, log2 of the footprint.
  const Texture t(checker2x2());
  const Real level1 = 128 / Real(255);
  const auto levelOf = [&](Real footprint) { return (1 - t.sample({0.25, 0.25}, footprint).b) / (1 - level1); };
  for (int i = 1; i < 1000; ++i) {
    const Real footprint = 1 + Real(i) / 1000;
    EXPECT_NEAR(levelOf(footprint), std::log2(footprint), 2e-6) << footprint;
  }
  // Powers of two are levels exactly; a footprint of at most one texel, or not a number, is level
  // 0; beyond the last level (an infinite footprint too), the last level.
  EXPECT_EQ(t.sample({0.25, 0.25}, 2).b, level1);
  for (Real small : {Real(1), Real(0.5), Real(0), Real(-3), std::numeric_limits<Real>::quiet_NaN()})
    EXPECT_EQ(t.sample({0.25, 0.25}, small).b, 1) << small;
  for (Real big : {Real(4), Real(1e30), std::numeric_limits<Real>::infinity()})
    EXPECT_EQ(t.sample({0.25, 0.25}, big).b, level1) << big;
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// A colour texture stored sRGB is decoded to linear before filtering (GL_SRGB8_ALPHA8): the mean of
// black and white is linear grey 0.5 (the sRGB byte 188), not the byte 128; alpha stays linear;
// the stored bytes come back exactly.
TEST(Texture, SrgbTexelsAreDecodedBeforeFiltering) {
  Image img(2, 1);
  img.rgba = {0, 0, 0, 255, 255, 255, 255, 0};
  const Texture t(img, TexelEncoding::Srgb);
  EXPECT_NEAR(t.sampleLevel({0.5f, 0.5f}, 0).r, 0.5, 1e-6);
  EXPECT_NEAR(t.sampleLevel({0.5f, 0.5f}, 0).a, 0.5, 1e-6);
  // The mipmap averages linear values too: black and white make linear 0.5, kept as the sRGB byte
  // nearest it, 188 (0.5029), not the byte mean 128 (0.2158).
  EXPECT_NEAR(t.sampleLevel({0.5f, 0.5f}, 1).r, 0.5029, 1e-3);
  EXPECT_EQ(t.byteSize(), 2u * 4 + 4);  // 8 bits a channel, every level
  Image grey(1, 1);
  grey.rgba = {188, 128, 0, 255};
  const Texture g(grey, TexelEncoding::Srgb);
  EXPECT_NEAR(g.sampleLevel({0.5f, 0.5f}, 0).r, 0.5029, 1e-3);  // ((188/255 + 0.055)/1.055)^2.4
  EXPECT_NEAR(g.sampleLevel({0.5f, 0.5f}, 0).g, 0.2158, 1e-3);
  EXPECT_EQ(g.baseImage().rgba, grey.rgba);
  Image every(256, 1);
  for (int i = 0; i < 256; ++i) every.rgba[std::size_t(4 * i)] = std::uint8_t(i), every.rgba[std::size_t(4 * i + 3)] = 255;
  EXPECT_EQ(Texture(every, TexelEncoding::Srgb).baseImage().rgba, every.rgba);
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// 8 bits a channel on every level: a 4096² texture costs its 64 MiB and a third more for the mip
// chain (floats would cost four times that).
TEST(Texture, KeepsEveryLevelAsBytes) {
  Image big(4096, 4096);
  const Texture t(std::move(big));
  EXPECT_EQ(t.levelCount(), 13);
  const std::size_t base = std::size_t(4096) * 4096 * 4;
  EXPECT_GE(t.byteSize(), base + base / 4);
  EXPECT_LE(t.byteSize(), base + base / 3 + 64);
}

}  // namespace
}  // namespace illum
