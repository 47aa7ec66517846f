// The environment map's sampling density: a true density over the sphere, the one `sample` draws
// with, and zero only where lookups find no radiance.
#include "trace/environment_light.h"

#include "trace/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

EnvironmentMap twoSuns() {
  const int w = 32, h = 16;
  std::vector<Vec3> texels(std::size_t(w * h), Vec3(0.01f));
  texels[std::size_t(3 * w + 5)] = Vec3(50);
  texels[std::size_t(12 * w + 31)] = Vec3(0, 80, 0);  // at the seam of longitude
  return EnvironmentMap(w, h, texels);
}

Vec3 direction(double theta, double phi) {
  return {Real(std::sin(theta) * std::sin(phi)), Real(std::cos(theta)), Real(-std::sin(theta) * std::cos(phi))};
}

TEST(EnvironmentLight, ThePdfIntegratesToOneOverTheSphere) {
  const EnvironmentMap map = twoSuns();
  const EnvironmentLight light(map);
  double integral = 0;
  const int nu = 1024, nv = 512;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double theta = M_PI * (j + 0.5) / nv, phi = 2 * M_PI * ((i + 0.5) / nu - 0.5);
      integral += light.pdf(direction(theta, phi)) * 2 * M_PI * M_PI * std::sin(theta) / (double(nu) * nv);
    }
  EXPECT_NEAR(integral, 1, 2e-3);
}

// Each sample's pdf is the density's value there, and L/pdf averages to ∫ L dω over the sphere
// (the light's total), as a quadrature of the map's own lookups finds it.
TEST(EnvironmentLight, SamplesCarryTheirPdfAndEstimateTheMapsIntegral) {
  const EnvironmentMap map = twoSuns();
  const EnvironmentLight light(map);
  double quadrature = 0;
  const int nu = 2048, nv = 1024;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double theta = M_PI * (j + 0.5) / nv, phi = 2 * M_PI * ((i + 0.5) / nu - 0.5);
      quadrature += luminance(map.radiance(direction(theta, phi))) * 2 * M_PI * M_PI * std::sin(theta) / (double(nu) * nv);
    }
  Rng rng(7, 1);
  double estimate = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const EnvironmentSample s = light.sample(rng.uniform(), rng.uniform());
    ASSERT_NEAR(glm::length(s.direction), 1, 1e-5);
    ASSERT_GT(s.pdf, 0);
    EXPECT_NEAR(s.pdf, light.pdf(s.direction), 1e-3 * s.pdf);
    estimate += luminance(map.radiance(s.direction)) / s.pdf / n;
  }
  EXPECT_NEAR(estimate, quadrature, 0.02 * quadrature);
}

TEST(EnvironmentLight, ABlackMapIsEmpty) {
  const EnvironmentMap black(4, 2, std::vector<Vec3>(8, Vec3(0)));
  EXPECT_TRUE(EnvironmentLight(black).empty());
  EXPECT_EQ(EnvironmentLight(black).pdf({0, 1, 0}), 0);
}

}  // namespace
}  // namespace illum
