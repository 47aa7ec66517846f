// Kajiya's rendering equation (1986), L_o = L_e + ∫ f L_i cos θ dω, solved by Monte Carlo path
// tracing on the ray tracers' scene: next-event estimation towards the scene's point, spot and
// directional lights, its emissive surfaces and an environment map's bright texels (multiple
// importance sampling with the BSDF, Veach's
// power heuristic), BSDF importance sampling (GGX visible normals, the classic lobes, cosine),
// Russian roulette after three bounces, and `environment` radiance where rays escape — what the
// classic models' ambient term stood for.
#pragma once

#include <illum/scene.h>

#include "trace/area_lights.h"
#include "trace/environment_light.h"
#include "trace/ray_scene.h"
#include "trace/surface_hit.h"
#include "trace/whitted.h"

#include <optional>
#include <vector>

namespace illum {

// What the denoiser is guided by: the albedo and the eye-space normal (towards the viewer) where
// the path first met a surface that is not wholly an ideal mirror or glass; 0 where it met none.
struct PathFeatures {
  Color3 albedo{0};
  Vec3 normal{0};
};

// Which sample of which pixel a path is, for its random numbers: at its first surface, the BSDF's,
// the environment's and the area lights' pairs of numbers are stratified over the pixel's samples
// (stratifiedPair); the rest come from the path's own generator.
struct PathSample {
  std::uint64_t seed = 0;       // the path's generator's (sampleSeed of the pixel and the sample)
  std::uint64_t pixelSeed = 0;  // the pixel's, for its stratified pairs
  std::uint32_t index = 0;      // the sample's number in its pixel
};

class PathTracer {
 public:
  PathTracer(const Scene& scene, const RayScene& rays);

  // The radiance (unclamped) and alpha seen along a primary ray whose first hit is `hit` (null: a
  // miss, which shows the background); `sample` picks this pixel sample's random numbers. With
  // `features`, the denoiser's guides along this path too.
  Color4 primary(const Ray& ray, const RayHit* hit, const RayCone& cone, RayCounts& counts, const PathSample& sample,
                 PathFeatures* features = nullptr) const;

 private:
  // The radiance arriving along an escaping ray (eye-space direction).
  Color3 environment(const Vec3& eyeDirection) const;

  const Scene& scene_;
  const RayScene& rays_;
  std::vector<EyeLight> lights_;
  AreaLights area_;
  const EnvironmentMap* environmentMap_ = nullptr;     // the scene's, decoded when this tracer is made
  std::optional<EnvironmentLight> environmentLight_;  // an environment map, sampled as a light
  Mat3 worldFromView_{1};  // to the environment map's space: the view undone, then its rotation
};

}  // namespace illum
