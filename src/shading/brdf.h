// The reflection lobes and light factors for one value at a time: the lane templates of
// brdf-inl.h and light_sample-inl.h on a single lane (defined in shade_points.cpp), for tests and
// reports.
#pragma once

#include <illum/lighting.h>
#include <illum/real.h>

namespace illum {

// max(N·L, 0): Lambert's cosine law as GL's diffuse term uses it.
Real Fd_LambertCosine(Real NoL);
// (R·V)^n, (N·H)^n: max(x, 0)^n with 0^0 = 1.
Real Fs_Phong(Real RoV, Real shininess);
Real Fs_BlinnPhong(Real NoH, Real shininess);
// 1 / (k_c + k_l·d + k_q·d²).
Real distanceAttenuation(const Vec3& k, Real d);
// max(−L·S, 0)^e inside the cone (−L·S ≥ cos cutoff), else 0.
Real spotFactor(Real minusLoS, Real cosCutoff, Real exponent);

// Where is the light, seen from P with unit normal N (light_sample-inl.h's SampleLight): L towards
// it, its distance (0 for a directional light), attenuation and spot factor. A positional light
// exactly at P shines along N; a directional light of zero direction along +Z.
struct LightSampleAt {
  Vec3 L{0};
  Real distance = 0;
  Real attenuation = 1;
  Real spot = 1;
};
LightSampleAt sampleLight(const EyeLight& light, const Vec3& P, const Vec3& N);

// Cook-Torrance's terms (cook_torrance-inl.h, brdf-inl.h): the normal distributions, the Smith
// visibility G / (4 N·L N·V), Schlick's Fresnel, and α for a perceptual roughness.
Real Fd_Lambert();  // 1/π
Real D_GGX(Real NoH, Real alpha);
Real D_Beckmann(Real NoH, Real alpha);
Real V_SmithGGXCorrelated(Real NoV, Real NoL, Real alpha);
Color3 F_Schlick(Real VoH, const Color3& f0);
Real microfacetAlpha(Real roughness);

}  // namespace illum
