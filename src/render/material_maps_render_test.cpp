// glTF's metallic-roughness, normal and emissive maps as every renderer draws them: a map of one
// texel draws what the material with that texel applied by hand draws, with per-pixel shading,
// in the reference pipeline and in the ray and path tracers.
#include "render/reference_render.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace illum {
namespace {

// A 2×2 quad in the z = 0 plane facing the camera, u along +x and v along +y (or mirrored).
std::shared_ptr<const Mesh> quad(bool mirroredU = false) {
  auto m = std::make_shared<Mesh>();
  m->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m->normals.assign(4, Vec3(0, 0, 1));
  m->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  if (mirroredU)
    for (Vec2& uv : m->uvs) uv.x = 1 - uv.x;
  m->indices = {0, 1, 2, 0, 2, 3};
  return m;
}

std::shared_ptr<const Texture> oneTexel(int r, int g, int b) {
  Image image(1, 1);
  image.rgba = {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255};
  return std::make_shared<const Texture>(image);
}

Scene quadScene(LightingModel model) {
  Scene s;
  s.width = s.height = 32;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 1.5f;  // the quad fills the picture
  s.lightModel.ambient = Color3(0.1f);
  s.lights[0].position = {0.6f, 0.3f, 1, 0};
  s.model = model;
  Object o;
  o.mesh = quad();
  PhysicalMaterial p;
  p.baseColor = {0.6f, 0.4f, 0.3f};
  p.roughness = 0.9f;
  p.metallic = 1;
  glFromPhysical(o.material, p);
  o.material.specular = {0.8f, 0.8f, 0.8f, 1};  // the classic models' highlight, for the normal map
  o.material.shininess = 20;
  s.objects.push_back(o);
  return s;
}

// Largest difference of any channel of any pixel.
int maxDifference(const Image& a, const Image& b) {
  int worst = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return worst;
}

// Every renderer that reads the maps, and the reference pipeline, against the hand-made scene.
void expectSameAsByHand(const Scene& mapped, const Scene& byHand, int tolerance) {
  for (RendererKind renderer : {RendererKind::Raster, RendererKind::Whitted}) {
    Scene a = mapped, b = byHand;
    a.renderer = b.renderer = renderer;
    const Image image = renderScene(a);
    EXPECT_LE(maxDifference(image, renderScene(b)), tolerance) << toString(renderer);
    if (renderer == RendererKind::Raster) {
      EXPECT_EQ(renderSceneReference(a).rgba, image.rgba);
    }
  }
}

TEST(MaterialMaps, MetallicRoughnessTexelScalesTheFactors) {
  Scene mapped = quadScene(LightingModel::CookTorrance);
  mapped.objects[0].maps.metallicRoughness = oneTexel(0, 102, 51);  // roughness × 0.4, metallic × 0.2
  Scene byHand = quadScene(LightingModel::CookTorrance);
  byHand.objects[0].material.physical.roughness *= Real(102) / 255;
  byHand.objects[0].material.physical.metallic *= Real(51) / 255;
  expectSameAsByHand(mapped, byHand, 1);
  // And the map matters: the factors alone draw something else.
  EXPECT_GT(maxDifference(renderScene(mapped), renderScene(quadScene(LightingModel::CookTorrance))), 20);
}

TEST(MaterialMaps, EmissiveTexelScalesTheEmission) {
  for (LightingModel model : {LightingModel::CookTorrance, LightingModel::BlinnPhong}) {
    Scene mapped = quadScene(model);
    mapped.objects[0].material.emission = {0.4f, 1, 1, 1};
    mapped.objects[0].maps.emissive = oneTexel(255, 51, 0);
    Scene byHand = quadScene(model);
    byHand.objects[0].material.emission = {0.4f, 0.2f, 0, 1};
    expectSameAsByHand(mapped, byHand, 1);
  }
}

// A texel tilted by 25° towards +u lights the quad as a quad whose normals are tilted so: towards
// +x with u along +x, towards −x with u mirrored; and not at all under Gouraud shading.
TEST(MaterialMaps, NormalMapTiltsTheNormalInTheTangentFrame) {
  const Real angle = glm::radians(Real(25));
  const int r = int(std::lround((std::sin(angle) * 0.5 + 0.5) * 255)), b = int(std::lround((std::cos(angle) * 0.5 + 0.5) * 255));
  const Vec3 stored(2 * Real(r) / 255 - 1, 2 * Real(128) / 255 - 1, 2 * Real(b) / 255 - 1);  // as decoded
  for (LightingModel model : {LightingModel::BlinnPhong, LightingModel::CookTorrance})
    for (bool mirrored : {false, true}) {
      Scene mapped = quadScene(model);
      mapped.objects[0].mesh = quad(mirrored);
      mapped.objects[0].maps.normal = oneTexel(r, 128, b);
      Scene byHand = quadScene(model);
      auto tilted = std::make_shared<Mesh>(*quad(mirrored));
      const Vec3 n = glm::normalize(Vec3(mirrored ? -stored.x : stored.x, stored.y, stored.z));
      tilted->normals.assign(4, n);
      byHand.objects[0].mesh = tilted;
      SCOPED_TRACE(std::string(toString(model)) + (mirrored ? " mirrored" : ""));
      expectSameAsByHand(mapped, byHand, 1);
      EXPECT_GT(maxDifference(renderScene(mapped), renderScene(quadScene(model))), 5);
      // Per-vertex shading has no texels to read.
      mapped.shading = Shading::Gouraud;
      Scene plain = quadScene(model);
      plain.objects[0].mesh = quad(mirrored);
      plain.shading = Shading::Gouraud;
      EXPECT_EQ(renderScene(mapped).rgba, renderScene(plain).rgba);
    }
}

// The normal map's scale from glTF multiplies X and Y: scale 0 leaves the normal as it was.
TEST(MaterialMaps, NormalScaleZeroIsNoMap) {
  Scene mapped = quadScene(LightingModel::BlinnPhong);
  mapped.objects[0].maps.normal = oneTexel(200, 60, 220);
  mapped.objects[0].maps.normalScale = 0;
  expectSameAsByHand(mapped, quadScene(LightingModel::BlinnPhong), 1);
}

// The path tracer: an emitter seen directly shows emission × texel, and it lights a white
// Lambertian floor as an emitter of that radiance does.
TEST(MaterialMaps, PathTracedEmissiveMapIsTheEmittersRadiance) {
  Scene s;
  s.renderer = RendererKind::Path;
  s.width = s.height = 24;
  s.rayTracing.samples = 64;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 1.5f;
  s.lights.clear();
  Object emitter;
  emitter.mesh = quad();
  emitter.material.diffuse = {0, 0, 0, 1};
  emitter.material.emission = {1, 0.5f, 1, 1};
  emitter.maps.emissive = oneTexel(255, 255, 51);
  s.objects.push_back(emitter);
  const Image seen = renderScene(s);
  EXPECT_NEAR(seen.pixel(12, 12)[0], 255, 1);
  EXPECT_NEAR(seen.pixel(12, 12)[1], 128, 1);
  EXPECT_NEAR(seen.pixel(12, 12)[2], 51, 1);

  // Next-event estimation samples the map: a floor under a mapped emitter equals the floor under
  // an emitter of the texel's radiance (grey, so that no channel clamps).
  s.camera.eye = {0, 5, 0};
  s.camera.up = {0, 0, -1};
  s.camera.viewHeight = 6;
  s.objects[0].worldFromObject = glm::translate(Mat4(1), Vec3(0, 1, 0)) * glm::rotate(Mat4(1), glm::radians(Real(90)), Vec3(1, 0, 0));
  s.objects[0].material.emission = {1, 1, 1, 1};
  s.objects[0].maps.emissive = oneTexel(128, 128, 128);
  Object floor;
  floor.mesh = quad();
  floor.worldFromObject = glm::scale(glm::rotate(Mat4(1), glm::radians(Real(-90)), Vec3(1, 0, 0)), Vec3(3));
  floor.material.diffuse = {1, 1, 1, 1};
  s.objects.push_back(floor);
  Scene byHand = s;
  byHand.objects[0].maps.emissive = nullptr;
  byHand.objects[0].material.emission = {Real(128) / 255, Real(128) / 255, Real(128) / 255, 1};
  const Image mapped = renderScene(s), expected = renderScene(byHand);
  double sumMapped = 0, sumExpected = 0;
  for (std::size_t i = 0; i < mapped.rgba.size(); i += 4) sumMapped += mapped.rgba[i], sumExpected += expected.rgba[i];
  EXPECT_GT(sumExpected, 0);
  EXPECT_NEAR(sumMapped / sumExpected, 1, 0.03);
}

}  // namespace
}  // namespace illum
