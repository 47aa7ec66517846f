// An environment as every renderer uses it: image-based light in the rasterizer (each shading
// frequency, the reference pipeline equal to the fast one) and the Whitted tracer, the map turned
// by its rotation, and shown behind the scene where asked.
#include "render/reference_render.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

std::shared_ptr<const EnvironmentMapFile> mapFile(Vec3 (*radiance)(const Vec3&)) {
  constexpr int kWidth = 128, kHeight = 64;
  constexpr Real kPi = Real(3.14159265358979323846);
  std::vector<Vec3> texels;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Real phi = ((Real(x) + Real(0.5)) / kWidth - Real(0.5)) * 2 * kPi, theta = (Real(y) + Real(0.5)) / kHeight * kPi;
      texels.push_back(radiance({std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)}));
    }
  return EnvironmentMapFile::of(std::make_shared<const EnvironmentMap>(kWidth, kHeight, texels));
}

Vec3 skyAbove(const Vec3& d) { return d.y > 0 ? Vec3(1) : Vec3(0); }
Vec3 brightEast(const Vec3& d) { return d.x > 0 ? Vec3(1) : Vec3(0); }
Vec3 brightFront(const Vec3& d) { return d.z > 0 ? Vec3(1) : Vec3(0.2f); }

// A unit sphere seen along −z, ambient-white and otherwise black (GL), with no lights: what it shows
// is the environment's irradiance E/π, in place of the global ambient.
Scene ambientSphere(Shading shading) {
  Scene s;
  s.width = s.height = 41;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2.2f;
  s.lights.clear();
  s.shading = shading;
  s.background = {0.1f, 0.2f, 0.3f, 1};
  Object o;
  o.mesh = std::make_shared<const Mesh>(makeSphere(1, 64, 32));
  o.material.ambient = {1, 1, 1, 1};
  o.material.diffuse = {0, 0, 0, 1};
  o.material.specular = {0, 0, 0, 1};
  s.objects.push_back(o);
  s.environment.lighting = EnvironmentLighting::All;
  s.rayTracing.environment = Color3(1);
  return s;
}

int red(const Image& image, int x, int y) { return image.pixel(x, y)[0]; }

TEST(EnvironmentLighting, AUniformEnvironmentIsTheAmbientItStandsFor) {
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
    Scene s = ambientSphere(shading);
    s.rayTracing.environment = Color3(0.6f);  // no map: a uniform environment of this radiance
    const Image image = renderScene(s);
    EXPECT_EQ(red(image, 20, 20), 153) << toString(shading);
    EXPECT_EQ(red(image, 20, 5), 153) << toString(shading);
    EXPECT_EQ(red(image, 0, 0), std::lround(0.1 * 255)) << "the background stays the scene's";
    s.environment.lighting = EnvironmentLighting::None;
    s.lightModel.ambient = Color3(0.6f);
    EXPECT_EQ(renderScene(s).rgba, image.rgba) << "the same as GL's global ambient of 0.6";
  }
}

TEST(EnvironmentLighting, ASkyAboveLightsTheTopOfASphereAndNotItsBottom) {
  Scene s = ambientSphere(Shading::Phong);
  s.rayTracing.environmentMap = mapFile(skyAbove);
  const Image image = renderScene(s);
  EXPECT_NEAR(red(image, 20, 20), 128, 3);  // facing the viewer, sideways to the sky: E/π = ½
  EXPECT_NEAR(red(image, 20, 2), 249, 6);   // near the top (n·up ≈ 0.95)
  EXPECT_NEAR(red(image, 20, 38), 6, 6);    // near the bottom
  EXPECT_EQ(renderSceneReference(s).rgba, image.rgba) << "the reference pipeline is the oracle";
}

TEST(EnvironmentLighting, TheRotationTurnsTheMapAboutUp) {
  Scene s = ambientSphere(Shading::Phong);
  s.rayTracing.environmentMap = mapFile(brightEast);
  const Image east = renderScene(s);
  EXPECT_GT(red(east, 38, 20), 240);  // the right of the picture faces +x
  EXPECT_LT(red(east, 2, 20), 15);
  s.environment.rotation = 180;
  const Image turned = renderScene(s);
  EXPECT_LT(red(turned, 38, 20), 15);
  EXPECT_GT(red(turned, 2, 20), 240);
  s.environment.rotation = 90;  // +x turned to −z, away from the viewer: the front sees none of it
  const Image away = renderScene(s);
  EXPECT_LT(red(away, 20, 20), 10);
  EXPECT_NEAR(red(away, 38, 20), red(away, 2, 20), 1);  // and both sides the same half
}

TEST(EnvironmentLighting, PhysicallyBasedMetalsReflectTheMapAndClassicMaterialsCanKeepTheirAmbient) {
  Scene s = ambientSphere(Shading::Phong);
  s.rayTracing.environmentMap = mapFile(brightFront);
  s.multisample = 4;
  Object metal = s.objects[0];
  PhysicalMaterial p;
  p.baseColor = {1, 1, 1};
  p.metallic = 1;
  p.roughness = 0;
  glFromPhysical(metal.material, p);
  metal.material.model = LightingModel::CookTorrance;
  s.objects = {metal};
  const Image mirror = renderScene(s);
  // At the centre a mirror reflects straight back towards +z (radiance 1): F ≈ f0 = 1.
  EXPECT_GE(red(mirror, 20, 20), 245);
  EXPECT_EQ(renderSceneReference(s).rgba, mirror.rgba);
  // "physically_based" leaves classic materials with GL's global ambient.
  Scene classic = ambientSphere(Shading::Phong);
  classic.rayTracing.environmentMap = s.rayTracing.environmentMap;
  classic.environment.lighting = EnvironmentLighting::PhysicallyBased;
  classic.lightModel.ambient = Color3(0.2f);
  EXPECT_EQ(red(renderScene(classic), 20, 20), 51);
}

TEST(EnvironmentBackground, TheMapIsShownBehindTheSceneAndTheSceneIsUnchanged) {
  Scene s = ambientSphere(Shading::Phong);
  s.rayTracing.environmentMap = mapFile(skyAbove);
  const Image plain = renderScene(s);
  s.environment.background = EnvironmentBackground::Sharp;
  s.camera.projection = Projection::Perspective;
  s.camera.fovy = 60;
  const Image plainPerspective = [&] {
    Scene q = s;
    q.environment.background = EnvironmentBackground::None;
    return renderScene(q);
  }();
  const Image shown = renderScene(s);
  EXPECT_EQ(shown.pixel(0, 0)[0], 255);  // looking up into the sky
  EXPECT_EQ(shown.pixel(0, 40)[0], 0);   // and down under the horizon
  EXPECT_EQ(shown.pixel(0, 0)[3], 255);
  for (std::size_t i = 0; i < shown.rgba.size(); i += 4) {
    if (plainPerspective.rgba[i + 0] != 26 || plainPerspective.rgba[i + 2] != 77) {  // not the background colour
      EXPECT_EQ(shown.rgba[i], plainPerspective.rgba[i]) << "pixel " << i / 4;
    }
  }
  // --no-background: the light stays, no picture behind, transparent.
  s.background.a = 0;
  const Image transparent = renderScene(s);
  EXPECT_EQ(transparent.pixel(0, 0)[3], 0);
  (void)plain;
}

TEST(EnvironmentLighting, WhittedsMirrorRaysSeeTheEnvironment) {
  Scene s = ambientSphere(Shading::Phong);
  s.renderer = RendererKind::Whitted;
  s.rayTracing.environmentMap = mapFile(brightFront);
  s.objects[0].material.ambient = {0, 0, 0, 1};
  s.objects[0].optics.reflective = Color3(1);
  const Image image = renderScene(s);
  EXPECT_EQ(red(image, 20, 20), 255);  // the mirror sends the centre's ray back to +z: radiance 1
  EXPECT_EQ(red(image, 0, 0), std::lround(0.1 * 255));  // the primary ray that misses: the background
  s.environment.lighting = EnvironmentLighting::None;
  EXPECT_EQ(red(renderScene(s), 20, 20), std::lround(0.1 * 255)) << "without it, the mirror shows the background";
}

}  // namespace
}  // namespace illum
