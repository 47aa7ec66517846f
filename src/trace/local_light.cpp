#include "trace/local_light.h"

#include "trace/optics.h"

#include <cmath>

namespace illum {
namespace {

// Hall's transmitted highlight of one light behind the surface (N·L < 0), attenuation and spot
// applied by the caller.
Color3 transmittedHighlight(const LocalSurface& s, const EyeLight& light, const Vec3& L, const HallSurface& hall) {
  const Vec3& N = s.geometry.normal;
  const Vec3& V = s.geometry.toViewer;
  Vec3 H = -(hall.etaBeyond * L + hall.etaViewer * V);
  const Real len = glm::length(H);
  if (!(len > Real(1e-6))) return Color3(0);
  H /= len;
  if (glm::dot(H, N) < 0) H = -H;
  const Real Ft = 1 - fresnelDielectric(std::abs(glm::dot(V, H)), hall.etaViewer, hall.etaBeyond);
  const Real NoH = std::max(Real(0), glm::dot(N, H));
  const Real lobe = NoH == 0 && hall.transmissionShininess == 0 ? Real(1) : std::pow(NoH, hall.transmissionShininess);
  return (Ft * lobe) * Color3(s.material.specular) * light.specular;
}

}  // namespace

LightingTerms localTerms(std::span<const EyeLight> lights, const LightModel& lightModel, LightingModel model,
                         const LocalSurface& s, const LightVisibility* visibility, const HallSurface* hall) {
  // Emission and the global ambient: the equation without its lights.
  LightingTerms terms = evaluateTerms({}, lightModel, s.material, model, s.geometry);
  for (const EyeLight& light : lights) {
    LightingTerms one;
    LightDetail detail;
    accumulateLight(one, light, s.material, model, s.geometry, &detail, lightModel.convention);
    terms.ambient = terms.ambient + one.ambient;  // a light's ambient term reaches every point
    const Real scale = detail.attenuation * detail.spot;
    const bool lit = one.diffuse != Color3(0) || one.specular != Color3(0);
    const bool behind = hall && hall->transmits && detail.NoL < 0 && scale > 0;
    if (!lit && !behind) continue;
    const Color3 seen = visibility ? visibility->towards(light, detail.L, detail.distance) : Color3(1);
    if (seen == Color3(0)) continue;
    Color3 specular = one.specular;
    if (hall && lit) {
      // Hall: the highlight is the light the surface reflects, F_r of the angle between L and H.
      const Vec3 H = detail.L + s.geometry.toViewer;
      const Real len = glm::length(H);
      const Real LoH = len > Real(1e-6) ? glm::dot(detail.L, H) / len : Real(1);
      specular = specular * fresnelDielectric(LoH, hall->etaViewer, hall->etaBeyond);
    }
    terms.diffuse = terms.diffuse + seen * one.diffuse;
    terms.specular = terms.specular + seen * specular;
    if (behind) terms.specular = terms.specular + (scale * seen) * transmittedHighlight(s, light, detail.L, *hall);
  }
  return terms;
}

}  // namespace illum
