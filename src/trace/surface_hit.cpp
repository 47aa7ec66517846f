#include "trace/surface_hit.h"

#include "shading/material_maps.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace illum {
namespace {

// Texture coordinates where `ray` meets the plane of the hit's triangle (the barycentrics of that
// point, which may lie outside the triangle, as the rasterizer's extrapolated ones do).
Vec2 uvOnPlane(const EyeMesh& mesh, const HitPoint& h, const Ray& ray) {
  const auto& uvs = mesh.object->mesh->uvs;
  const Vec3 &p0 = mesh.positions[h.index[0]], &p1 = mesh.positions[h.index[1]], &p2 = mesh.positions[h.index[2]];
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, n = glm::cross(e1, e2);
  const Real facing = glm::dot(ray.direction, n);
  if (facing == 0) return h.w[0] * uvs[h.index[0]] + h.w[1] * uvs[h.index[1]] + h.w[2] * uvs[h.index[2]];
  const Vec3 P = ray.origin + (glm::dot(p0 - ray.origin, n) / facing) * ray.direction;
  const Real area = glm::dot(n, n);
  const Real w1 = glm::dot(glm::cross(P - p0, e2), n) / area, w2 = glm::dot(glm::cross(e1, P - p0), n) / area;
  return (1 - w1 - w2) * uvs[h.index[0]] + w1 * uvs[h.index[1]] + w2 * uvs[h.index[2]];
}

}  // namespace

Vec3 offsetOrigin(const Vec3& P, const Vec3& geometricNormal, const Vec3& direction) {
  const Real eps = Real(2e-4) * std::max({Real(1e-3), std::abs(P.x), std::abs(P.y), std::abs(P.z)});
  return P + (glm::dot(direction, geometricNormal) > 0 ? eps : -eps) * geometricNormal;
}


HitPoint hitPoint(const RayScene& rays, const Ray& ray, const RayHit& hit) {
  const EyeMesh& mesh = rays.mesh(hit.object);
  HitPoint h;
  h.object = mesh.object;
  const auto& indices = mesh.object->mesh->indices;
  for (int k = 0; k < 3; ++k) h.index[std::size_t(k)] = indices[3 * std::size_t(hit.triangle) + std::size_t(k)];
  h.w = {1 - hit.u - hit.v, hit.u, hit.v};
  const Vec3 &p0 = mesh.positions[h.index[0]], &p1 = mesh.positions[h.index[1]], &p2 = mesh.positions[h.index[2]];
  h.position = h.w[0] * p0 + h.w[1] * p1 + h.w[2] * p2;
  const Vec3 n = h.w[0] * mesh.normals[h.index[0]] + h.w[1] * mesh.normals[h.index[1]] + h.w[2] * mesh.normals[h.index[2]];
  const Real len = glm::length(n);
  h.normal = len > 0 ? (Real(1) / len) * n : Vec3(0, 0, 1);
  const Vec3 ng = glm::cross(p1 - p0, p2 - p0);
  const Real ngLen = glm::length(ng);
  h.geometricNormal = ngLen > 0 ? ng / ngLen : h.normal;
  h.front = glm::dot(ng, ray.direction) < 0;
  return h;
}

Vec4 texelAt(const Texture& texture, const EyeMesh& mesh, const HitPoint& h, const Ray& ray, const RayCone& cone,
             Real coneWidth) {
  const auto& uvs = mesh.object->mesh->uvs;
  const Vec2 uv = h.w[0] * uvs[h.index[0]] + h.w[1] * uvs[h.index[1]] + h.w[2] * uvs[h.index[2]];
  const Vec2 size(Real(texture.width()), Real(texture.height()));
  if (cone.differentials) {
    const Vec2 dx = uvOnPlane(mesh, h, cone.right) - uv, dy = uvOnPlane(mesh, h, cone.up) - uv;
    return texture.sample(uv, std::max(glm::length(dx * size), glm::length(dy * size)));
  }
  const Vec3 &p0 = mesh.positions[h.index[0]], &p1 = mesh.positions[h.index[1]], &p2 = mesh.positions[h.index[2]];
  const Real worldArea = glm::length(glm::cross(p1 - p0, p2 - p0));
  const Vec2 e1 = uvs[h.index[1]] - uvs[h.index[0]], e2 = uvs[h.index[2]] - uvs[h.index[0]];
  const Real texelArea = std::abs(e1.x * e2.y - e1.y * e2.x) * size.x * size.y;
  if (!(worldArea > 0)) return texture.sample(uv, 1);
  // Texels per unit length on the triangle, stretched along the view where it is seen edge-on.
  const Real cosine = std::max(Real(0.05), std::abs(glm::dot(glm::normalize(ray.direction), h.geometricNormal)));
  return texture.sample(uv, coneWidth * std::sqrt(texelArea / worldArea) / cosine);
}

PointMaterial materialAtHit(const EyeMesh& mesh, HitPoint& h, const Ray& ray, const RayCone& cone, Real coneWidth,
                            LightingModel sceneModel, bool litPerPoint) {
  const Object& object = *h.object;
  std::optional<Color4> vertexColor;
  if (!object.mesh->colors.empty()) {
    const auto& c = object.mesh->colors;
    vertexColor = h.w[0] * c[h.index[0]] + h.w[1] * c[h.index[1]] + h.w[2] * c[h.index[2]];
  }
  PointMaterial point = materialAt(object, sceneModel, litPerPoint, vertexColor ? &*vertexColor : nullptr,
                                   [&](const Texture& texture) { return texelAt(texture, mesh, h, ray, cone, coneWidth); });
  if (point.normalTexel) {
    const auto& uvs = object.mesh->uvs;
    const TangentFrame frame =
        triangleTangents({mesh.positions[h.index[0]], mesh.positions[h.index[1]], mesh.positions[h.index[2]]},
                         {uvs[h.index[0]], uvs[h.index[1]], uvs[h.index[2]]});
    h.normal = normalFromMap(h.normal, frame, *point.normalTexel, object.maps.normalScale);
  }
  return point;
}

}  // namespace illum
