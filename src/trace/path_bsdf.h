// The BSDF the path tracer samples at a hit, from the material and its lighting model, in
// radiance units (the 1/π of a Lambertian surface included):
//   cook-torrance: f = (1 − F)(1 − metallic)·base/π + D·V·F (the rasterizer's terms, brdf.h);
//   GL materials:  f = k_d/π + k_s·(n+8)/(8π)·(N·H)^n (blinn-phong) or k_s·(n+2)/(2π)·(R·L)^n
//                  (phong), the classic lobes normalized to conserve energy (lambert: k_d/π).
// Its two parts are kept apart so that a GL light lights the diffuse one with its diffuse colour
// and the specular one with its specular colour, as the rasterizer does.
#pragma once

#include <illum/lighting.h>

#include "trace/sampling.h"

namespace illum {

struct BsdfValue {
  Color3 diffuse{0}, specular{0};
  Color3 sum() const { return diffuse + specular; }
};

struct BsdfSample {
  Vec3 direction{0};
  BsdfValue value;
  Real pdf = 0;  // solid angle
};

class PathBsdf {
 public:
  // `normal` is the shading normal turned to the side the ray came from; `material` has vertex
  // colours and textures applied.
  PathBsdf(const Material& material, LightingModel model, const Vec3& normal);

  BsdfValue eval(const Vec3& toViewer, const Vec3& toLight) const;
  Real pdf(const Vec3& toViewer, const Vec3& toLight) const;
  // What the surface reflects of white light, about: the denoiser's albedo (a dielectric's base
  // colour, a metal's reflectance; k_d + k_s of a GL material, at most 1).
  Color3 albedo() const;
  // Chooses a lobe by its expected weight (`choice` in [0, 1)), then a direction from it (`u`).
  bool sample(const Vec3& toViewer, Real choice, const Vec2& u, BsdfSample& out) const;

 private:
  Real specularPdf(const Vec3& v, const Vec3& l) const;  // local directions

  Frame frame_;
  LightingModel model_;
  PhysicalMaterial physical_;
  Real alpha_ = 1;
  Color3 kd_{0}, ks_{0};
  Real shininess_ = 0;
  Real specularChance_ = 0;
};

}  // namespace illum
