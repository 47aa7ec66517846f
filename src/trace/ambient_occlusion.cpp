#include "trace/ambient_occlusion.h"

#include "math/unorm8.h"
#include "trace/camera_rays.h"
#include "trace/ray_scene.h"
#include "trace/sampling.h"
#include "trace/surface_hit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace illum {
namespace {

// The open share of the hemisphere around N at P: `rays` cosine-weighted directions, stratified in
// their cosine and spread in azimuth by the golden angle, turned by a per-pixel random offset.
Real openShare(const RayScene& rays, const Vec3& P, const Vec3& N, const Vec3& facet, int count, Real distance,
               std::uint64_t seed) {
  const Frame frame(N);
  Rng rng(seed, seed >> 32);
  const Real turn = rng.uniform(), shift = rng.uniform();
  int open = 0;
  for (int i = 0; i < count; ++i) {
    const Real u1 = (Real(i) + shift) / Real(count);
    Real u2 = turn + Real(i) * Real(0.6180339887498949);
    u2 -= std::floor(u2);
    Vec3 d = frame.toWorld(sampleCosineHemisphere(u1, u2));
    // A direction under the facet (an interpolated normal tilts off it) is mirrored back over it.
    if (!(glm::dot(d, facet) > 0)) d = glm::normalize(d - 2 * glm::dot(d, facet) * facet);
    Ray ray;
    ray.origin = offsetOrigin(P, facet, d);
    ray.direction = d;
    ray.tFar = distance;
    open += !rays.occluded(ray);
  }
  return Real(open) / Real(count);
}

}  // namespace

Real occlusionDistance(const Scene& scene) {
  if (scene.ambientOcclusion.distance) return *scene.ambientOcclusion.distance;
  Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
  for (const Object& o : scene.objects)
    for (const Vec3& p : o.mesh->positions) {
      const Vec3 w(o.worldFromObject * Vec4(p, 1));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
  const Real diagonal = glm::length(hi - lo);
  return std::isfinite(diagonal) && diagonal > 0 ? diagonal / 5 : Real(1);
}

void applyAmbientOcclusion(const Scene& scene, Image& image) {
  if (!scene.ambientOcclusion.enabled || scene.objects.empty()) return;
  const RayScene rays(scene);
  const CameraRays camera(scene.camera, scene.width, scene.height);
  std::vector<EyeLight> lights;
  const Mat4 viewFromWorld = scene.camera.viewFromWorld();
  for (const Light& l : scene.lights) lights.push_back(toEyeSpace(l, viewFromWorld));
  const Real distance = occlusionDistance(scene);
  const int count = std::clamp(scene.ambientOcclusion.rays, 1, 256);
  tbb::parallel_for(0, scene.height, [&](int y) {
    for (int x = 0; x < scene.width; ++x) {
      const Ray ray = camera.through(Real(x) + Real(0.5), Real(y) + Real(0.5));
      RayHit hit;
      if (!rays.intersect(ray, hit)) continue;
      HitPoint h = hitPoint(rays, ray, hit);
      const EyeMesh& mesh = rays.mesh(hit.object);
      const Object& object = *h.object;
      // The material and normal as the rasterizer sees them here.
      const Real length = hit.t * glm::length(ray.direction);
      const RayCone cone{camera.pixelWidthAt(0), camera.pixelWidthAt(1) - camera.pixelWidthAt(0), false, {}, {}};
      const PointMaterial point = materialAtHit(mesh, h, ray, cone, cone.width + cone.spread * length, scene.model,
                                                scene.shading == Shading::Phong);
      const Material& material = point.material;
      const LightingModel model = point.model;
      // Lit on the side the camera sees.
      const Vec3 toEye = -glm::normalize(ray.direction);
      const Vec3 facet = glm::dot(h.geometricNormal, toEye) >= 0 ? h.geometricNormal : -h.geometricNormal;
      const Vec3 N = glm::dot(h.normal, facet) >= 0 ? h.normal : -h.normal;
      const SurfaceGeometry g{h.position, N, viewerDirection(h.position, scene.lightModel.localViewer)};
      const LightingTerms terms = evaluateTerms(lights, scene.lightModel, material, model, g);
      if (terms.ambient == Color3(0)) continue;
      const Real open = openShare(rays, h.position, N, facet, count, distance, sampleSeed(x, y, 0, 7));
      // What the clamped colour loses: min(sum, 1) − min(sum − (1 − k)·a, 1), per channel.
      const Color3 sum = terms.sum(), occluded = sum - (1 - open) * terms.ambient;
      const Color3 loss = glm::min(sum, Color3(1)) - glm::min(occluded, Color3(1));
      const Color3 factor(point.modulation());
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = toUnorm8(Real(p[c]) / 255 - loss[c] * factor[c]);
    }
  });
}

}  // namespace illum
