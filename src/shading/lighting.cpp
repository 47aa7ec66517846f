// The OpenGL 2.1 §2.14.1 lighting equation:
//   c = e_cm + a_cm·a_cs + Σ_i att_i · spot_i · [a_cm·a_cli + (n⊙VP)·d_cm·d_cli + f_i·(n⊙ĥ)^s·s_cm·s_cli]
// computed per channel in eye space.
#include <illum/lighting.h>

#include "shading/brdf.h"

#include <cmath>

namespace illum {

std::string_view toString(LightingModel model) {
  switch (model) {
    case LightingModel::BlinnPhong: return "blinn-phong";
    case LightingModel::Phong: return "phong";
    case LightingModel::Lambert: return "lambert";
  }
  return "?";
}

std::string_view toString(Shading shading) {
  switch (shading) {
    case Shading::Flat: return "flat";
    case Shading::Gouraud: return "gouraud";
    case Shading::Phong: return "phong";
  }
  return "?";
}

std::optional<LightingModel> parseLightingModel(std::string_view name) {
  if (name == "blinn-phong") return LightingModel::BlinnPhong;
  if (name == "phong") return LightingModel::Phong;
  if (name == "lambert") return LightingModel::Lambert;
  return std::nullopt;
}

std::optional<Shading> parseShading(std::string_view name) {
  if (name == "flat") return Shading::Flat;
  if (name == "gouraud") return Shading::Gouraud;
  if (name == "phong") return Shading::Phong;
  return std::nullopt;
}

EyeLight toEyeSpace(const Light& light, const Mat4& viewFromWorld) {
  EyeLight eye;
  // glLightfv(GL_POSITION) transforms the position by GL_MODELVIEW.
  eye.position = viewFromWorld * light.position;
  // GL_SPOT_DIRECTION is transformed by the upper-left 3×3 of GL_MODELVIEW (§2.14.1).
  Vec3 s = Mat3(viewFromWorld) * light.spotDirection;
  Real len = glm::length(s);
  eye.spotDirection = len > 0 ? s / len : Vec3(0, 0, -1);
  eye.ambient = light.ambient;
  eye.diffuse = light.diffuse;
  eye.specular = light.specular;
  eye.attenuation = light.attenuation;
  eye.spotExponent = light.spotExponent;
  eye.spotCutoff = light.spotCutoff;
  eye.spotCosCutoff = light.spotCutoff == 180 ? Real(-2)
                                              : std::cos(glm::radians(light.spotCutoff));
  return eye;
}

Vec3 viewerDirection(const Vec3& eyePosition, bool localViewer) {
  if (!localViewer) return Vec3(0, 0, 1);
  Real len = glm::length(eyePosition);
  // A point at the eye itself has no direction to the viewer; take the infinite viewer's.
  return len > 0 ? -eyePosition / len : Vec3(0, 0, 1);
}

namespace {

// The one light term of §2.14.1. With kRecord every intermediate goes to `d` as well; without,
// nothing but the sum is written (the renderer's hot path).
template <bool kRecord>
void lightTerm(LightingTerms& terms, const EyeLight& light, const Material& material, LightingModel model,
               const SurfaceGeometry& surface, LightDetail* d) {
  const Vec3& N = surface.normal;
  const Vec3& V = surface.toViewer;

  // Where the light is: the unit vector towards it and the attenuation.
  Vec3 L;
  Real attenuation = 1;
  if (light.isPositional()) {
    Vec3 toLight = Vec3(light.position) / light.position.w - surface.position;
    Real dist = glm::length(toLight);
    L = dist > 0 ? toLight / dist : N;  // a light exactly at the point shines along the normal
    attenuation = distanceAttenuation(light.attenuation, dist);
    if constexpr (kRecord) d->distance = dist;
  } else {
    Real len = glm::length(Vec3(light.position));
    L = len > 0 ? Vec3(light.position) / len : Vec3(0, 0, 1);
  }

  // The spot factor applies to directional lights too, as GL specifies.
  Real spot = light.isSpot() ? spotFactor(glm::dot(-L, light.spotDirection), light.spotCosCutoff,
                                          light.spotExponent)
                             : Real(1);
  Real scale = attenuation * spot;
  Real NoL = glm::dot(N, L);
  if constexpr (kRecord) d->positional = light.isPositional(), d->L = L, d->attenuation = attenuation, d->spot = spot, d->NoL = NoL;
  if (scale == 0 && !kRecord) return;

  // How the surface answers: ambient, Lambert's diffuse and the model's specular lobe.
  const Color3 ambient = scale * Color3(material.ambient) * light.ambient;
  const Color3 diffuse = scale * Fd_Lambert(NoL) * Color3(material.diffuse) * light.diffuse;
  Color3 specular(0);
  // f_i = 0 when the light is behind the surface: no highlight without direct light.
  Real lobe = 0;
  if (model == LightingModel::BlinnPhong && (NoL > 0 || kRecord)) {
    Vec3 H = L + V;
    Real len = glm::length(H);
    // L = −V (up to rounding) leaves H undefined; illum takes N·H = 0 (so only 0^0 = 1 survives).
    Real NoH = len > Real(1e-6) ? glm::dot(N, H) / len : Real(0);
    if constexpr (kRecord) d->H = len > Real(1e-6) ? H / len : Vec3(0), d->NoH = NoH;
    if (NoL > 0) lobe = Fs_BlinnPhong(NoH, material.shininess);
  } else if (model == LightingModel::Phong && (NoL > 0 || kRecord)) {
    Vec3 R = Real(2) * NoL * N - L;
    if constexpr (kRecord) d->R = R, d->RoV = glm::dot(R, V);
    if (NoL > 0) lobe = Fs_Phong(glm::dot(R, V), material.shininess);
  }
  if (model != LightingModel::Lambert && NoL > 0) specular = scale * lobe * Color3(material.specular) * light.specular;
  if constexpr (kRecord) {
    d->lobe = lobe;
    if (scale == 0) return;  // the terms stay zero
    d->terms.ambient = ambient, d->terms.diffuse = diffuse, d->terms.specular = specular;
  }
  terms.ambient += ambient;
  terms.diffuse += diffuse;
  terms.specular += specular;
}

}  // namespace

void accumulateLight(LightingTerms& terms, const EyeLight& light, const Material& material,
                     LightingModel model, const SurfaceGeometry& surface, LightDetail* detail) {
  if (detail) {
    *detail = LightDetail{};
    lightTerm<true>(terms, light, material, model, surface, detail);
  } else {
    lightTerm<false>(terms, light, material, model, surface, nullptr);
  }
}

LightingTerms evaluateTerms(std::span<const EyeLight> lights, const LightModel& lightModel,
                            const Material& material, LightingModel model,
                            const SurfaceGeometry& surface) {
  LightingTerms terms;
  terms.emission = Color3(material.emission);
  terms.ambient = lightModel.ambient * Color3(material.ambient);
  for (const EyeLight& light : lights) accumulateLight(terms, light, material, model, surface);
  return terms;
}

Color4 clampedColor(const LightingTerms& terms, const Material& material) {
  Color3 c = glm::clamp(terms.sum(), Color3(0), Color3(1));
  return Color4(c, glm::clamp(material.diffuse.a, Real(0), Real(1)));
}

}  // namespace illum
