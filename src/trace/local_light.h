// The local equation at a ray's hit, composed from the rasterizer's own terms (shading/: "where is
// the light" and "how a GL material answers", one light at a time) with what only a ray tracer
// knows: whether each light is seen (shadow rays), and for Hall and Greenberg's model the Fresnel
// weighting of highlights and the highlights of lights seen through a transmissive surface.
#pragma once

#include <illum/lighting.h>

#include <span>

namespace illum {

// The light that reaches a point from one light (1 seen, 0 in shadow, a colour through filters).
class LightVisibility {
 public:
  virtual ~LightVisibility() = default;
  // `toLight` is the unit vector towards the light, `distance` 0 for a directional light.
  virtual Color3 towards(const EyeLight& light, const Vec3& toLight, Real distance) const = 0;
};

// Hall and Greenberg (1983) at a transmissive or reflective dielectric surface: the indices of
// refraction on the viewer's side and on the other side, and the transmitted highlights' exponent.
struct HallSurface {
  Real etaViewer = 1, etaBeyond = Real(1.5);
  Real transmissionShininess = 0;
  bool transmits = false;  // lights behind the surface give transmitted highlights
};

// Where and what is lit: eye space, N the unit normal of the side the viewer sees.
struct LocalSurface {
  SurfaceGeometry geometry;
  Material material;  // vertex colours applied
};

// The terms (unclamped) of:
//   Whitted (hall == nullptr): e + a_cm·a_cs + Σ_i att·spot·[a_cm·a_cli + S_i ⊙ (diffuse_i + specular_i)]
//   Hall:    the same with specular_i × F_r(L·H), plus for lights behind a transmissive surface
//            att·spot·S_i ⊙ F_t · max(N·H′,0)^n′ · s_cm ⊙ s_cli (Hall & Greenberg 1983's
//            transmitted specular term), H′ the normal of the facets that refract L into V,
//            H′ ∝ −(η_L·L + η_V·V) (Walter et al. 2007's form of Hall's H′), F_t = 1 − F_r(V·H′).
// S_i is `visibility` towards light i (1 everywhere when it is null).
LightingTerms localTerms(std::span<const EyeLight> lights, const LightModel& lightModel, LightingModel model,
                         const LocalSurface& surface, const LightVisibility* visibility, const HallSurface* hall);

}  // namespace illum
