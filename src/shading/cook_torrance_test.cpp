// Cook-Torrance's terms against their defining properties: each distribution is normalized (the
// projected microfacet area is the macrosurface's), the specular BRDF never reflects more than it
// receives, Schlick's Fresnel meets its end points, and the visibility term's closed form.
#include "shading/brdf.h"

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ D(h) (n·h) dω over the hemisphere, by the midpoint rule in θ (D has no φ dependence), on a
// grid fine enough for the sharpest lobe tested.
double projectedArea(Real (*D)(Real, Real), Real alpha) {
  const int steps = 200000;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double theta = (i + 0.5) * (kPi / 2) / steps;
    sum += double(D(Real(std::cos(theta)), alpha)) * std::cos(theta) * std::sin(theta);
  }
  return 2 * kPi * sum * (kPi / 2) / steps;
}

TEST(CookTorrance, DistributionsAreNormalized) {
  for (Real alpha : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f}) {
    EXPECT_NEAR(projectedArea(D_GGX, alpha), 1, 2e-3) << "GGX α = " << alpha;
    EXPECT_NEAR(projectedArea(D_Beckmann, alpha), 1, 2e-3) << "Beckmann α = " << alpha;
  }
  // The peak: 1/(πα²) for both.
  EXPECT_NEAR(D_GGX(1, 0.5f), 1 / (kPi * 0.25), 1e-5);
  EXPECT_NEAR(D_Beckmann(1, 0.5f), 1 / (kPi * 0.25), 1e-5);
}

// The directional albedo of the specular lobe with F = 1, ∫ D·V·(n·l) dω_l, estimated by sampling
// the half vector from D(h)(n·h) on a stratified grid (l = the mirror of v about h).
double specularAlbedo(Real alpha, double thetaV) {
  const double vx = std::sin(thetaV), vz = std::cos(thetaV);
  const int n = 512;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n;
      const double thetaH = std::atan(double(alpha) * std::sqrt(u1 / (1 - u1))), phi = 2 * kPi * u2;
      const double hx = std::sin(thetaH) * std::cos(phi), hz = std::cos(thetaH);  // v lies in the xz plane
      const double VoH = vx * hx + vz * hz;
      if (VoH <= 0) continue;
      const double lz = 2 * VoH * hz - vz;  // n·l of l = 2(v·h)h − v
      if (lz <= 0) continue;
      // f·(n·l) / pdf(l) with pdf(l) = D(h)(n·h) / (4 v·h): the D cancels.
      sum += double(V_SmithGGXCorrelated(Real(vz), Real(lz), alpha)) * 4 * VoH * lz / hz;
    }
  return sum / (double(n) * n);
}

TEST(CookTorrance, GgxSpecularAlbedoNeverExceedsOne) {
  for (Real alpha : {0.01f, 0.05f, 0.2f, 0.5f, 0.8f, 1.0f})
    for (double degrees : {0.0, 30.0, 60.0, 75.0, 85.0}) {
      const double albedo = specularAlbedo(alpha, degrees * kPi / 180);
      EXPECT_LE(albedo, 1.0 + 2e-3) << "α " << alpha << ", θ " << degrees;
      // Single scattering with Smith's masking loses energy where the lobe is rough or the view
      // grazing; a near mirror seen from above keeps almost all.
      EXPECT_GT(albedo, alpha <= 0.05f && degrees <= 75 ? 0.97 : 0.25) << "α " << alpha << ", θ " << degrees;
    }
}

TEST(CookTorrance, SchlickFresnelMeetsItsEndPoints) {
  const Color3 f0(0.04f, 0.5f, 0.9f);
  const Color3 normal = F_Schlick(1, f0), grazing = F_Schlick(0, f0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(normal[c], f0[c]);
    EXPECT_FLOAT_EQ(grazing[c], 1);
  }
  // (1 − cos θ)⁵ between: at 60°, 1/32 of the way from f0 to 1.
  EXPECT_NEAR(F_Schlick(0.5f, f0).r, 0.04 + 0.96 / 32, 1e-6);
}

TEST(CookTorrance, SmithVisibilityAtNormalIncidenceIsAQuarter) {
  // N = L = V: G = 1, so V = G / (4 N·L N·V) = 1/4 whatever α.
  for (Real alpha : {0.1f, 0.5f, 1.0f}) EXPECT_NEAR(V_SmithGGXCorrelated(1, 1, alpha), 0.25, 1e-6);
  EXPECT_FLOAT_EQ(microfacetAlpha(0.5f), 0.25f);
  EXPECT_FLOAT_EQ(microfacetAlpha(0), 0.045f * 0.045f);  // kept off the mirror limit
}

}  // namespace
}  // namespace illum
