// Ideal specular optics at a smooth interface: the mirror direction, Snell's law and Fresnel's
// equations for an unpolarised dielectric. Directions are unit vectors; N faces the incoming ray.
#pragma once

#include <illum/real.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace illum {

// The mirror direction of D about N: R = D − 2(N·D)N.
inline Vec3 reflectDirection(const Vec3& D, const Vec3& N) { return D - (2 * glm::dot(N, D)) * N; }

// Snell's law, η_i sin θ_i = η_t sin θ_t, for D arriving from the side N faces (N·D < 0):
// T = η D + (η cos θ_i − cos θ_t) N with η = η_i/η_t. None under total internal reflection.
inline std::optional<Vec3> refractDirection(const Vec3& D, const Vec3& N, Real etaI, Real etaT) {
  const Real eta = etaI / etaT;
  const Real cosI = std::min(Real(1), -glm::dot(N, D));
  const Real sin2T = eta * eta * std::max(Real(0), 1 - cosI * cosI);
  if (sin2T >= 1) return std::nullopt;
  const Real cosT = std::sqrt(1 - sin2T);
  return glm::normalize(eta * D + (eta * cosI - cosT) * N);
}

// The fraction of light a smooth dielectric interface reflects, unpolarised (the mean of the s
// and p reflectances), for light meeting it at cos θ_i from the medium of index η_i towards η_t.
// 1 under total internal reflection; ((η_t−η_i)/(η_t+η_i))² at normal incidence.
inline Real fresnelDielectric(Real cosI, Real etaI, Real etaT) {
  cosI = std::clamp(cosI, Real(0), Real(1));
  const Real sinT = etaI / etaT * std::sqrt(std::max(Real(0), 1 - cosI * cosI));
  if (sinT >= 1) return 1;
  const Real cosT = std::sqrt(std::max(Real(0), 1 - sinT * sinT));
  const Real rs = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
  const Real rp = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
  return (rs * rs + rp * rp) / 2;
}

}  // namespace illum
