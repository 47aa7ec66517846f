// Random numbers and the sample warps of Monte Carlo path tracing. Every pixel sample draws from
// its own generator, seeded by (pixel, sample) alone, so pictures do not depend on threads.
#pragma once

#include <illum/real.h>

#include <cmath>
#include <cstdint>

namespace illum {

// PCG32 (O'Neill 2014): small, fast and statistically good; one stream per pixel sample.
class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t stream) : inc_((stream << 1u) | 1u) {
    next();
    state_ += seed;
    next();
  }
  std::uint32_t next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = std::uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
  }
  // Uniform in [0, 1).
  Real uniform() { return Real(next() >> 8) * Real(1.0 / (1u << 24)); }

 private:
  std::uint64_t state_ = 0, inc_;
};

// A pixel sample's seed: a hash of (x, y, sample, salt) alone (SplitMix64's finalizer), so that
// jitter, paths and occlusion rays are the same on every run and thread count.
inline std::uint64_t sampleSeed(int x, int y, int sample, std::uint64_t salt) {
  std::uint64_t r = (std::uint64_t(std::uint32_t(x)) << 40) ^ (std::uint64_t(std::uint32_t(y)) << 20) ^
                    std::uint64_t(std::uint32_t(sample)) ^ (salt * 0x9E3779B97F4A7C15ull);
  r = (r ^ (r >> 30)) * 0xBF58476D1CE4E5B9ull;
  r = (r ^ (r >> 27)) * 0x94D049BB133111EBull;
  return r ^ (r >> 31);
}

// An orthonormal basis around a unit normal (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017).
struct Frame {
  Vec3 t, b, n;
  explicit Frame(const Vec3& normal) : n(normal) {
    const Real sign = std::copysign(Real(1), n.z);
    const Real a = -1 / (sign + n.z), c = n.x * n.y * a;
    t = Vec3(1 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = Vec3(c, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toWorld(const Vec3& v) const { return v.x * t + v.y * b + v.z * n; }
  Vec3 toLocal(const Vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
};

constexpr Real kPiReal = Real(3.14159265358979323846);

// Relative luminance of linear Rec. 709 RGB: how bright a colour is, for choosing among lights.
inline Real luminance(const Vec3& c) { return Real(0.2126) * c.r + Real(0.7152) * c.g + Real(0.0722) * c.b; }

// Cosine-weighted direction about +z: pdf = cos θ / π (Malley's method).
inline Vec3 sampleCosineHemisphere(Real u1, Real u2) {
  const Real r = std::sqrt(u1), phi = 2 * kPiReal * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(Real(0), 1 - u1))};
}

// A uniform point on a triangle as barycentric weights (b0, b1), b2 = 1 − b0 − b1.
inline Vec2 sampleTriangle(Real u1, Real u2) {
  const Real s = std::sqrt(u1);
  return {1 - s, u2 * s};
}

// Veach's power heuristic (β = 2) for two sampling techniques.
inline Real powerHeuristic(Real pdfA, Real pdfB) {
  const Real a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0 ? a / (a + b) : 0;
}

// A GGX visible normal in the local frame of the view vector v (z up), Heitz, "Sampling the GGX
// Distribution of Visible Normals", JCGT 7(4) 2018, for isotropic α.
inline Vec3 sampleGgxVisibleNormal(const Vec3& v, Real alpha, Real u1, Real u2) {
  const Vec3 vh = glm::normalize(Vec3(alpha * v.x, alpha * v.y, v.z));
  const Real lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3 T1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
  const Vec3 T2 = glm::cross(vh, T1);
  const Real r = std::sqrt(u1), phi = 2 * kPiReal * u2;
  const Real t1 = r * std::cos(phi);
  Real t2 = r * std::sin(phi);
  const Real s = Real(0.5) * (1 + vh.z);
  t2 = (1 - s) * std::sqrt(std::max(Real(0), 1 - t1 * t1)) + s * t2;
  const Vec3 nh = t1 * T1 + t2 * T2 + std::sqrt(std::max(Real(0), 1 - t1 * t1 - t2 * t2)) * vh;
  return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(Real(1e-6), nh.z)));
}

}  // namespace illum
