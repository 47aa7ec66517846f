// A physically based material drawn by every renderer against the equation worked by hand.
#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

// A sphere seen head-on under a directional light along the view: at its pole N = L = V = H, so
// D = 1/(πα²), V = 1/4, F = f0 and
//   c = (1 − f0)·base + π·D·V·F = (1 − f0)·base + f0 / (4α²).
// base 0.5, f0 0.04, roughness 0.8 (α = 0.64): 0.48 + 0.0244 = 0.5044 → byte 129.
TEST(PhysicallyBased, ThePoleOfASphereMatchesTheEquationWorkedByHand) {
  Scene s;
  s.width = s.height = 65;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2.2f;
  s.lightModel.ambient = Color3(0);
  s.lights[0].position = {0, 0, 1, 0};
  s.model = LightingModel::CookTorrance;
  Object ball;
  ball.mesh = std::make_shared<const Mesh>(makeSphere(1, 64, 32));
  PhysicalMaterial p;
  p.baseColor = Color3(0.5f);
  p.roughness = 0.8f;
  p.f0 = Color3(0.04f);
  glFromPhysical(ball.material, p);
  s.objects.push_back(ball);
  const Real alpha = 0.64f;
  const Real expected = (1 - 0.04f) * 0.5f + 0.04f / (4 * alpha * alpha);
  const int byte = int(std::lround(expected * 255));
  ASSERT_EQ(byte, 129);
  for (RendererKind renderer : {RendererKind::Raster, RendererKind::Whitted})
    for (Shading shading : {Shading::Phong, Shading::Gouraud}) {
      s.renderer = renderer;
      s.shading = shading;
      const Image image = renderScene(s);
      EXPECT_NEAR(image.pixel(32, 32)[0], byte, 1) << toString(renderer) << " " << toString(shading);
    }
  // The same material drawn by the classic models through its derived GL parameters: diffuse
  // base·(1 − metallic) = 0.5 under N·L = 1, plus the Blinn-Phong highlight of the derived
  // specular 2.5·√0.04 = 0.5 at N·H = 1.
  s.renderer = RendererKind::Raster;
  s.model = LightingModel::BlinnPhong;
  EXPECT_EQ(renderScene(s).pixel(32, 32)[0], 255);
  s.model = LightingModel::Lambert;
  EXPECT_EQ(renderScene(s).pixel(32, 32)[0], 128);
}

TEST(PhysicallyBased, AMaterialsOwnModelOverridesTheScenes) {
  Scene s;
  s.width = s.height = 33;
  s.camera.projection = Projection::Orthographic;
  s.lightModel.ambient = Color3(0);
  s.lights[0].position = {0, 0, 1, 0};
  Object ball;
  ball.mesh = std::make_shared<const Mesh>(makeSphere(1, 32, 16));
  ball.material.diffuse = {0.5f, 0.5f, 0.5f, 1};
  ball.material.specular = {1, 1, 1, 1};
  ball.material.shininess = 10;
  s.objects.push_back(ball);
  const int blinnPhong = renderScene(s).pixel(16, 16)[0];
  EXPECT_EQ(blinnPhong, 255);  // 0.5 + 1
  s.objects[0].material.model = LightingModel::Lambert;
  EXPECT_EQ(renderScene(s).pixel(16, 16)[0], 128);
}

}  // namespace
}  // namespace illum
