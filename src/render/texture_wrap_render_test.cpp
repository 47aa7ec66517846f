// A texture's wrap modes as the rasterizer draws them: its SIMD sampler (texture_lanes-inl.h)
// gives the reference pipeline's bytes (the one-texel sampler) for every mode, and the picture
// shows what each mode means.
#include "render/reference_render.h"
#include "render/square_test_support.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <cstdlib>

namespace illum {
namespace {

// A 4×4 texture whose every texel differs: red rises to the right, green upwards.
std::shared_ptr<const Texture> ramp(TextureWraps wraps) {
  Image image(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = std::uint8_t(40 + 60 * x);
      p[1] = std::uint8_t(40 + 60 * (3 - y));  // image row 0 is the top
      p[2] = 128;
      p[3] = 255;
    }
  return std::make_shared<const Texture>(image, TexelEncoding::Linear, wraps);
}

// A square filling the picture, texture coordinates from −1 to 2 both ways, lit so that the
// texel is the colour (ambient 1, a white material: GL_MODULATE by the texel).
Scene wrapScene(TextureWraps wraps, Shading shading) {
  Scene s = test::orthographicScene(48, 2);
  s.lightModel.ambient = Color3(1);
  s.lights.clear();
  s.shading = shading;
  Object o;
  o.mesh = test::facingSquare(1, {{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}}});
  o.material.ambient = {1, 1, 1, 1};
  o.material.diffuse = {0, 0, 0, 1};
  o.material.specular = {0, 0, 0, 1};
  o.diffuseTexture = ramp(wraps);
  s.objects.push_back(o);
  return s;
}

const std::uint8_t* at(const Image& image, int x, int y) { return image.pixel(x, y); }

TEST(TextureWrap, EveryModeDrawsTheReferencePipelinesBytes) {
  for (TextureWrap s : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge})
    for (TextureWrap t : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge})
      for (Shading shading : {Shading::Gouraud, Shading::Phong}) {
        const Scene scene = wrapScene({s, t}, shading);
        EXPECT_EQ(renderScene(scene).rgba, renderSceneReference(scene).rgba)
            << int(s) << " " << int(t) << " " << toString(shading);
      }
}

TEST(TextureWrap, ThePictureShowsEachMode) {
  // u runs −1 → 2 over 48 pixels: 16 pixels a period, pixel x at u = (x + ½)/16 − 1.
  const Image repeat = renderScene(wrapScene({TextureWrap::Repeat, TextureWrap::Repeat}, Shading::Phong));
  const Image mirrored = renderScene(wrapScene({TextureWrap::MirroredRepeat, TextureWrap::Repeat}, Shading::Phong));
  const Image clamped = renderScene(wrapScene({TextureWrap::ClampToEdge, TextureWrap::Repeat}, Shading::Phong));
  // In the middle period, u in [0, 1], every mode reads the texture itself, except within half a
  // texel of its edges, where repeat blends in the far edge's texels.
  for (int x = 18; x < 30; ++x) {
    EXPECT_EQ(at(mirrored, x, 20)[0], at(repeat, x, 20)[0]) << x;
    EXPECT_EQ(at(clamped, x, 20)[0], at(repeat, x, 20)[0]) << x;
  }
  EXPECT_NE(at(clamped, 16, 20)[0], at(repeat, 16, 20)[0]);
  for (int x = 0; x < 16; ++x) {
    EXPECT_LE(std::abs(at(repeat, x, 20)[0] - at(repeat, x + 16, 20)[0]), 1) << x;  // repeated
    EXPECT_LE(std::abs(at(mirrored, x, 20)[0] - at(mirrored, 31 - x, 20)[0]), 1) << x;  // mirrored about u = 0
    EXPECT_LE(std::abs(at(mirrored, 32 + x, 20)[0] - at(mirrored, 31 - x, 20)[0]), 1) << x;  // and about u = 1
    EXPECT_EQ(at(clamped, x, 20)[0], 40) << x;        // the left column's red
    EXPECT_EQ(at(clamped, 32 + x, 20)[0], 220) << x;  // the right column's
  }
}

}  // namespace
}  // namespace illum
