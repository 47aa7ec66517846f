#include "trace/whitted.h"

#include "scene/environment_use.h"

#include "trace/local_light.h"
#include "trace/optics.h"
#include "trace/surface_hit.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

// Rays whose weight in the pixel falls below this are not traced: they could not change a byte
// (Hall and Greenberg's adaptive depth control).
constexpr Real kMinWeight = Real(1) / 512;
// At most this many reflected, refracted and see-through rays per primary ray (a full tree of
// depth 6 has 126): with k_r = k_t = 1 Whitted's tree doubles at every level, and no scene may ask
// for unbounded work.
constexpr int kMaxSecondaryRays = 128;
// Shadow rays pass through at most this many transmissive surfaces (Hall).
constexpr int kMaxShadowCrossings = 16;

Real maxComponent(const Color3& c) { return std::max({c.r, c.g, c.b}); }

Color3 powColor(const Color3& base, Real exponent) {
  return {std::pow(base.r, exponent), std::pow(base.g, exponent), std::pow(base.b, exponent)};
}


// Shadow rays from one point: whether each light is seen. Whitted: any surface in between casts
// a shadow. Hall: transmissive surfaces let k_t of the light through, filtered inside.
class ShadowRays final : public LightVisibility {
 public:
  ShadowRays(const RayScene& rays, const HitPoint& at, bool hall, RayCounts& counts)
      : rays_(rays), at_(at), hall_(hall), counts_(counts) {}

  Color3 towards(const EyeLight&, const Vec3& L, Real distance) const override {
    Ray ray;
    ray.origin = offsetOrigin(at_.position, at_.geometricNormal, L);
    ray.direction = L;
    const Real end = distance > 0 ? distance : std::numeric_limits<Real>::infinity();
    ray.tFar = end;
    ++counts_.shadow;
    if (!hall_) return rays_.occluded(ray) ? Color3(0) : Color3(1);
    Color3 through(1);
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
      RayHit hit;
      if (!rays_.intersect(ray, hit)) return through;
      const HitPoint h = hitPoint(rays_, ray, hit);
      const SurfaceOptics& optics = h.object->optics;
      if (!optics.transmits()) return Color3(0);
      through *= optics.transmissive;
      // Leaving a medium through its back face: the light crossed it for the distance since entry.
      if (!h.front) through *= powColor(optics.filter, hit.t);
      if (maxComponent(through) < kMinWeight) return Color3(0);
      ray.origin = offsetOrigin(h.position, h.geometricNormal, L);
      if (distance > 0) {
        ray.tFar = end - glm::length(h.position - at_.position);
        if (!(ray.tFar > 0)) return through;
      }
      ++counts_.shadow;
    }
    return Color3(0);
  }

 private:
  const RayScene& rays_;
  const HitPoint& at_;
  bool hall_;
  RayCounts& counts_;
};

}  // namespace

struct WhittedTracer::Path {
  int depth = 0;
  Color3 weight{1};     // of this ray in the pixel
  RayCone cone;
  bool primary = false;
  int* budget = nullptr;  // secondary rays left for this primary ray
};

WhittedTracer::WhittedTracer(const Scene& scene, const RayScene& rays)
    : scene_(scene), rays_(rays), hall_(scene.renderer == RendererKind::Hall) {
  const Mat4 viewFromWorld = scene.camera.viewFromWorld();
  for (const Light& l : scene.lights) lights_.push_back(toEyeSpace(l, viewFromWorld));
  lightModel_ = scene.lightModel;
  lightModel_.environment = eyeImageLight(scene, viewFromWorld);
  environmentFromEye_ = environmentFromEye(scene, viewFromWorld);
}

Color4 WhittedTracer::primary(const Ray& ray, const RayHit* hit, const RayCone& cone, RayCounts& counts,
                              PixelProbe* probe) const {
  ++counts.primary;
  int budget = kMaxSecondaryRays;
  Path path;
  path.primary = true;
  path.cone = cone;
  path.budget = &budget;
  if (!hit) return scene_.background;
  return shade(ray, *hit, path, counts, probe);
}

Color4 WhittedTracer::trace(const Ray& ray, const Path& path, RayCounts& counts) const {
  ++counts.secondary;
  --*path.budget;
  RayHit hit;
  if (!rays_.intersect(ray, hit)) {
    // A mirror or refracted ray that leaves the scene sees the environment where it lights it.
    if (lightModel_.environment)
      return {environmentRadiance(scene_, environmentFromEye_, glm::normalize(ray.direction), false), 1};
    return scene_.background;
  }
  return shade(ray, hit, path, counts);
}

Color4 WhittedTracer::shade(const Ray& ray, const RayHit& rayHit, const Path& path, RayCounts& counts,
                            PixelProbe* probe) const {
  HitPoint h = hitPoint(rays_, ray, rayHit);
  const EyeMesh& mesh = rays_.mesh(rayHit.object);
  const Object& object = *h.object;
  const SurfaceOptics& optics = object.optics;
  const Real length = rayHit.t * glm::length(ray.direction);
  const Vec3 D = glm::normalize(ray.direction);

  // The local equation, as the rasterizer's Phong shading evaluates it at a pixel: the material
  // there (vertex colours, texel, maps), the normal of the side shown under two-sided lighting.
  const PointMaterial point =
      materialAtHit(mesh, h, ray, path.cone, path.cone.width + path.cone.spread * length, scene_.model);
  const Material& material = point.material;
  const LightingModel model = point.model;
  LocalSurface local;
  local.material = material;
  local.geometry.position = h.position;
  local.geometry.normal = lightModel_.twoSided && !h.front ? -h.normal : h.normal;
  // GL's viewer for primary rays (infinite unless local_viewer); the ray's origin for the others.
  local.geometry.toViewer = path.primary ? viewerDirection(h.position, lightModel_) : -D;
  const Real etaOutside = 1, etaInside = optics.ior;
  HallSurface hall;
  hall.etaViewer = h.front ? etaOutside : etaInside;
  hall.etaBeyond = h.front ? etaInside : etaOutside;
  hall.transmissionShininess = optics.transmissionShininess.value_or(material.shininess);
  hall.transmits = optics.transmits();
  // Hall's Fresnel-weighted and transmitted highlights, for the classic models' mirrors and glass
  // (cook-torrance's own highlight already carries Fresnel's F).
  const bool hallSurface = hall_ && model != LightingModel::CookTorrance && (optics.reflects() || optics.transmits());
  const ShadowRays shadows(rays_, h, hall_, counts);
  const LightingTerms terms = localTerms(lights_, lightModel_, model, local,
                                         scene_.rayTracing.shadows ? &shadows : nullptr, hallSurface ? &hall : nullptr);
  Color4 color = clampedColor(terms, material);
  color *= point.modulation();
  if (probe) {
    probe->hit = true;
    probe->object = rayHit.object;
    probe->triangle = rayHit.triangle;
    probe->frontFacing = h.front;
    probe->eyePosition = h.position;
    probe->eyeNormal = local.geometry.normal;
    probe->material = material;
    probe->weights = h.w;
    probe->textured = point.textured;
    probe->texel = point.texel;
    probe->texelIsBaseColor = point.texelIsBaseColor;
    probe->lit = color;
    probe->lightVisibility.clear();
    for (const EyeLight& light : lights_) {
      LightingTerms unused;
      LightDetail d;
      accumulateLight(unused, light, material, model, local.geometry, &d, lightModel_.convention);
      probe->lightVisibility.push_back(scene_.rayTracing.shadows ? shadows.towards(light, d.L, d.distance) : Color3(1));
    }
  }

  // Mirror and glass: the rays the surface sends on, each weighted by what it carries to the pixel.
  Color3 rgb(color);
  // A ray the surface sends on, weighed `k` in this ray's colour: what it brings back, or nothing
  // when its weight in the pixel is too small or the primary ray's budget is spent.
  const auto follow = [&](const Vec3& direction, const Color3& k, bool primary) -> std::optional<Color4> {
    const Color3 weight = path.weight * k;
    if (maxComponent(weight) < kMinWeight || *path.budget <= 0) return std::nullopt;
    Ray next;
    next.origin = offsetOrigin(h.position, h.geometricNormal, direction);
    next.direction = direction;
    Path nextPath = path;
    nextPath.depth = path.depth + 1;
    nextPath.weight = weight;
    nextPath.primary = primary;
    nextPath.cone.width = path.cone.width + path.cone.spread * length;
    nextPath.cone.differentials = primary && path.cone.differentials;  // the camera's next pixels still apply
    return trace(next, nextPath, counts);
  };
  if (path.depth < scene_.rayTracing.maxDepth && (optics.reflects() || optics.transmits())) {
    // The interpolated normal, turned to face the incoming ray.
    const Vec3 N = glm::dot(h.normal, D) > 0 ? -h.normal : h.normal;
    const std::optional<Vec3> refracted = refractDirection(D, N, hall.etaViewer, hall.etaBeyond);
    Color3 kr = optics.reflective, kt = optics.transmissive;
    if (hall_) {
      const Real Fr = fresnelDielectric(-glm::dot(N, D), hall.etaViewer, hall.etaBeyond);  // 1 under TIR
      kr *= Fr;
      kt *= 1 - Fr;
    } else if (!refracted) {
      kr += kt;  // total internal reflection: the transmitted share goes to the mirror ray
    }
    if (!refracted) kt = Color3(0);
    // Interpolated normals tilt away from the true surface near silhouettes, where a mirror ray
    // could point into the surface it leaves (or a refracted one out of it): such a ray is turned
    // back across the triangle's plane instead of hitting its own surface.
    const Vec3 Ng = glm::dot(h.geometricNormal, D) > 0 ? -h.geometricNormal : h.geometricNormal;
    const auto keepSide = [&](Vec3 direction, bool above) {
      const Real side = glm::dot(direction, Ng);
      return (side > 0) == above ? direction : glm::normalize(direction - 2 * side * Ng);
    };
    const auto add = [&](const Vec3& direction, const Color3& k) {
      rgb += k * Color3(follow(direction, k, false).value_or(Color4(0)));
    };
    if (kr != Color3(0)) add(keepSide(reflectDirection(D, N), true), kr);
    if (kt != Color3(0)) add(keepSide(*refracted, false), kt);
  }
  Real alpha = color.a;
  // GL blending's counterpart: a translucent surface lets (1 − α) of what lies behind through.
  if (scene_.blend && color.a < 1 && path.depth < kMaxRayDepth) {
    // A primary ray seen through a translucent surface keeps GL's viewer.
    const Color4 behind = follow(D, Color3(1 - color.a), path.primary).value_or(scene_.background);
    rgb = color.a * rgb + (1 - color.a) * Color3(behind);
    alpha = color.a + behind.a * (1 - color.a);
  }
  // Hall: light coming back out of a medium was filtered over the distance it travelled inside.
  if (hall_ && !h.front && optics.transmits()) rgb *= powColor(optics.filter, length);
  if (probe) probe->written = {rgb, alpha};
  return {rgb, alpha};
}

}  // namespace illum
