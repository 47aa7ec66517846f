#include "trace/ambient_occlusion.h"

#include "trace/ray_scene.h"
#include "trace/sampling.h"
#include "trace/surface_hit.h"

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

TracedOcclusion::TracedOcclusion(const Scene& scene)
    : rays_(std::make_unique<RayScene>(scene)), distance_(occlusionDistance(scene)),
      count_(std::clamp(scene.ambientOcclusion.rays, 1, 256)) {}

TracedOcclusion::~TracedOcclusion() = default;

void TracedOcclusion::open(std::size_t count, const Real* const position[3], const Real* const normal[3],
                           const std::uint64_t* seed, Real* open) const {
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 P(position[0][i], position[1][i], position[2][i]);
    const Vec3 N(normal[0][i], normal[1][i], normal[2][i]);
    // (The interpolated normal stands for the facet too: the rays leave on the side it faces.)
    open[i] = openShare(*rays_, P, N, N, count_, distance_, sampleSeed(int(seed[i] >> 32), int(seed[i]), 0, 7));
  }
}

}  // namespace illum
