// glTF's maps applied to a point: the tangent frame of a triangle and the normal it gives a
// tangent-space texel, against closed forms.
#include "shading/material_maps.h"

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

constexpr Real kEps = 1e-5f;

void expectNear(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(a.x, b.x, kEps);
  EXPECT_NEAR(a.y, b.y, kEps);
  EXPECT_NEAR(a.z, b.z, kEps);
}

// The RGB a normal map stores for a unit tangent-space normal.
Vec4 encode(const Vec3& n) { return {n.x * 0.5f + 0.5f, n.y * 0.5f + 0.5f, n.z * 0.5f + 0.5f, 1}; }

TEST(TangentFrame, IsTheDerivativeOfPositionByUv) {
  // P = (2u, 3v, u + v): ∂P/∂u = (2, 0, 1), ∂P/∂v = (0, 3, 1), whatever three points are taken.
  const auto P = [](Vec2 uv) { return Vec3(2 * uv.x, 3 * uv.y, uv.x + uv.y); };
  const std::array<Vec2, 3> uv = {Vec2(0.1f, 0.2f), Vec2(0.7f, 0.3f), Vec2(0.4f, 0.9f)};
  const TangentFrame f = triangleTangents({P(uv[0]), P(uv[1]), P(uv[2])}, uv);
  expectNear(f.dPdu, {2, 0, 1});
  expectNear(f.dPdv, {0, 3, 1});
}

TEST(TangentFrame, DegenerateUvsGiveNoFrameAndLeaveTheNormal) {
  const TangentFrame f = triangleTangents({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {Vec2(0), Vec2(0.5f), Vec2(1)});
  EXPECT_EQ(f.dPdu, Vec3(0));
  EXPECT_EQ(normalFromMap({0, 0, 1}, f, encode(glm::normalize(Vec3(1, 1, 1))), 1), Vec3(0, 0, 1));
}

TEST(NormalMap, TheFlatTexelKeepsTheNormal) {
  const TangentFrame f{{1, 0, 0}, {0, 1, 0}};
  expectNear(normalFromMap({0, 0, 1}, f, {0.5f, 0.5f, 1, 1}, 1), {0, 0, 1});
}

TEST(NormalMap, TiltsTowardsTheTangentAndTheBitangent) {
  // A quad in the xy plane with u along +x and v along +y: tangent space is the object's.
  const TangentFrame f{{2, 0, 0}, {0, 5, 0}};
  const Real s = std::sin(Real(0.5)), c = std::cos(Real(0.5));
  expectNear(normalFromMap({0, 0, 1}, f, encode({s, 0, c}), 1), {s, 0, c});
  expectNear(normalFromMap({0, 0, 1}, f, encode({0, s, c}), 1), {0, s, c});
  // Mirrored uvs (u running along −x) mirror the map's X: the bitangent keeps to ∂P/∂v's side.
  const TangentFrame mirrored{{-1, 0, 0}, {0, 1, 0}};
  expectNear(normalFromMap({0, 0, 1}, mirrored, encode({s, 0, c}), 1), {-s, 0, c});
  expectNear(normalFromMap({0, 0, 1}, mirrored, encode({0, s, c}), 1), {0, s, c});
}

TEST(NormalMap, TheTangentIsMadeOrthogonalToTheShadingNormal) {
  // An interpolated normal tilted off the face: the frame follows it, so the flat texel keeps it.
  const Vec3 N = glm::normalize(Vec3(0.3f, 0, 1));
  const TangentFrame f{{1, 0, 0}, {0, 1, 0}};
  expectNear(normalFromMap(N, f, {0.5f, 0.5f, 1, 1}, 1), N);
}

TEST(NormalMap, ScaleMultipliesXAndY) {
  // glTF: scaledNormal = normalize((2·rgb − 1) · (scale, scale, 1)).
  const TangentFrame f{{1, 0, 0}, {0, 1, 0}};
  const Vec4 texel{0.75f, 0.5f, 0.75f, 1};  // (0.5, 0, 0.5)
  expectNear(normalFromMap({0, 0, 1}, f, texel, 2), glm::normalize(Vec3(1, 0, 0.5f)));
}

TEST(MapTexels, RoughnessTimesGreenMetallicTimesBlueEmissionTimesRgb) {
  Material m;
  m.physicallyBased = true;
  m.physical.roughness = 0.8f;
  m.physical.metallic = 0.5f;
  m.emission = {1, 0.5f, 0.25f, 1};
  MapTexels t;
  t.metallicRoughness = Vec4(0.9f, 0.5f, 0.25f, 1);  // R is glTF's occlusion channel: unused here
  t.emissive = Vec4(0.5f, 1, 0, 1);
  const Material out = withMapTexels(m, t);
  EXPECT_FLOAT_EQ(out.physical.roughness, 0.4f);
  EXPECT_FLOAT_EQ(out.physical.metallic, 0.125f);
  EXPECT_EQ(Vec4(out.emission), Vec4(0.5f, 0.5f, 0, 1));
  // No texels: the material as it was.
  const Material same = withMapTexels(m, {});
  EXPECT_EQ(same.physical.roughness, m.physical.roughness);
  EXPECT_EQ(Vec4(same.emission), Vec4(m.emission));
}

}  // namespace
}  // namespace illum
