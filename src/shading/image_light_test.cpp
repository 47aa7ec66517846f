// Image-based lighting against closed forms: a uniform environment's irradiance is π·L; a sky
// bright above the horizon gives E/π = 1 facing up, ½ facing sideways and 0 facing down (exact in
// nine harmonics); the mirror level is the map; the split sum's table keeps energy.
#include "shading/image_light.h"

#include <illum/lighting.h>

#include <gtest/gtest.h>

#include <limits>

namespace illum {
namespace {

EnvironmentMap mapOf(int width, int height, Vec3 (*radiance)(const Vec3&)) {
  std::vector<Vec3> texels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      texels.push_back(radiance(latLongDirection(Real(x) + Real(0.5), Real(y) + Real(0.5), width, height)));
  return EnvironmentMap(width, height, texels);
}

Vec3 uniformHalf(const Vec3&) { return Vec3(0.5f); }
Vec3 skyAbove(const Vec3& d) { return d.y > 0 ? Vec3(1) : Vec3(0); }
Vec3 stripes(const Vec3& d) { return Vec3(d.x > 0.3f ? 2.0f : 0.1f, d.y * d.y, d.z < 0 ? 1.0f : 0.0f); }

const Vec3 kDirections[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, {0.6f, 0.48f, 0.64f}, {-0.36f, -0.48f, 0.8f}};

TEST(ImageLight, AUniformEnvironmentIsItsRadianceInEveryDirectionAndRoughness) {
  const ImageLight light(mapOf(128, 64, uniformHalf));
  for (const Vec3& n : kDirections) {
    const Vec3 e = light.irradianceOverPi(n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], 0.5f, 2e-3f) << n.x << "," << n.y << "," << n.z;
    for (Real roughness : {0.0f, 0.3f, 0.5f, 0.9f, 1.0f}) EXPECT_NEAR(light.prefiltered(n, roughness).x, 0.5f, 1e-4f);
  }
}

TEST(ImageLight, ASkyAboveTheHorizonGivesLambertsClosedForm) {
  // E(n) = ∫ over the sky of cos: π(1 + n·up)/2 for a unit sky, which nine harmonics hold exactly.
  const ImageLight light(mapOf(256, 128, skyAbove));
  for (const Vec3& n : kDirections) {
    const Real expected = (1 + n.y) / 2;
    EXPECT_NEAR(light.irradianceOverPi(glm::normalize(n)).x, expected, 0.01f) << n.x << "," << n.y << "," << n.z;
  }
}

TEST(ImageLight, TheMirrorLevelIsTheMap) {
  // Away from the stripes' edges the octahedral level holds the map's own radiance.
  const EnvironmentMap map = mapOf(200, 100, [](const Vec3& d) { return Vec3(d.x > 0 ? 2.0f : 0.1f, 0.5f, d.z < 0 ? 1.0f : 0.0f); });
  const ImageLight light(map);
  for (const Vec3& d : {Vec3(0.8f, 0.6f, -0.1f), Vec3(-0.7f, 0.1f, 0.7f), Vec3(0.5f, -0.5f, -0.7f), Vec3(-0.3f, -0.9f, 0.3f)}) {
    const Vec3 r = glm::normalize(d), expected = map.radiance(r), got = light.prefiltered(r, 0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-4f) << r.x << "," << r.y << "," << r.z;
  }
}

TEST(ImageLight, RougherLevelsSpreadABrightSpotWithoutLosingIt) {
  // A small bright cap: the rougher the lobe, the lower its peak and the wider its reach, while
  // the mean over the sphere stays about the map's.
  const EnvironmentMap map = mapOf(256, 128, [](const Vec3& d) { return d.y > 0.97f ? Vec3(20) : Vec3(0); });
  const ImageLight light(map);
  const Vec3 up(0, 1, 0), side = glm::normalize(Vec3(1, 1.2f, 0));
  Real previousPeak = 1e9f;
  for (Real roughness : {0.2f, 0.4f, 0.6f, 0.8f, 1.0f}) {
    const Real peak = light.prefiltered(up, roughness).x;
    EXPECT_LT(peak, previousPeak) << roughness;
    previousPeak = peak;
  }
  EXPECT_GT(light.prefiltered(side, 1).x, light.prefiltered(side, 0.2f).x);
  EXPECT_EQ(light.prefiltered(-up, 0.2f).x, 0);
}

// A degenerate direction (zero, NaN) or roughness reads inside the tables (the sanitizer run checks
// the reads) and gives no light from nowhere.
TEST(ImageLight, DegenerateQueriesStayInsideTheTables) {
  const ImageLight light(mapOf(64, 32, stripes));
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  for (const Vec3& d : {Vec3(0), Vec3(nan), Vec3(inf, 0, 0), Vec3(-inf, nan, 1)})
    for (Real roughness : {Real(0), Real(0.5), nan, inf, -inf}) {
      (void)light.prefiltered(d, roughness);
      (void)light.irradianceOverPi(d);
    }
  for (Real x : {nan, inf, -inf, Real(-1), Real(2)}) {
    (void)splitSumDfg(x, 0.5f);
    (void)splitSumDfg(0.5f, x);
  }
  EXPECT_EQ(light.prefiltered(Vec3(0), 0.5f), light.prefiltered(Vec3(0), 0.5f));
}

TEST(SplitSum, ASmoothSurfaceReflectsAllItsFresnelAndRougherOnesKeepEnergy) {
  const Vec2 mirror = splitSumDfg(1, 0);
  EXPECT_NEAR(mirror.x + mirror.y, 1, 0.02f);  // f0 = 1: all of it
  EXPECT_NEAR(mirror.y, 0, 0.01f);             // head-on Schlick adds nothing to f0
  for (Real NoV : {0.05f, 0.3f, 0.7f, 1.0f})
    for (Real roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
      const Vec2 dfg = splitSumDfg(NoV, roughness);
      EXPECT_GE(dfg.x, 0);
      EXPECT_GE(dfg.y, 0);
      EXPECT_LE(dfg.x + dfg.y, 1.001f) << NoV << " " << roughness;
    }
  // Grazing angles reflect more of the Fresnel term's white; rough surfaces lose some of it.
  EXPECT_GT(splitSumDfg(0.1f, 0.1f).y, splitSumDfg(1, 0.1f).y);
  EXPECT_LT(splitSumDfg(1, 1).x + splitSumDfg(1, 1).y, 0.9f);
}

TEST(ImageLight, IsComputedOncePerMapContent) {
  const EnvironmentMap a = mapOf(64, 32, stripes), b = mapOf(64, 32, stripes), c = mapOf(64, 32, skyAbove);
  EXPECT_EQ(ImageLight::of(a), ImageLight::of(b));
  EXPECT_NE(ImageLight::of(a), ImageLight::of(c));
}

TEST(EyeImageLight, TurnsEyeDirectionsIntoTheMapsAndScalesInTheEquation) {
  auto eye = std::make_shared<EyeImageLight>();
  eye->light = ImageLight::of(mapOf(256, 128, skyAbove));
  eye->mapFromEye = Mat3(1, 0, 0, 0, 0, -1, 0, 1, 0);  // eye +z is the map's up (+Y)
  eye->scale = {2, 1, 0.5f};
  LightModel lm;
  lm.ambient = Color3(0.3f);  // what the environment replaces
  lm.environment = eye;
  Material white;
  white.ambient = {1, 1, 1, 1};
  const SurfaceGeometry facingSky{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}}, facingFloor{{0, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  const Vec3 e = evaluateTerms({}, lm, white, LightingModel::BlinnPhong, facingSky).ambient;
  EXPECT_NEAR(e.x, 2, 0.02f);
  EXPECT_NEAR(e.y, 1, 0.01f);
  EXPECT_NEAR(e.z, 0.5f, 0.01f);
  EXPECT_NEAR(evaluateTerms({}, lm, white, LightingModel::BlinnPhong, facingFloor).ambient.x, 0, 0.02f);
  // Wylie's model has no ambient light; physically_based leaves GL's ambient alone.
  EXPECT_EQ(evaluateTerms({}, lm, white, LightingModel::Wylie, facingSky).ambient, Vec3(0));
  eye->lightsClassic = false;
  EXPECT_EQ(evaluateTerms({}, lm, white, LightingModel::BlinnPhong, facingSky).ambient, Vec3(0.3f));
  // A mirror (metallic, f0 = its white base, roughness 0) facing the viewer along eye +z reflects
  // the sky straight back, and nothing diffusely.
  Material mirror;
  PhysicalMaterial p;
  p.baseColor = {1, 1, 1};
  p.metallic = 1;
  p.roughness = 0;
  glFromPhysical(mirror, p);
  const LightingTerms t = evaluateTerms({}, lm, mirror, LightingModel::CookTorrance, facingSky);
  EXPECT_NEAR(t.specular.x, 2, 0.05f);
  EXPECT_NEAR(t.specular.z, 0.5f, 0.02f);
  EXPECT_EQ(t.ambient, Vec3(0));
}

}  // namespace
}  // namespace illum
