// Recursive ray tracing after Whitted (1980) and Hall and Greenberg (1983), in eye space:
//   Whitted: I = local + k_r·R + k_t·T
//   Hall:    I = local_Hall + k_r·F_r·R·T_r^d_r + k_t·F_t·T·T_t^d_t
// where local is GL's equation with shadow rays (local_light.h), R and T the colours the mirror
// and the refracted ray bring back, F_r the exact dielectric Fresnel reflectance (F_t = 1 − F_r)
// and T_r, T_t the filter transmittance over the distance d a ray travels inside a medium.
#pragma once

#include <illum/render.h>
#include <illum/scene.h>

#include "trace/ray_scene.h"
#include "trace/surface_hit.h"

#include <cstdint>
#include <vector>

namespace illum {

struct RayCounts {
  std::uint64_t primary = 0, secondary = 0, shadow = 0;
  RayCounts& operator+=(const RayCounts& o) {
    primary += o.primary, secondary += o.secondary, shadow += o.shadow;
    return *this;
  }
};

class WhittedTracer {
 public:
  WhittedTracer(const Scene& scene, const RayScene& rays);

  // The colour (unclamped) and alpha seen along a primary ray whose first hit is `hit` (null: a
  // miss). Primary rays light with GL's viewer direction, so that without shadows, mirrors and
  // glass the colour is the rasterizer's Phong-shaded pixel.
  // With `probe`, what the primary hit computed is recorded there (--debug-pixel).
  Color4 primary(const Ray& ray, const RayHit* hit, const RayCone& cone, RayCounts& counts,
                 PixelProbe* probe = nullptr) const;

 private:
  struct Path;
  Color4 shade(const Ray& ray, const RayHit& hit, const Path& path, RayCounts& counts,
               PixelProbe* probe = nullptr) const;
  Color4 trace(const Ray& ray, const Path& path, RayCounts& counts) const;

  const Scene& scene_;
  const RayScene& rays_;
  std::vector<EyeLight> lights_;
  LightModel lightModel_;  // the scene's, with its environment's image-based light for this view
  Mat3 environmentFromEye_{1};
  bool hall_;
};

}  // namespace illum
