#include "shading/material_maps.h"

#include <cmath>

namespace illum {

Material withMapTexels(Material m, const MapTexels& texels) {
  if (texels.metallicRoughness) {
    m.physical.roughness *= (*texels.metallicRoughness).g;
    m.physical.metallic *= (*texels.metallicRoughness).b;
  }
  if (texels.emissive) m.emission = Color4(Color3(m.emission) * Color3(*texels.emissive), m.emission.a);
  return m;
}

TangentFrame triangleTangents(const std::array<Vec3, 3>& p, const std::array<Vec2, 3>& uv) {
  // Solve e1 = Δu1·T + Δv1·B, e2 = Δu2·T + Δv2·B for T = ∂P/∂u and B = ∂P/∂v.
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Vec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
  const Real det = d1.x * d2.y - d2.x * d1.y;
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return {};
  const Real inv = 1 / det;
  TangentFrame f{(d2.y * e1 - d1.y * e2) * inv, (d1.x * e2 - d2.x * e1) * inv};
  if (!std::isfinite(f.dPdu.x + f.dPdu.y + f.dPdu.z + f.dPdv.x + f.dPdv.y + f.dPdv.z)) return {};
  return f;
}

Vec3 normalFromMap(const Vec3& N, const TangentFrame& frame, const Vec4& texel, Real scale) {
  const Vec3 t = frame.dPdu - glm::dot(frame.dPdu, N) * N;  // Gram-Schmidt against the shading normal
  const Real tLen = glm::length(t);
  if (!(tLen > 0)) return N;
  const Vec3 T = t / tLen;
  const Vec3 B = glm::dot(glm::cross(N, T), frame.dPdv) < 0 ? -glm::cross(N, T) : glm::cross(N, T);
  const Vec3 n((2 * texel.r - 1) * scale, (2 * texel.g - 1) * scale, 2 * texel.b - 1);
  const Vec3 perturbed = n.x * T + n.y * B + n.z * N;
  const Real len = glm::length(perturbed);
  return len > 0 ? perturbed / len : N;
}

}  // namespace illum
