#include "trace/area_lights.h"

#include "trace/sampling.h"

#include <algorithm>

namespace illum {
namespace {
}  // namespace

AreaLights::AreaLights(const Scene& scene, const RayScene& rays) : rays_(rays) {
  objectLuminance_.assign(scene.objects.size(), 0);
  for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Real lum = luminance(Color3(scene.objects[o].material.emission));
    if (!(lum > 0)) continue;
    objectLuminance_[o] = lum;
    const EyeMesh& mesh = rays.mesh(o);
    const auto& indices = scene.objects[o].mesh->indices;
    for (std::uint32_t t = 0; 3 * std::size_t(t) < indices.size(); ++t) {
      const Vec3 &p0 = mesh.positions[indices[3 * t]], &p1 = mesh.positions[indices[3 * t + 1]],
                 &p2 = mesh.positions[indices[3 * t + 2]];
      const Real area = glm::length(glm::cross(p1 - p0, p2 - p0)) / 2;
      if (!(area > 0)) continue;
      total_ += area * lum;
      object_.push_back(o);
      triangle_.push_back(t);
      cumulative_.push_back(total_);
    }
  }
}

AreaLightSample AreaLights::sample(Real u0, Real u1, Real u2) const {
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u0 * total_);
  const std::size_t i = std::min<std::size_t>(std::size_t(it - cumulative_.begin()), cumulative_.size() - 1);
  const std::uint32_t o = object_[i];
  const EyeMesh& mesh = rays_.mesh(o);
  const auto& indices = mesh.object->mesh->indices;
  const std::size_t t = triangle_[i];
  const Vec3 &p0 = mesh.positions[indices[3 * t]], &p1 = mesh.positions[indices[3 * t + 1]],
             &p2 = mesh.positions[indices[3 * t + 2]];
  const Vec2 b = sampleTriangle(u1, u2);
  AreaLightSample out;
  out.position = b.x * p0 + b.y * p1 + (1 - b.x - b.y) * p2;
  out.normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  out.radiance = Color3(mesh.object->material.emission);
  // An emissive map scales the emission where the point falls on it (its finest level: a light's
  // texels are seen from afar only through this one point).
  const Object& object = *mesh.object;
  if (object.maps.emissive && !object.mesh->uvs.empty()) {
    const auto& uvs = object.mesh->uvs;
    const Vec2 uv = b.x * uvs[indices[3 * t]] + b.y * uvs[indices[3 * t + 1]] + (1 - b.x - b.y) * uvs[indices[3 * t + 2]];
    out.radiance *= Color3(object.maps.emissive->sampleLevel(uv, 0));
  }
  out.pdfArea = objectLuminance_[o] / total_;
  return out;
}

Real AreaLights::pdfArea(std::uint32_t object) const {
  return total_ > 0 ? objectLuminance_[object] / total_ : 0;
}

}  // namespace illum
