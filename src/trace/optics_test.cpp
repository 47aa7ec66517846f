// Snell's law, total internal reflection and Fresnel's equations against their closed forms.
#include "trace/optics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

TEST(Optics, MirrorDirectionKeepsTheAngle) {
  const Vec3 D = glm::normalize(Vec3(1, -1, 0)), N(0, 1, 0);
  const Vec3 R = reflectDirection(D, N);
  EXPECT_NEAR(R.x, D.x, 1e-6);
  EXPECT_NEAR(R.y, -D.y, 1e-6);
}

TEST(Optics, RefractionFollowsSnellsLaw) {
  for (Real degrees : {0.0f, 10.0f, 30.0f, 60.0f, 85.0f}) {
    const Real theta = glm::radians(degrees);
    const Vec3 D(std::sin(theta), -std::cos(theta), 0), N(0, 1, 0);
    const auto T = refractDirection(D, N, 1, Real(1.5));
    ASSERT_TRUE(T.has_value());
    // 1 · sin θ_i = 1.5 · sin θ_t, and the ray goes on into the surface.
    EXPECT_NEAR(T->x * 1.5f, std::sin(theta), 1e-6) << degrees;
    EXPECT_LT(T->y, 0);
    EXPECT_NEAR(glm::length(*T), 1, 1e-6);
  }
}

TEST(Optics, TotalInternalReflectionBeginsAtTheCriticalAngle) {
  const Real n = Real(1.5);
  const Real critical = std::asin(1 / n);  // 41.81°
  const Vec3 N(0, 1, 0);
  const auto at = [&](Real theta) { return Vec3(std::sin(theta), -std::cos(theta), 0); };
  // Inside the glass (η_i = 1.5) towards air: refracted just below the critical angle, not above.
  EXPECT_TRUE(refractDirection(at(critical - Real(1e-3)), N, n, 1).has_value());
  EXPECT_FALSE(refractDirection(at(critical + Real(1e-3)), N, n, 1).has_value());
  EXPECT_EQ(fresnelDielectric(std::cos(critical + Real(1e-3)), n, 1), 1);
  EXPECT_LT(fresnelDielectric(std::cos(critical - Real(1e-2)), n, 1), 1);
  // Just below it the refracted ray grazes the surface: sin θ_t → 1.
  const auto grazing = refractDirection(at(critical - Real(1e-4)), N, n, 1);
  ASSERT_TRUE(grazing.has_value());
  EXPECT_GT(std::abs(grazing->x), Real(0.99));
}

TEST(Optics, FresnelAtNormalIncidenceIsTheSquaredRatio) {
  for (Real n : {1.33f, 1.5f, 2.4f}) {
    const Real expected = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1));
    EXPECT_NEAR(fresnelDielectric(1, 1, n), expected, 1e-6) << n;
    EXPECT_NEAR(fresnelDielectric(1, n, 1), expected, 1e-6) << n;  // the same from inside
  }
}

TEST(Optics, FresnelAtBrewstersAngleLeavesOnlyTheSPolarisation) {
  // At Brewster's angle r_p = 0, so F = r_s² / 2 with r_s = cos(θ_i + θ_t)... = (n² − 1)/(n² + 1).
  const Real n = Real(1.5);
  const Real brewster = std::atan(n);
  const Real rs = (n * n - 1) / (n * n + 1);
  EXPECT_NEAR(fresnelDielectric(std::cos(brewster), 1, n), rs * rs / 2, 1e-5);
  // And at grazing incidence everything is reflected.
  EXPECT_NEAR(fresnelDielectric(0, 1, n), 1, 1e-6);
}

}  // namespace
}  // namespace illum
