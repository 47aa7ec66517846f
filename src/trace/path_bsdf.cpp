#include "trace/path_bsdf.h"

#include "shading/brdf.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {


Vec3 reflect(const Vec3& v, const Vec3& n) { return 2 * glm::dot(v, n) * n - v; }  // v about n, both away

// Smith's G1 for GGX: the fraction of visible microfacets seen from a direction at cos θ = c.
Real smithG1(Real c, Real alpha) {
  const Real a2 = alpha * alpha;
  return 2 * c / (c + std::sqrt(a2 + (1 - a2) * c * c));
}

}  // namespace

PathBsdf::PathBsdf(const Material& material, LightingModel model, const Vec3& normal) : frame_(normal), model_(model) {
  if (model == LightingModel::CookTorrance) {
    physical_ = physicalOf(material);
    alpha_ = microfacetAlpha(physical_.roughness);
    const Color3 f0 = glm::mix(physical_.f0, physical_.baseColor, physical_.metallic);
    const Real specular = luminance(f0), diffuse = luminance((1 - physical_.metallic) * physical_.baseColor);
    specularChance_ = specular + diffuse > 0 ? std::clamp(specular / (specular + diffuse), Real(0.1), Real(0.9)) : 0;
    if (diffuse == 0) specularChance_ = 1;
    return;
  }
  kd_ = Color3(material.diffuse);
  // Lambert, Wylie and Bouknight have no highlight (the path tracer draws the early two as Lambertian).
  if (model == LightingModel::BlinnPhong || model == LightingModel::Phong)
    ks_ = Color3(material.specular), shininess_ = material.shininess;
  const Real d = luminance(kd_), s = luminance(ks_);
  specularChance_ = d + s > 0 ? s / (d + s) : 0;
}

Color3 PathBsdf::albedo() const {
  if (model_ == LightingModel::CookTorrance) return physical_.baseColor;
  return glm::min(kd_ + ks_, Color3(1));
}

BsdfValue PathBsdf::eval(const Vec3& toViewer, const Vec3& toLight) const {
  const Vec3 v = frame_.toLocal(toViewer), l = frame_.toLocal(toLight);
  BsdfValue f;
  if (v.z <= 0 || l.z <= 0) return f;
  const Vec3 h = glm::normalize(v + l);
  if (model_ == LightingModel::CookTorrance) {
    const Color3 f0 = glm::mix(physical_.f0, physical_.baseColor, physical_.metallic);
    const Color3 F = F_Schlick(glm::dot(v, h), f0);
    const Real D = physical_.distribution == Microfacet::GGX ? D_GGX(h.z, alpha_) : D_Beckmann(h.z, alpha_);
    f.diffuse = (Color3(1) - F) * (1 - physical_.metallic) * physical_.baseColor * Fd_Lambert();
    f.specular = D * V_SmithGGXCorrelated(v.z, l.z, alpha_) * F;
    return f;
  }
  f.diffuse = kd_ / kPiReal;
  if (model_ == LightingModel::BlinnPhong)
    f.specular = ks_ * ((shininess_ + 8) / (8 * kPiReal) * Fs_BlinnPhong(h.z, shininess_));
  else if (model_ == LightingModel::Phong)
    f.specular = ks_ * ((shininess_ + 2) / (2 * kPiReal) * Fs_Phong(glm::dot(reflect(l, Vec3(0, 0, 1)), v), shininess_));
  return f;
}

Real PathBsdf::specularPdf(const Vec3& v, const Vec3& l) const {
  const Vec3 h = glm::normalize(v + l);
  const Real VoH = glm::dot(v, h);
  if (VoH <= 0) return 0;
  if (model_ == LightingModel::CookTorrance)  // visible normals: G1(v)·D(h)/(4 N·V)
    return smithG1(v.z, alpha_) * D_GGX(h.z, alpha_) / (4 * v.z);
  if (model_ == LightingModel::BlinnPhong)  // H from (n+1)/(2π) (N·H)^n, then l = mirror of v
    return (shininess_ + 1) / (2 * kPiReal) * std::pow(std::max(Real(0), h.z), shininess_) / (4 * VoH);
  // phong: l about the mirror direction R of v with (n+1)/(2π) cos^n
  return (shininess_ + 1) / (2 * kPiReal) * std::pow(std::max(Real(0), glm::dot(reflect(v, Vec3(0, 0, 1)), l)), shininess_);
}

Real PathBsdf::pdf(const Vec3& toViewer, const Vec3& toLight) const {
  const Vec3 v = frame_.toLocal(toViewer), l = frame_.toLocal(toLight);
  if (v.z <= 0 || l.z <= 0) return 0;
  Real p = (1 - specularChance_) * l.z / kPiReal;
  if (specularChance_ > 0) p += specularChance_ * specularPdf(v, l);
  return p;
}

bool PathBsdf::sample(const Vec3& toViewer, Real choice, const Vec2& u, BsdfSample& out) const {
  const Vec3 v = frame_.toLocal(toViewer);
  if (v.z <= 0) return false;
  const Real u1 = u.x, u2 = u.y;
  Vec3 l;
  if (choice < specularChance_) {
    if (model_ == LightingModel::CookTorrance) {
      l = reflect(v, sampleGgxVisibleNormal(v, alpha_, u1, u2));
    } else {
      // A direction about the lobe's axis at cos = u1^(1/(n+1)): H for blinn-phong, l for phong.
      const Real c = std::pow(u1, 1 / (shininess_ + 1)), s = std::sqrt(std::max(Real(0), 1 - c * c));
      const Vec3 local(s * std::cos(2 * kPiReal * u2), s * std::sin(2 * kPiReal * u2), c);
      if (model_ == LightingModel::BlinnPhong) {
        l = reflect(v, Frame(Vec3(0, 0, 1)).toWorld(local));
      } else {
        l = Frame(reflect(v, Vec3(0, 0, 1))).toWorld(local);
      }
    }
  } else {
    l = sampleCosineHemisphere(u1, u2);
  }
  if (l.z <= 0) return false;
  out.direction = frame_.toWorld(l);
  out.value = eval(toViewer, out.direction);
  out.pdf = pdf(toViewer, out.direction);
  return out.pdf > 0;
}

}  // namespace illum
