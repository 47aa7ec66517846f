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
#include "trace/sampling.h"
#include "trace/surface_hit.h"
#include "trace/whitted.h"

#include <optional>
#include <vector>

namespace illum {

// What the denoiser is guided by: the albedo and the eye-space normal (towards the viewer) where
// the path first met a surface that is not wholly an ideal mirror or glass; 0 where it met none.
// Where that surface is a part mirror (both of its parts are then followed: PathTracer::walk),
// what came back along the mirror is kept apart (`mirroredRadiance`, part of the path's radiance)
// with the guides of what it saw (the same rule past the mirror; where the ray escaped, no albedo
// and its direction for a normal), so that the denoiser filters a polished floor's reflections by
// the reflected objects' edges, not the floor's.
// `direct` is what that first surface took from point, spot and directional lights (each sampled
// there, up to 16 of them: PathTracer::walk) where the camera saw it, straight or through ideal
// mirrors: exact but for where in the pixel the ray went, so the denoiser leaves it unfiltered and
// a hard shadow's edge or a highlight stays as sharp as the samples drew it. It is 0 where one
// light was drawn for many or the path went through glass (a choice among its samples).
struct PathFeatures {
  Color3 direct{0};
  Color3 albedo{0};
  Vec3 normal{0};
  Real depth = 0;  // the distance from the eye to that surface
  bool mirrored = false;
  Color3 mirroredRadiance{0};
  Color3 mirrorAlbedo{0};
  Vec3 mirrorNormal{0};
};

class PathBsdf;

// The denoiser's guides at a first surface that is not wholly ideal (PathFeatures' albedo,
// normal and depth, as a path's first sample of it finds them), and its `direct` light as a
// path's would be (0 where one light is drawn for many).
struct SurfaceGuides {
  Color3 albedo{0};
  Vec3 normal{0};
  Real depth = 0;
  Color3 direct{0};
};

// A surface's ideal part: its weight k (k_t for glass, else k_r: the rest is its BSDF's), and
// k's luminance, the chance that a path follows it (0: none, 1: the surface is wholly ideal).
Color3 idealWeight(const SurfaceOptics& optics);
Real idealChance(const SurfaceOptics& optics);
// Whether a scene has a part mirror or glass (0 < chance < 1), whose reflection the denoiser
// filters as a layer of its own.
bool hasPartMirrors(const Scene& scene);

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
  // The guides a path along this primary ray would record, and its first surface's direct light
  // (no path on from there): none where the first surface is wholly ideal (a mirror's or glass's
  // guides lie past it).
  std::optional<SurfaceGuides> firstSurfaceGuides(const Ray& ray, const RayHit& hit, const RayCone& cone,
                                                  RayCounts& counts) const;

 private:
  // A surface as a path sees it: the hit, the ray's length to it and the way back to its origin,
  // the material there (textures and vertex colours applied), what it emits towards the ray, and
  // its facet's and shading normals turned to the ray's side.
  struct Surface {
    HitPoint h;
    Real length = 0;
    Vec3 wo{0};
    Material material;
    LightingModel model{};
    Color3 emission{0};
    Vec3 Ng{0}, N{0};
    // Whether light along wi leaves (or arrives) above both the shading normal and the facet.
    bool leaves(const Vec3& wi) const { return glm::dot(wi, N) > 0 && glm::dot(wi, Ng) > 0; }
  };
  Surface surfaceAt(const Ray& ray, const RayHit& hit, const RayCone& cone) const;
  // The denoiser's albedo of a surface: its BSDF's, its ideal part k and its emission (up to 1).
  static Color3 guideAlbedo(const PathBsdf& bsdf, const Color3& k, const Color3& emission);
  // What a surface reflects towards its viewer of a point, spot or directional light, times the
  // path's throughput `beta` and `weight` (the lights it stands for): 0 where the light is behind
  // the surface, out of its cone or blocked.
  Color3 lightFrom(const EyeLight& light, const Surface& s, const PathBsdf& bsdf, const Color3& beta, Real weight,
                   RayCounts& counts) const;

  // A path at a surface: the ray that found it and its hit, the ray cone, the throughput, the pdf
  // of the direction that led here, whether nothing but that direction could have found a light
  // (after a camera ray or an ideal mirror or refraction), the bounce, and the denoiser's guides
  // still to be found: the first surface's and, past a part mirror there, the mirror's.
  struct Walk {
    Ray ray;
    RayHit hit;
    RayCone cone;
    Color3 beta{1};
    Real bsdfPdf = 0;
    bool lightHitWhole = true;
    int depth = 0;
    bool splits = false;  // a part mirror at the first surface that is not wholly ideal is split there
    PathFeatures* features = nullptr;
    PathFeatures* mirrorGuides = nullptr;
    Color3* direct = nullptr;  // where the first surface's light from point, spot and directional lights goes
  };
  // The radiance the walk gathers from its surface on.
  Color3 walk(Walk w, Rng& rng, RayCounts& counts, const PathSample& sample) const;

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
