// The two descriptions of a material, each derived from the other (lighting.h).
#include <illum/lighting.h>

#include <algorithm>
#include <cmath>

namespace illum {

namespace {
constexpr Real kMaxShininess = 10000;  // α → 0 is a mirror, which no exponent reaches
}

PhysicalMaterial physicalFromGl(const Material& m) {
  PhysicalMaterial p = m.physical;
  p.baseColor = Color3(m.diffuse);
  p.metallic = 0;
  // Filament's reflectance parameter: f0 = 0.16·r², so GL's specular 0.5 is the common dielectric's
  // 0.04, 1 a gemstone's 0.16, and a material without specular colour has no highlight.
  const Color3 s(m.specular);
  p.f0 = Real(0.16) * s * s;
  const Real alpha = std::sqrt(Real(2) / (m.shininess + 2));
  p.roughness = std::sqrt(alpha);
  return p;
}

void glFromPhysical(Material& m, const PhysicalMaterial& p) {
  m.physicallyBased = true;
  m.physical = p;
  const Color3 albedo = p.baseColor * (1 - p.metallic);
  m.ambient = Color4(albedo, m.diffuse.a);
  m.diffuse = Color4(albedo, m.diffuse.a);
  // The inverse of physicalFromGl's reflectance mapping for the dielectric part, the base colour
  // (a metal's highlight colour) for the metallic part.
  const Color3 reflectance = glm::min(Color3(1), Real(2.5) * glm::sqrt(p.f0));
  m.specular = Color4(reflectance * (1 - p.metallic) + p.baseColor * p.metallic, 1);
  const Real alpha = p.roughness * p.roughness;
  m.shininess = alpha > 0 ? std::min(kMaxShininess, std::max(Real(0), 2 / (alpha * alpha) - 2)) : kMaxShininess;
}

}  // namespace illum
