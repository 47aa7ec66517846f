// The SIMD equation against the one-lane equation, and every SIMD target against every other:
// the same bits, for every model, light kind and option. And the lanes' power function against
// std::pow.
#include "shading/image_light.h"
#include "shading/shade_points.h"

#include <illum/lighting.h>

#include "math/unorm8.h"  // packUnorm8, the framebuffer's conversion
#include "shading/brdf.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace illum {
namespace {

struct Batch {
  std::vector<Real> v[10];  // position xyz, normal xyz, colour rgba
  SurfacePoints points() const {
    SurfacePoints p;
    p.count = v[0].size();
    for (int c = 0; c < 3; ++c) p.position[c] = v[c].data(), p.normal[c] = v[3 + c].data();
    if (!v[6].empty())
      for (int c = 0; c < 4; ++c) p.color[c] = v[6 + c].data();
    return p;
  }
};

// Points scattered in front of the eye with random unit normals, some facing away from the lights.
Batch randomPoints(std::size_t n, bool colors, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1);
  Batch b;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p(3 * u(rng), 3 * u(rng), -4 + 3 * u(rng));
    Vec3 nrm(u(rng), u(rng), u(rng));
    nrm = glm::length(nrm) > Real(1e-3) ? glm::normalize(nrm) : Vec3(0, 0, 1);
    for (int c = 0; c < 3; ++c) b.v[c].push_back(p[c]), b.v[3 + c].push_back(nrm[c]);
    if (colors)
      for (int c = 0; c < 4; ++c) b.v[6 + c].push_back((u(rng) + 1) / 2);
  }
  return b;
}

std::vector<EyeLight> lightsOfKind(int kind) {
  EyeLight l;
  l.diffuse = {0.9f, 0.7f, 0.5f};
  l.specular = {1, 0.9f, 0.8f};
  l.ambient = {0.05f, 0.04f, 0.03f};
  switch (kind) {
    case 0: l.position = {0.3f, 0.8f, 0.5f, 0}; break;                              // directional
    case 1: l.position = {1, 2, -1, 1}, l.attenuation = {1, 0.1f, 0.02f}; break;    // positional, attenuated
    case 2:                                                                         // spot
      l.position = {0, 0, 0, 1}, l.spotDirection = glm::normalize(Vec3(0, 0, -1));
      l.spotCutoff = 30, l.spotCosCutoff = std::cos(glm::radians(Real(30))), l.spotExponent = 8;
      break;
    default: {  // eight of every kind
      std::vector<EyeLight> all;
      for (int k = 0; k < 8; ++k) {
        EyeLight m = l;
        m.position = {Real(k) - 4, Real(k % 3), Real(-k), Real(k % 2)};
        all.push_back(m);
      }
      return all;
    }
  }
  return {l};
}

std::vector<Real> shadeAll(const ShadeSetup& setup, const Batch& b) {
  const std::size_t n = b.v[0].size();
  std::vector<Real> out(4 * n);
  Real* const dst[4] = {out.data(), out.data() + n, out.data() + 2 * n, out.data() + 3 * n};
  shadePoints(setup, b.points(), dst);
  return out;
}

bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof(Real)) == 0; }

// How the equation is asked for: GL's with an infinite or a local viewer, or a lecture note's way.
// With `environment`, an image-based light (a sky of two bright spots over a dark floor, turned).
struct Viewing {
  bool localViewer;
  Convention convention;
  bool environment = false;
};
constexpr Viewing kViewings[] = {{false, Convention::GL},
                                 {true, Convention::GL},
                                 {false, Convention::NoteShader},
                                 {false, Convention::NoteHalfSum},
                                 {false, Convention::NoteWorldSpace},
                                 {true, Convention::GL, true}};

std::shared_ptr<const EyeImageLight> testImageLight() {
  std::vector<Vec3> texels;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x)
      texels.push_back(y < 16 ? Vec3(Real(0.2) + Real(x % 7 == 0) * 3, Real(0.4), Real(y == 5) * 5) : Vec3(Real(0.05)));
  auto eye = std::make_shared<EyeImageLight>();
  eye->light = ImageLight::of(EnvironmentMap(64, 32, texels));
  eye->mapFromEye = Mat3(0.6f, 0, 0.8f, 0, 1, 0, -0.8f, 0, 0.6f);
  eye->scale = {1.5f, 1, 0.7f};
  return eye;
}

class EveryModelAndLight : public testing::TestWithParam<std::tuple<LightingModel, int, bool, int>> {};

TEST_P(EveryModelAndLight, SimdEqualsOneLaneBitForBit) {
  const auto [model, kind, colors, viewing] = GetParam();
  std::mt19937 rng(1234 + kind);
  const std::vector<EyeLight> lights = lightsOfKind(kind);
  ShadeSetup setup{lights, {}, model, {}};
  setup.lightModel.localViewer = kViewings[viewing].localViewer;
  setup.lightModel.convention = kViewings[viewing].convention;
  if (kViewings[viewing].environment) setup.lightModel.environment = testImageLight();
  setup.material.specular = {0.8f, 0.8f, 0.8f, 1};
  setup.material.emission = {0.01f, 0.02f, 0.03f, 1};
  setup.material.shininess = 37;
  if (model == LightingModel::CookTorrance && kind % 2 == 1) {
    // A physically based material (metal, Beckmann) on odd kinds; a GL one seen through physicalOf on even.
    PhysicalMaterial p;
    p.baseColor = {0.9f, 0.6f, 0.3f};
    p.metallic = 0.7f;
    p.roughness = 0.35f;
    p.distribution = Microfacet::Beckmann;
    glFromPhysical(setup.material, p);
  }
  const std::size_t n = 203;  // not a multiple of any lane count: the tail is tested too
  const Batch b = randomPoints(n, colors, rng);
  const std::vector<Real> simd = shadeAll(setup, b);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p(b.v[0][i], b.v[1][i], b.v[2][i]), nrm(b.v[3][i], b.v[4][i], b.v[5][i]);
    Material m = setup.material;
    if (colors) m = withVertexColor(m, {b.v[6][i], b.v[7][i], b.v[8][i], b.v[9][i]});
    const SurfaceGeometry s{p, nrm, viewerDirection(p, setup.lightModel)};
    const Color4 one = clampedColor(evaluateTerms(lights, setup.lightModel, m, model, s), m);
    for (int c = 0; c < 4; ++c)
      ASSERT_TRUE(sameBits(simd[c * n + i], one[c])) << "point " << i << " channel " << c << ": " << simd[c * n + i]
                                                     << " vs " << one[c];
  }
}

INSTANTIATE_TEST_SUITE_P(Shading, EveryModelAndLight,
                         testing::Combine(testing::ValuesIn(kLightingModels),
                                          testing::Values(0, 1, 2, 3), testing::Bool(),
                                          testing::Range(0, int(std::size(kViewings)))));

TEST(ShadePoints, EverySimdTargetGivesTheSameBits) {
  std::mt19937 rng(99);
  const std::vector<EyeLight> lights = lightsOfKind(3);
  ShadeSetup setup{lights, {}, LightingModel::BlinnPhong, {}};
  setup.material.specular = {1, 1, 1, 1};
  setup.material.shininess = 90;
  const Batch b = randomPoints(1000, true, rng);
  ShadeSetup physical = setup;
  physical.model = LightingModel::CookTorrance;
  PhysicalMaterial p;
  p.metallic = 0.4f;
  p.roughness = 0.3f;
  glFromPhysical(physical.material, p);
  physical.lightModel.environment = testImageLight();
  ShadeSetup beckmann = physical;
  p.distribution = Microfacet::Beckmann;
  glFromPhysical(beckmann.material, p);
  // glTF's metallic-roughness map: a roughness of its own at each point, so that the lanes of a
  // vector read the environment's prefiltered levels and the split sum's rows apart.
  std::uniform_real_distribution<Real> unit(0, 1);
  std::vector<Real> metallic(b.v[0].size()), roughness(b.v[0].size());
  for (std::size_t i = 0; i < metallic.size(); ++i) metallic[i] = unit(rng), roughness[i] = unit(rng);
  SurfacePoints mappedPoints = b.points();
  mappedPoints.metallic = metallic.data(), mappedPoints.roughness = roughness.data();
  const auto shadeMapped = [&] {
    const std::size_t n = b.v[0].size();
    std::vector<Real> out(4 * n);
    Real* const dst[4] = {out.data(), out.data() + n, out.data() + 2 * n, out.data() + 3 * n};
    shadePoints(physical, mappedPoints, dst);
    return out;
  };
  const std::vector<Real> reference = shadeAll(setup, b), physicalReference = shadeAll(physical, b),
                          beckmannReference = shadeAll(beckmann, b), mappedReference = shadeMapped();
  EXPECT_NE(mappedReference, physicalReference);
  int tried = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    EXPECT_STREQ(simdTargetName(), hwy::TargetName(target));
    ++tried;
    for (const auto& [s, expected] : {std::pair{&setup, &reference}, std::pair{&physical, &physicalReference},
                                      std::pair{&beckmann, &beckmannReference}}) {
      const std::vector<Real> out = shadeAll(*s, b);
      for (std::size_t i = 0; i < out.size(); ++i)
        ASSERT_TRUE(sameBits(out[i], (*expected)[i])) << hwy::TargetName(target) << " differs at " << i;
    }
    const std::vector<Real> mapped = shadeMapped();
    for (std::size_t i = 0; i < mapped.size(); ++i)
      ASSERT_TRUE(sameBits(mapped[i], mappedReference[i])) << hwy::TargetName(target) << " (mapped) differs at " << i;
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(tried, 2);  // at least the SIMD target and the portable one
}

#if !ILLUM_USE_DOUBLE
// Each owned point lit with its owner's setup, as shadePoints lights it, whatever the vector's
// other lanes hold: whole vectors of one owner, vectors split between owners or partly empty
// (gathered owner by owner before they are lit), owners alternating lane by lane, one owner's
// lanes with holes in every vector, and an owner with colours of its own; two cook-torrance
// owners, a GL material and a physically based one, whose physical description each vector
// must take from its own owner. On every SIMD target.
TEST(ShadeOwnedPoints, LightsEachPointWithItsOwnersSetupWhateverItsVectorHolds) {
  std::mt19937 rng(7);
  const std::size_t n = 1024;
  const Batch b = randomPoints(n, true, rng);
  const std::vector<EyeLight> lights = lightsOfKind(3);
  std::vector<ShadeSetup> setups(3, ShadeSetup{lights, {}, LightingModel::BlinnPhong, {}});
  setups[1].material.shininess = 12;
  setups[1].material.diffuse = {0.2f, 0.9f, 0.4f, 0.5f};
  setups[2].model = LightingModel::Phong;
  setups[2].material.specular = {1, 1, 1, 1};
  setups[2].material.shininess = 61;
  setups.push_back(setups[1]);
  setups[3].model = LightingModel::CookTorrance;  // the GL material seen through physicalOf
  setups.push_back(setups[3]);
  PhysicalMaterial metal;
  metal.baseColor = {0.9f, 0.6f, 0.2f};
  metal.metallic = 1;
  metal.roughness = 0.3f;
  glFromPhysical(setups[4].material, metal);
  const std::vector<std::uint8_t> colored = {0, 1, 0, 0, 0};
  std::vector<std::uint32_t> owner(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t block = i / 64;  // runs of 64: longer than any vector
    owner[i] = block % 6 == 0   ? 0
               : block % 6 == 1 ? (i % 3 == 0 ? kNoOwner : std::uint32_t(i % 2 + 1))  // mixed, lane by lane
               : block % 6 == 2 ? (i % 64 < 21 ? 2 : i % 64 < 40 ? kNoOwner : 1)      // split runs
               : block % 6 == 3 ? std::uint32_t(rng() % 4 == 0 ? kNoOwner : rng() % 5)
               // One owner with holes: its lanes gathered across vectors, more than one vector's worth.
               : block % 6 == 4 ? (i % 5 == 0 ? kNoOwner : 1)
                                : (i % 7 == 3 ? kNoOwner : 2);
  }
  // What each owner's setup gives every point.
  std::vector<std::vector<Real>> expected;
  for (std::size_t o = 0; o < setups.size(); ++o) {
    Batch own = b;
    if (!colored[o])
      for (int c = 6; c < 10; ++c) own.v[c].clear();
    expected.push_back(shadeAll(setups[o], own));
  }
  constexpr std::uint32_t kUntouched = 0x12345678;
  int tried = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++tried;
    std::vector<std::uint32_t> rgba(n, kUntouched);
    shadeOwnedPoints(setups, colored, b.points(), owner.data(), rgba.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (owner[i] == kNoOwner) {
        ASSERT_EQ(rgba[i], kUntouched) << "point " << i;
        continue;
      }
      const std::vector<Real>& e = expected[owner[i]];
      const Color4 c(e[i], e[n + i], e[2 * n + i], e[3 * n + i]);
      ASSERT_EQ(rgba[i], packUnorm8(c)) << hwy::TargetName(target) << ", point " << i << " of owner " << owner[i];
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(tried, 2);
}
#endif

TEST(PowLobe, FollowsStdPowClosely) {
  for (const Real n : {Real(0.5), Real(1), Real(5), Real(25), Real(128), Real(1000), Real(2.5), Real(77.7), Real(5000)}) {
    for (Real x = Real(1e-4); x < 1; x *= Real(1.07)) {
      const double expected = std::pow(double(x), double(n));
      const double got = Fs_BlinnPhong(x, n);
      // Float lanes: whole exponents by binary powering (below n·2^-23 relative), others by
      // log2/exp2 (about 1e-7 relative per unit of |n·log2 x|).
      const double relative = n == std::floor(n) ? n * 0x1p-23 : 2e-7 * std::max(1.0, std::abs(n * std::log2(double(x))));
      const double tolerance = relative * expected + 1e-38;
      ASSERT_NEAR(got, expected, tolerance) << x << "^" << n;
    }
  }
  EXPECT_EQ(Fs_Phong(1, 77), 1);
  EXPECT_EQ(Fs_Phong(0, 3), 0);
  EXPECT_EQ(Fs_Phong(Real(-0.2), 3), 0);
  EXPECT_EQ(Fs_Phong(Real(0.5), 1), Real(0.5));
  EXPECT_EQ(Fs_Phong(Real(0.25), Real(0.5)), Real(0.5));
  EXPECT_GT(Fs_Phong(Real(1e-39), Real(0.5)), Real(3e-20));  // a denormal base
  if constexpr (sizeof(Real) == 4) {
    EXPECT_EQ(Fs_Phong(Real(1e-3), 40), 0);  // below the smallest float
  }
}

}  // namespace
}  // namespace illum
