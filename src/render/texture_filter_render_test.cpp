// How the ray tracers filter a texture when a pixel takes many samples: the samples average over
// the pixel, so each one reads the texture over its share of the pixel only (pbrt-v4's scaled ray
// differentials); a whole pixel's footprint on each sample would blur the texture over two pixels.
#include "render/square_test_support.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

// A 32×1 black texture with one white pair of texels (10 and 11) on a square 16 pixels wide: two
// texels a pixel, the pair exactly pixel 5's column.
Scene stripeScene(int samples) {
  Scene s = test::orthographicScene(16, 2);
  s.lightModel.ambient = Color3(1);
  s.lights.clear();
  s.renderer = RendererKind::Whitted;
  s.rayTracing.samples = samples;
  Image image(32, 1);
  for (int x = 0; x < 32; ++x) {
    const std::uint8_t v = x == 10 || x == 11 ? 255 : 0;
    image.pixel(x, 0)[0] = image.pixel(x, 0)[1] = image.pixel(x, 0)[2] = v;
    image.pixel(x, 0)[3] = 255;
  }
  Object o;
  o.mesh = test::facingSquare(1);
  o.material.ambient = {1, 1, 1, 1};
  o.material.diffuse = o.material.specular = {0, 0, 0, 1};
  o.diffuseTexture = std::make_shared<const Texture>(image);
  s.objects.push_back(o);
  return s;
}

TEST(TextureFilter, ManySamplesKeepATexturePixelSharp) {
  const Image sharp = renderScene(stripeScene(64));
  EXPECT_GE(sharp.pixel(5, 8)[0], 210);  // the pair's pixel stays nearly white (bilinear: 223)
  EXPECT_LE(sharp.pixel(4, 8)[0], 25);   // and its neighbours nearly black (16; a whole pixel a sample: 29 and 35)
  EXPECT_LE(sharp.pixel(6, 8)[0], 25);
  // One ray through the centre reads the texture over the whole pixel, as the rasterizer does
  // (mip level 1, whose texel 5 is the white pair): the same pixel, white.
  const Image one = renderScene(stripeScene(1));
  EXPECT_EQ(one.pixel(5, 8)[0], 255);
  EXPECT_EQ(one.pixel(4, 8)[0], 0);
}

}  // namespace
}  // namespace illum
