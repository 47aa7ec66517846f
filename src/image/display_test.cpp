// Tone maps and encodings against their closed forms, and the pictures every renderer writes with
// them: the bytes are the displayed values, the linear (EXR) values stay as they were.
#include <illum/display.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

TEST(Display, ToneMapsAtKnownPoints) {
  EXPECT_EQ(toneMapped(2, ToneMap::None), 2);
  EXPECT_FLOAT_EQ(toneMapped(1, ToneMap::Reinhard), 0.5f);
  EXPECT_FLOAT_EQ(toneMapped(3, ToneMap::Reinhard), 0.75f);
  EXPECT_EQ(toneMapped(0, ToneMap::Aces), 0);
  // Narkowicz's fit at 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 2.54 / 3.16.
  EXPECT_NEAR(toneMapped(1, ToneMap::Aces), 2.54 / 3.16, 1e-6);
  EXPECT_EQ(toneMapped(INFINITY, ToneMap::Reinhard), 1);
  EXPECT_EQ(toneMapped(NAN, ToneMap::Aces), 0);
  EXPECT_EQ(toneMapped(-1, ToneMap::Reinhard), 0);
  Real last = 0;
  for (Real x = 0.01f; x < 100; x *= 1.1f) {  // monotonic, within [0, 1]
    const Real y = toneMapped(x, ToneMap::Aces);
    EXPECT_GE(y, last);
    EXPECT_LE(y, 1);
    last = y;
  }
}

TEST(Display, SrgbEncodingRoundTripsEveryByte) {
  EXPECT_EQ(srgbEncoded(0), 0);
  EXPECT_FLOAT_EQ(srgbEncoded(1), 1);
  EXPECT_NEAR(srgbEncoded(0.5f), 0.735357, 1e-5);
  EXPECT_NEAR(srgbEncoded(0.002f), 0.02584, 1e-6);  // the linear segment
  // Decoding (the inverse transfer function) brings every encoded byte back.
  for (int i = 0; i < 256; ++i) {
    const double encoded = i / 255.0;
    const double linear = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
    EXPECT_EQ(std::lround(srgbEncoded(Real(linear)) * 255), i);
  }
}

TEST(Display, EveryPixelMapsOnItsOwnWhereverItLies) {
  // 1000 pixels (a vector's tail too): every colour byte through the encoding, alpha kept, and the
  // background's bytes, wherever they stand (whole vectors of them, single ones), its shown ones.
  // (A dark red whose shown byte, 10, is not its stored byte's encoding, 13.)
  const Vec4 background(0.003f, 0.4f, 0.6f, 1);
  const std::uint8_t stored[4] = {1, 102, 153, 255};
  Image image(1000, 1);
  std::uint32_t state = 12345;
  for (int x = 0; x < image.width; ++x) {
    std::uint8_t* p = image.pixel(x, 0);
    const bool backdrop = (x >= 64 && x < 160) || x % 37 == 0;
    for (int c = 0; c < 4; ++c) {
      state = state * 1664525u + 1013904223u;
      p[c] = backdrop ? stored[c] : std::uint8_t(state >> 24);
    }
  }
  const Image before = image;
  const Display display{ToneMap::None, Encoding::Srgb};
  applyDisplay(image, display, &background);
  const std::array<std::uint8_t, 4> shown = backgroundBytes(background, display);
  EXPECT_EQ(shown[0], 10);
  EXPECT_EQ(std::lround(srgbEncoded(1.0f / 255) * 255), 13);
  for (int x = 0; x < image.width; ++x) {
    const std::uint8_t* was = before.pixel(x, 0);
    const std::uint8_t* is = image.pixel(x, 0);
    const bool backdrop = std::equal(was, was + 4, stored);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(is[c], backdrop ? shown[std::size_t(c)] : std::lround(srgbEncoded(Real(was[c]) / 255) * 255))
          << "pixel " << x << " channel " << c;
    EXPECT_EQ(is[3], was[3]) << "pixel " << x;
  }
}

// A quad of emission `e` filling a 16×16 picture, no lights.
Scene glowing(RendererKind renderer, Color3 e) {
  Scene s;
  s.renderer = renderer;
  s.width = s.height = 16;
  s.lights.clear();
  s.lightModel.ambient = Color3(0);
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 1;
  s.rayTracing.samples = 4;
  Object o;
  auto m = std::make_shared<Mesh>();
  m->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m->normals.assign(4, Vec3(0, 0, 1));
  m->indices = {0, 1, 2, 0, 2, 3};
  o.mesh = m;
  o.material.diffuse = o.material.ambient = {0, 0, 0, 1};
  o.material.emission = Color4(e, 1);
  s.objects.push_back(o);
  return s;
}

TEST(Display, TheRasterizerEncodesItsBytes) {
  Scene s = glowing(RendererKind::Raster, {0.5f, 1, 0});
  EXPECT_EQ(renderScene(s).pixel(8, 8)[0], 128);  // linear, as GL writes it
  s.display.encoding = Encoding::Srgb;
  FloatImage linear;
  const Image image = renderScene(s, nullptr, nullptr, &linear);
  EXPECT_EQ(image.pixel(8, 8)[0], std::lround(srgbEncoded(128.0f / 255) * 255));  // 188
  EXPECT_EQ(image.pixel(8, 8)[0], 188);
  EXPECT_EQ(image.pixel(8, 8)[1], 255);
  EXPECT_EQ(image.pixel(8, 8)[2], 0);
  EXPECT_EQ(image.pixel(8, 8)[3], 255);
  EXPECT_FLOAT_EQ(linear.pixel(8, 8)[0], 128.0f / 255);  // the EXR keeps the linear value
}

TEST(Display, ThePathTracerToneMapsRadianceAboveOne) {
  Scene s = glowing(RendererKind::Path, {3, 1, 0});
  EXPECT_EQ(renderScene(s).pixel(8, 8)[0], 255);  // clamped
  s.display.toneMap = ToneMap::Reinhard;
  FloatImage linear;
  const Image image = renderScene(s, nullptr, nullptr, &linear);
  EXPECT_EQ(image.pixel(8, 8)[0], 191);  // 3/4
  EXPECT_EQ(image.pixel(8, 8)[1], 128);  // 1/2
  EXPECT_EQ(image.pixel(8, 8)[2], 0);
  EXPECT_FLOAT_EQ(linear.pixel(8, 8)[0], 3);  // unclamped, untouched
  s.display.encoding = Encoding::Srgb;
  EXPECT_EQ(renderScene(s).pixel(8, 8)[1], 188);  // sRGB(1/2)
}

// Whitted's local colour is GL's, clamped; its bytes are encoded like every renderer's.
TEST(Display, TheRayTracerEncodesItsColours) {
  Scene s = glowing(RendererKind::Whitted, {0.5f, 1, 0});
  s.display.encoding = Encoding::Srgb;
  EXPECT_EQ(renderScene(s).pixel(8, 8)[0], 188);
  s.background = {0.5f, 0.5f, 0.5f, 1};
  s.objects.clear();
  EXPECT_EQ(renderScene(s).pixel(0, 0)[0], 188);  // the background is a linear colour too
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// 16 bits: the display encoding of the linear values at full precision, alpha linear, labels over.
TEST(Display, SixteenBitPictureKeepsThePrecision) {
  Scene s = glowing(RendererKind::Path, {3, 0.5f, 0});
  s.display = {ToneMap::Reinhard, Encoding::Linear};
  FloatImage linear;
  renderScene(s, nullptr, nullptr, &linear);
  const std::vector<std::uint16_t> deep = picture16(s, linear);
  const std::size_t centre = (8 * 16 + 8) * 4;
  EXPECT_EQ(deep[centre], 49151);      // 3/4 of 65535
  EXPECT_EQ(deep[centre + 1], 21845);  // 1/3
  EXPECT_EQ(deep[centre + 3], 65535);
  s.display.encoding = Encoding::Srgb;
  EXPECT_EQ(picture16(s, linear)[centre + 1], std::lround(srgbEncoded(Real(0.5) / Real(1.5)) * 65535));
  // A label is laid over it.
  s.labels.push_back({"HELLO", std::nullopt, Vec2(8, 12), Color3(0, 0, 1), 14});
  const std::vector<std::uint16_t> labelled = picture16(s, linear);
  int changed = 0;
  const std::vector<std::uint16_t> plain = [&] {
    Scene t = s;
    t.labels.clear();
    return picture16(t, linear);
  }();
  for (std::size_t i = 0; i < plain.size(); ++i) changed += plain[i] != labelled[i];
  EXPECT_GT(changed, 10);
  // The PNG says 16 bits, RGBA (IHDR: bit depth at byte 24, colour type at 25).
  const std::vector<std::uint8_t> png = encodePng16(16, 16, plain);
  EXPECT_EQ(png[24], 16);
  EXPECT_EQ(png[25], 6);
}

}  // namespace
}  // namespace illum
