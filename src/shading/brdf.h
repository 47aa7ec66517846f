// The reflection lobes of the classic models, one small named function each (Filament style).
// Each returns the scalar factor that multiplies light colour × material colour.
#pragma once

#include <illum/real.h>

#include <algorithm>
#include <cmath>

namespace illum {

// Lambert's cosine law: reflected intensity ∝ cos θ = N·L, never negative.
// J. H. Lambert, Photometria (1760); OpenGL 2.1 §2.14.1, the term (n ⊙ VP_pli).
inline Real Fd_Lambert(Real NoL) { return std::max(NoL, Real(0)); }

// max(x, 0)^n, the lobes' common form: the values std::pow gives, with its exact cases (0^n and
// 1^n, common where a light is behind or straight along the lobe) answered without the call.
inline Real powLobe(Real x, Real n) {
  if (x <= 0) return n == 0 ? Real(1) : Real(0);  // pow(0, 0) = 1, pow(0, n > 0) = 0
  if (x == 1) return Real(1);                      // pow(1, n) = 1
  return std::pow(x, n);
}

// Phong's specular lobe (R·V)^n with R = 2N(N·L) − L.
// B. T. Phong, "Illumination for computer generated pictures", CACM 18(6), 1975.
// std::pow(0, 0) is 1, as GL requires for a shininess of 0.
inline Real Fs_Phong(Real RoV, Real shininess) { return powLobe(RoV, shininess); }

// Blinn's halfway-vector lobe (N·H)^n with H = normalize(L + V).
// J. F. Blinn, "Models of light reflection for computer synthesized pictures", SIGGRAPH 1977;
// OpenGL 2.1 §2.14.1, the term (n ⊙ ĥ_i)^s_rm. std::pow(0, 0) is 1.
inline Real Fs_BlinnPhong(Real NoH, Real shininess) { return powLobe(NoH, shininess); }

// Distance attenuation 1 / (k_c + k_l·d + k_q·d²) for positional lights (OpenGL 2.1 §2.14.1).
// With k = (0,0,1) it is the inverse-square law I/r².
inline Real distanceAttenuation(const Vec3& k, Real d) { return Real(1) / (k.x + k.y * d + k.z * d * d); }

// Spotlight factor: (max(−L·S, 0))^e inside the cone, 0 outside (OpenGL 2.1 §2.14.1).
// cosCutoff ≤ -1 (cutoff 180) means no spot.
inline Real spotFactor(Real minusLoS, Real cosCutoff, Real exponent) {
  if (minusLoS < cosCutoff) return 0;
  return std::pow(std::max(minusLoS, Real(0)), exponent);
}

}  // namespace illum
