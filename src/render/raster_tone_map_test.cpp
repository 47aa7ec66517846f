// The rasterizer under a tone map: each lit colour is tone mapped before GL's clamp and the 8-bit
// framebuffer (a radiance of 3 is Reinhard's 3/4, not the clamped 1's 1/2), on every route and
// shading frequency, as the reference pipeline draws it; the background stays its colour.
#include "render/reference_render.h"
#include "render/square_test_support.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

// A white square facing a white directional light of 3 along its normal: diffuse 3, and nothing else.
Scene brightSquare(Shading shading, int multisample) {
  Scene s = test::orthographicScene(16, 1);
  s.lightModel.ambient = Color3(0);
  s.lights.resize(1);
  s.lights[0].position = {0, 0, 1, 0};
  s.lights[0].diffuse = Color3(3);
  s.lights[0].specular = Color3(0);
  s.lights[0].ambient = Color3(0);
  s.shading = shading;
  s.multisample = multisample;
  s.background = {0.25f, 0.5f, 0.75f, 1};
  Object o;
  o.mesh = test::facingSquare(2);
  o.material.diffuse = {1, 1, 1, 1};
  o.material.ambient = o.material.specular = o.material.emission = {0, 0, 0, 1};
  s.objects.push_back(o);
  return s;
}

TEST(RasterToneMap, LitColoursAreToneMappedBeforeTheClamp) {
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong})
    for (int samples : {1, 4}) {
      Scene s = brightSquare(shading, samples);
      EXPECT_EQ(renderScene(s).pixel(8, 8)[0], 255);  // no tone map: GL's clamp
      s.display.toneMap = ToneMap::Reinhard;
      const Image image = renderScene(s);
      EXPECT_EQ(image.pixel(8, 8)[0], 191) << toString(shading) << " " << samples;  // round(3/4 · 255)
      EXPECT_EQ(image.rgba, renderSceneReference(s).rgba) << toString(shading) << " " << samples;
      s.display.encoding = Encoding::Srgb;
      EXPECT_EQ(renderScene(s).pixel(8, 8)[0], 224);  // sRGB of 191/255: 0.8803
    }
}

TEST(RasterToneMap, TheBackgroundIsItsColour) {
  Scene s = brightSquare(Shading::Phong, 1);
  s.camera.viewHeight = 8;  // the square in the middle, the background around it
  s.display.toneMap = ToneMap::Aces;
  const Image image = renderScene(s);
  EXPECT_EQ(image.pixel(0, 0)[0], 64);   // round(0.25 · 255), not ACES of it
  EXPECT_EQ(image.pixel(0, 0)[2], 191);
  EXPECT_EQ(image.pixel(8, 8)[0], 243);  // ACES(3) = 22.68/23.78 = 0.9537 (Narkowicz's fit)
}

}  // namespace
}  // namespace illum
