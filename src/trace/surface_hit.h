// What the ray tracers know of a ray's hit: the point, its normals and barycentrics, interpolated
// as Phong shading interpolates them; where a new ray leaves it; the material there (vertex
// colours, and the texel filtered for the pixel's footprint).
#pragma once

#include <illum/scene.h>

#include "shading/material_at.h"
#include "trace/ray_scene.h"

#include <array>
#include <cstdint>

namespace illum {

// How wide a pixel's footprint is along a path, for texture filtering: a ray cone (Akenine-Möller
// et al. 2019, without curvature), and for primary rays the rays through the next pixel to the
// right and the next one up, whose texture coordinates on the hit's plane are the rasterizer's
// derivatives exactly.
struct RayCone {
  Real width = 0;   // at the ray's origin
  Real spread = 0;  // growth per unit distance
  bool differentials = false;
  Ray right, up;
};

// What a hit needs for shading, interpolated with the hit's barycentrics as Phong shading does.
struct HitPoint {
  const Object* object;
  Vec3 position;            // eye space
  Vec3 normal;              // interpolated, unit (as the rasterizer renormalizes it)
  Vec3 geometricNormal;     // unit, counter-clockwise front
  bool front;               // the ray meets the front (counter-clockwise) side
  std::array<Real, 3> w;    // barycentric weights of the three vertices
  std::array<std::uint32_t, 3> index;
};

HitPoint hitPoint(const RayScene& rays, const Ray& ray, const RayHit& hit);

// A new ray from P leaves the surface on the side `direction` points to: its origin is pushed off
// the surface along the geometric normal by a distance relative to P's magnitude, so that it does
// not hit the triangle it starts on again.
Vec3 offsetOrigin(const Vec3& P, const Vec3& geometricNormal, const Vec3& direction);

// The texel GL_MODULATE multiplies by, filtered for the pixel's footprint on the triangle: for a
// primary ray as the rasterizer finds it, further along a path from the ray cone's width there.
Vec4 texelAt(const Texture& texture, const EyeMesh& mesh, const HitPoint& h, const Ray& ray, const RayCone& cone,
             Real coneWidth);

// The material at a hit (shading/material_at.h): vertex colours, the texel (the base colour of a
// physically based model, else GL_MODULATE's factor) and glTF's maps, each texel filtered as
// texelAt filters; the normal map bends the shading normal `h.normal` in the triangle's tangent
// frame. A ray lights the point itself, as Phong shading does (`litPerPoint`); ambient occlusion
// asks as the rasterizer it corrects lit it.
PointMaterial materialAtHit(const EyeMesh& mesh, HitPoint& h, const Ray& ray, const RayCone& cone, Real coneWidth,
                            LightingModel sceneModel, bool litPerPoint = true);

}  // namespace illum
