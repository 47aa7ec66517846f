// Random numbers and the sample warps of Monte Carlo path tracing. Every pixel sample draws from
// its own generator, seeded by (pixel, sample) alone, so pictures do not depend on threads.
#pragma once

#include <illum/real.h>

#include <array>
#include <cmath>
#include <cstdint>

namespace illum {

// A 32-bit fraction's top 24 bits as a Real in [0, 1): exact in float.
inline Real unitFraction(std::uint32_t v) { return Real(v >> 8) * Real(1.0 / (1u << 24)); }

// SplitMix64's finalizer: every bit of the result depends on every bit of v.
constexpr std::uint64_t mixedBits(std::uint64_t v) {
  v = (v ^ (v >> 30)) * 0xBF58476D1CE4E5B9ull;
  v = (v ^ (v >> 27)) * 0x94D049BB133111EBull;
  return v ^ (v >> 31);
}

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
  Real uniform() { return unitFraction(next()); }

 private:
  std::uint64_t state_ = 0, inc_;
};

// A pixel sample's seed: a hash of (x, y, sample, salt) alone (SplitMix64's finalizer), so that
// jitter, paths and occlusion rays are the same on every run and thread count.
inline std::uint64_t sampleSeed(int x, int y, int sample, std::uint64_t salt) {
  return mixedBits((std::uint64_t(std::uint32_t(x)) << 40) ^ (std::uint64_t(std::uint32_t(y)) << 20) ^
                   std::uint64_t(std::uint32_t(sample)) ^ (salt * 0x9E3779B97F4A7C15ull));
}

// A salt of sampleSeed for the picture of seed `pictureSeed` (RayTracing::seed): another hash
// for every seed, and for 0 the salt itself, the pictures of every earlier version.
constexpr std::uint64_t seededSalt(std::uint64_t salt, std::uint32_t pictureSeed) {
  return salt ^ (std::uint64_t(pictureSeed) << 32);
}

// The seed of pixel (x, y)'s own scrambling, of its sample points and of its paths' stratified
// pairs (stratifiedPair) alike.
inline std::uint64_t pixelSeed(int x, int y, std::uint32_t pictureSeed) {
  return sampleSeed(x, y, 0, seededSalt(1, pictureSeed));
}

// The bits of v in reverse order (bit 31 ↔ bit 0).
constexpr std::uint32_t reversedBits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
  v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
  return (v >> 16) | (v << 16);
}

// Owen's nested uniform scrambling of a 32-bit fraction: each digit flipped by a hash of the
// digits above it, so that a scrambled (0,m,2)-net is still one (Burley, "Practical Hash-based
// Owen Scrambling", JCGT 9(4) 2020: Laine and Karras's permutation on the reversed bits).
// laineKarras is that permutation: each bit flipped by a hash of the bits below it.
constexpr std::uint32_t laineKarras(std::uint32_t v, std::uint32_t seed) {
  v += seed;
  v ^= v * 0x6c50b47cu;
  v ^= v * 0xb82f1e52u;
  v ^= v * 0xc7afe638u;
  v ^= v * 0x8d22f6e6u;
  return v;
}
constexpr std::uint32_t owenScrambled(std::uint32_t v, std::uint32_t seed) {
  return reversedBits(laineKarras(reversedBits(v), seed));
}

// Sobol's second dimension, byte by byte: entry b of table k is the XOR of the generator matrix's
// columns (Pascal's matrix mod 2: each column the last one XOR itself shifted right once) for the
// set bits of b, taken as bits 8k..8k+7 of the index.
struct SobolSecondDimension {
  std::array<std::array<std::uint32_t, 256>, 4> byByte{};
  constexpr SobolSecondDimension() {
    std::array<std::uint32_t, 32> column{};
    column[0] = 1u << 31;
    for (int j = 1; j < 32; ++j) column[std::size_t(j)] = column[std::size_t(j - 1)] ^ (column[std::size_t(j - 1)] >> 1);
    for (std::size_t k = 0; k < 4; ++k)
      for (std::uint32_t b = 0; b < 256; ++b)
        for (std::size_t j = 0; j < 8; ++j)
          if (b >> j & 1) byByte[k][b] ^= column[8 * k + j];
  }
};
inline constexpr SobolSecondDimension kSobolSecondDimension{};

// Point `index` of Sobol's sequence in two dimensions (van der Corput's radical inverse in base 2,
// and the dimension of Pascal's matrix), as 32-bit fractions: every first 2^m points put one point
// in each of the 2^m elementary intervals of area 2^−m (for 16: each cell of a 4×4 grid, and of
// the 2×8, 8×2, 1×16 and 16×1 grids); so does every aligned block of 2^m points.
inline std::array<std::uint32_t, 2> sobol2D(std::uint32_t index) {
  const auto& t = kSobolSecondDimension.byByte;
  return {reversedBits(index), t[0][index & 255] ^ t[1][index >> 8 & 255] ^ t[2][index >> 16 & 255] ^ t[3][index >> 24]};
}

// Where sample `sample` of pixel (x, y) lies in the pixel, in [0, 1)²: Sobol's points, Owen-scrambled
// by seeds of the pixel's own. A pixel's samples are stratified, so that an edge's coverage and a
// texture's footprint come out far less noisy than from independent points (the error of a pixel
// on an edge falls as N^−3/4 instead of N^−1/2), and no two pixels share a pattern.
inline Vec2 pixelSampleOffset(int x, int y, int sample, std::uint32_t pictureSeed = 0) {
  const std::uint64_t seeds = pixelSeed(x, y, pictureSeed);
  const std::array<std::uint32_t, 2> p = sobol2D(std::uint32_t(sample));
  return {unitFraction(owenScrambled(p[0], std::uint32_t(seeds))), unitFraction(owenScrambled(p[1], std::uint32_t(seeds >> 32)))};
}

// Pair `dimension` (≥ 1) of sample `index` of the pixel whose samples `pixelSeed` seeds: Sobol's
// points in an order shuffled per pixel and dimension (the index Owen-scrambled, which maps every
// aligned block of 2^m indices onto one, so every power-of-two prefix is still a net), each
// coordinate Owen-scrambled (Burley 2020). Different dimensions are so decorrelated from each
// other and from the pixel's own offsets (pair 0, pixelSampleOffset).
inline Vec2 stratifiedPair(std::uint64_t pixelSeed, std::uint32_t dimension, std::uint32_t index) {
  const std::uint64_t h = mixedBits(pixelSeed ^ (std::uint64_t(dimension) * 0x9E3779B97F4A7C15ull));
  const std::uint32_t shuffled = owenScrambled(index, std::uint32_t(h));
  const std::uint32_t seedX = std::uint32_t(h >> 32), seedY = std::uint32_t(h >> 32) * 0x2C1B3C6Du + 0x297A2D39u;
  // The first coordinate is the reversed index (van der Corput's), so its scrambling's own
  // reversal cancels: owenScrambled(reversedBits(i), s) = reversedBits(laineKarras(i, s)).
  return {unitFraction(reversedBits(laineKarras(shuffled, seedX))), unitFraction(owenScrambled(sobol2D(shuffled)[1], seedY))};
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
