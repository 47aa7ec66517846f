#include "shading/brdf.h"

#include <gtest/gtest.h>

namespace illum {
namespace {

EyeLight pointAt(const Vec3& p, const Vec3& attenuation) {
  EyeLight l;
  l.position = Vec4(p, 1);
  l.attenuation = attenuation;
  return l;
}

// The one light sample every renderer uses (the rasterizer's lanes, the path tracer's next-event
// estimation): GL's direction, distance and 1 / (k_c + k_l·d + k_q·d²), and its edge cases.
TEST(SampleLight, PositionalDirectionalAndTheirEdgeCases) {
  const Vec3 N(0, 0, 1);
  const LightSampleAt a = sampleLight(pointAt({0, 3, 4}, {1, 0, 0.5}), Vec3(0), N);
  EXPECT_FLOAT_EQ(a.distance, 5);
  EXPECT_NEAR(a.L.y, 0.6, 1e-6);
  EXPECT_NEAR(a.L.z, 0.8, 1e-6);
  EXPECT_NEAR(a.attenuation, 1 / 13.5, 1e-7);  // 1 / (1 + 0.5·25)
  // A light at the point shines along the normal, attenuated by k_c alone.
  const LightSampleAt at = sampleLight(pointAt({1, 2, 3}, {2, 1, 1}), Vec3(1, 2, 3), N);
  EXPECT_EQ(at.distance, 0);
  EXPECT_EQ(at.L, N);
  EXPECT_FLOAT_EQ(at.attenuation, 0.5);
  // A directional light: unit L, no distance, no attenuation; a zero direction means +Z.
  EyeLight sun;
  sun.position = Vec4(0, 0, 0, 0);
  const LightSampleAt z = sampleLight(sun, Vec3(5), Vec3(1, 0, 0));
  EXPECT_EQ(z.L, Vec3(0, 0, 1));
  EXPECT_EQ(z.distance, 0);
  EXPECT_EQ(z.attenuation, 1);
}

}  // namespace
}  // namespace illum
