#include "conventions.h"

#include <algorithm>
#include <cmath>

namespace illum::cli {

std::optional<Convention> parseConvention(std::string_view name) {
  if (name == "note-shader") return Convention::NoteShader;
  if (name == "note-half-sum") return Convention::NoteHalfSum;
  return std::nullopt;
}

std::vector<std::string> conventionNames() { return {"note-shader", "note-half-sum"}; }

ConventionTerms underConvention(Convention c, const LightingTerms& gl, const EyeLight& light, const Material& m,
                                LightingModel model, const LightDetail& d, const Vec3& N, const Vec3& V) {
  ConventionTerms t;
  const Real n = m.shininess;
  const Color3 ka(m.ambient), kd(m.diffuse), ks(m.specular);
  const Real NoL = glm::dot(N, d.L);
  const bool lobe = model == LightingModel::Phong || model == LightingModel::BlinnPhong;
  if (c == Convention::NoteShader) {
    t.name = "note-shader";
    t.formula = "seed 001's shader: pixel = mat.ambient + (mat.diffuse + specular) × Ld·max(N·L, 0)";
    const Color3 strength = light.diffuse * std::max(NoL, Real(0)) * d.attenuation * d.spot;
    Real s = 0;
    if (lobe && NoL > 0) {
      const Real cosine = model == LightingModel::Phong ? glm::dot(d.R, V) : glm::dot(N, glm::normalize(d.L + V));
      s = std::pow(std::max(cosine, Real(0)), n);
    }
    t.ambient = ka;
    t.diffuse = kd * strength;
    t.specular = ks * s * strength;
  } else {
    t.name = "note-half-sum";
    t.formula = "seed 001's H = (L + V) / 2, not normalised: (N·H)ⁿ with |H| ≤ 1";
    // GL's terms, the specular's lobe taken with the plain mean of L and V (the same factors else:
    // a lobe GL finds zero, N·L ≤ 0 or N·H ≤ 0, is zero here too).
    t.emission = gl.emission;
    t.ambient = gl.ambient;
    t.diffuse = gl.diffuse;
    t.NoH = glm::dot(N, (d.L + V) / Real(2));
    const bool blinn = model == LightingModel::BlinnPhong;
    t.specular = blinn && d.lobe > 0 ? gl.specular * (std::pow(std::max(t.NoH, Real(0)), n) / d.lobe) : gl.specular;
    t.total = glm::clamp(t.emission + t.ambient + t.diffuse + t.specular, Color3(0), Color3(1));
    return t;
  }
  t.total = glm::clamp(t.ambient + t.diffuse + t.specular, Color3(0), Color3(1));
  return t;
}

}  // namespace illum::cli
