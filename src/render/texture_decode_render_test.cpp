// Every texel byte as the rasterizer's SIMD sampler decodes it (texture_lanes-inl.h: sRGB colour
// through the table, read from registers where the target allows; an opaque texture's alpha known
// to be 1) gives the reference pipeline's bytes, which decode through Texture::sample's table.
#include "render/reference_render.h"
#include "render/square_test_support.h"
#include "image/texel_lookup.h"

#include <illum/display.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>
#include <hwy/targets.h>

namespace illum {
namespace {

// A 16×16 texture in which each channel takes every byte value once, in a different order per
// channel; alpha is 255 everywhere (opaque) or every byte too.
std::shared_ptr<const Texture> everyByte(TexelEncoding encoding, bool opaque) {
  Image image(16, 16);
  for (int i = 0; i < 256; ++i) {
    std::uint8_t* p = image.pixel(i % 16, i / 16);
    p[0] = std::uint8_t(i);
    p[1] = std::uint8_t(255 - i);
    p[2] = std::uint8_t(i * 7 + 3);  // 7 is odd: every byte once
    p[3] = opaque ? 255 : std::uint8_t(i * 11 + 5);
  }
  return std::make_shared<const Texture>(image, encoding);
}

// The texture on a square `texels` texels per side across `pixels` pixels (magnified when texels
// < pixels, minified through the mip chain otherwise), the texel's colour lit by ambient 1.
Scene decodeScene(TexelEncoding encoding, bool opaque, int pixels, Real texels, Shading shading) {
  Scene s = test::orthographicScene(pixels, 2);
  s.lightModel.ambient = Color3(1);
  s.lights.clear();
  s.shading = shading;
  Object o;
  const Real r = texels / 16;
  o.mesh = test::facingSquare(1, {{{0, 0}, {r, 0}, {r, r}, {0, r}}});
  o.material.ambient = {1, 1, 1, 1};
  o.material.diffuse = {0, 0, 0, 1};
  o.material.specular = {0, 0, 0, 1};
  o.diffuseTexture = everyByte(encoding, opaque);
  s.objects.push_back(o);
  return s;
}

TEST(TextureDecode, EveryByteDrawsTheReferencePipelinesBytes) {
  // On every SIMD target this CPU has: the table in registers (AVX-512: looked up with byte
  // permutes where the CPU has VBMI, and with float permutes) or gathered.
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets())
   for (bool byteLookups : {true, false}) {
    hwy::SetSupportedTargetsForTest(target);
    setTexelByteLookupsForTest(byteLookups);
    for (TexelEncoding encoding : {TexelEncoding::Srgb, TexelEncoding::Linear})
      for (bool opaque : {true, false})
        for (Shading shading : {Shading::Gouraud, Shading::Phong})
          for (Real texels : {Real(16), Real(160)}) {  // 16 texels over 64 pixels, then 160: mipmapped
            const Scene scene = decodeScene(encoding, opaque, 64, texels, shading);
            const Image drawn = renderScene(scene);
            EXPECT_EQ(drawn.rgba, renderSceneReference(scene).rgba)
                << (encoding == TexelEncoding::Srgb ? "srgb" : "linear") << (opaque ? " opaque " : " alpha ")
                << toString(shading) << " " << texels << " " << hwy::TargetName(target)
                << (byteLookups && texelByteLookups() ? " byte lookups" : "");
          }
  }
  hwy::SetSupportedTargetsForTest(0);
  setTexelByteLookupsForTest(true);
}

TEST(TextureDecode, TexelCentresShowTheirOwnBytes) {
  // 16 texels over 48 pixels: pixel 3k + 1's centre is texel k's. The sRGB texel decoded, lit by 1
  // and encoded back to sRGB for the file is its own byte again (the encoding round-trips every
  // byte), up to the interpolated coordinate's last bits: a neighbour's weight of a few 1e-4 moves
  // a dark byte by several, so the bytes are compared as the linear values they encode.
  Scene scene = decodeScene(TexelEncoding::Srgb, true, 48, 16, Shading::Phong);
  scene.display.encoding = Encoding::Srgb;
  const Image drawn = renderScene(scene);
  const auto linear = [](int byte) { return srgbDecoded(Real(byte) / 255); };
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const int i = x + 16 * y;  // the texture's image row 0 is its top, as the picture's
      const std::uint8_t* p = drawn.pixel(3 * x + 1, 3 * y + 1);
      EXPECT_NEAR(linear(p[0]), linear(i), 0.006) << x << " " << y;
      EXPECT_NEAR(linear(p[1]), linear(255 - i), 0.006) << x << " " << y;
      EXPECT_NEAR(linear(p[2]), linear((i * 7 + 3) % 256), 0.006) << x << " " << y;
    }
}

}  // namespace
}  // namespace illum
