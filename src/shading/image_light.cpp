// The image light's tables, made once per map, and its one-lane queries (the templates of
// image_light-inl.h on one lane of the static target, the bits of every other).
#include "shading/image_light.h"

#include "shading/image_light-inl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>

namespace illum {
namespace {

constexpr Real kPi = Real(3.14159265358979323846);

// Perceptual roughness to the distribution's α, kept off the mirror limit (cook_torrance-inl.h's
// MicrofacetAlpha: the same clamp, so that the table and the lobe of a light agree).
Real alphaOf(Real roughness) {
  const Real r = std::clamp(roughness, Real(0.045), Real(1));
  return r * r;
}

// Van der Corput's radical inverse in base 2: the second coordinate of Hammersley's points.
Real radicalInverse(std::uint32_t bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return Real(double(bits) * 2.3283064365386963e-10);
}

// A GGX-distributed half vector about +Z (Walter et al. 2007), for the i-th of n Hammersley points.
Vec3 sampleGgxHalfVector(int i, int n, Real alpha) {
  const Real u1 = (Real(i) + Real(0.5)) / Real(n), u2 = radicalInverse(std::uint32_t(i));
  const Real phi = 2 * kPi * u1;
  const Real cosTheta = std::sqrt((1 - u2) / (1 + (alpha * alpha - 1) * u2));
  const Real sinTheta = std::sqrt(std::max(Real(0), 1 - cosTheta * cosTheta));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Real ggxDistribution(Real NoH, Real alpha) {
  const Real a2 = alpha * alpha, f = NoH * NoH * (a2 - 1) + 1;
  return a2 / (kPi * f * f);
}

// Smith's height-correlated visibility G / (4 N·L N·V) (brdf-inl.h's V_SmithGGXCorrelated).
Real smithVisibility(Real NoV, Real NoL, Real alpha) {
  const Real a2 = alpha * alpha;
  const Real v = NoL * std::sqrt(NoV * NoV * (1 - a2) + a2), l = NoV * std::sqrt(NoL * NoL * (1 - a2) + a2);
  return Real(0.5) / (v + l);
}

// An orthonormal frame about unit n (Duff et al. 2017).
void frameAbout(const Vec3& n, Vec3& t, Vec3& b) {
  const Real sign = std::copysign(Real(1), n.z);
  const Real a = -1 / (sign + n.z), c = n.x * n.y * a;
  t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// Half the size in each direction, each texel the mean of four.
LatLongImage halved(const LatLongImage& src) {
  LatLongImage dst{std::max(1, src.width / 2), std::max(1, src.height / 2), {}};
  dst.rgb.resize(std::size_t(dst.width) * std::size_t(dst.height) * 3);
  for (int y = 0; y < dst.height; ++y)
    for (int x = 0; x < dst.width; ++x) {
      const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
      const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
      const Vec3 mean = Real(0.25) * (src.texel(x0, y0) + src.texel(x1, y0) + src.texel(x0, y1) + src.texel(x1, y1));
      float* p = dst.rgb.data() + 3 * (std::size_t(y) * std::size_t(dst.width) + std::size_t(x));
      p[0] = float(mean.x), p[1] = float(mean.y), p[2] = float(mean.z);
    }
  return dst;
}

LatLongImage copyOf(const EnvironmentMap& map) {
  LatLongImage image{map.width(), map.height(), {}};
  image.rgb.resize(std::size_t(map.width()) * std::size_t(map.height()) * 3);
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const Vec3 t = map.texel(x, y);
      float* p = image.rgb.data() + 3 * (std::size_t(y) * std::size_t(map.width()) + std::size_t(x));
      p[0] = float(t.x), p[1] = float(t.y), p[2] = float(t.z);
    }
  return image;
}

// The nine harmonics integrated exactly over the texel of column x, row y of a width × height
// latitude-longitude image (θ from +Y, φ as latLongDirection), so that a map's projection is exact
// for its piecewise-constant texels: a uniform map has no band 1 or 2 at all.
std::array<double, 9> shOverTexel(int x, int y, int width, int height) {
  constexpr double pi = 3.14159265358979323846;
  const double t0 = y * pi / height, t1 = (y + 1) * pi / height;
  const double p0 = (double(x) / width - 0.5) * 2 * pi, p1 = (double(x + 1) / width - 0.5) * 2 * pi;
  const auto over = [](double a, double b, auto antiderivative) { return antiderivative(b) - antiderivative(a); };
  // θ factors, each with dω's sin θ.
  const double s1 = over(t0, t1, [](double t) { return -std::cos(t); });                                 // sin
  const double cs = over(t0, t1, [](double t) { return std::sin(t) * std::sin(t) / 2; });                // cos sin
  const double s2 = over(t0, t1, [](double t) { return t / 2 - std::sin(2 * t) / 4; });                  // sin²
  const double s2c = over(t0, t1, [](double t) { return std::pow(std::sin(t), 3) / 3; });                // sin² cos
  const double s3 = over(t0, t1, [](double t) { return -std::cos(t) + std::pow(std::cos(t), 3) / 3; });  // sin³
  const double c2s = over(t0, t1, [](double t) { return -std::pow(std::cos(t), 3) / 3; });               // cos² sin
  // φ factors.
  const double one = p1 - p0;
  const double sn = over(p0, p1, [](double p) { return -std::cos(p); });
  const double cn = over(p0, p1, [](double p) { return std::sin(p); });
  const double sn2 = over(p0, p1, [](double p) { return p / 2 - std::sin(2 * p) / 4; });
  const double cn2 = over(p0, p1, [](double p) { return p / 2 + std::sin(2 * p) / 4; });
  const double sncn = over(p0, p1, [](double p) { return std::sin(p) * std::sin(p) / 2; });
  // x = sin θ sin φ, y = cos θ, z = −sin θ cos φ.
  return {0.282095 * s1 * one,
          0.488603 * cs * one,
          -0.488603 * s2 * cn,
          0.488603 * s2 * sn,
          1.092548 * s2c * sn,
          -1.092548 * s2c * cn,
          0.315392 * (3 * s3 * cn2 - s1 * one),
          -1.092548 * s3 * sncn,
          0.546274 * (s3 * sn2 - c2s * one)};
}

// A square octahedral image (image_light-inl.h's OctahedralUv) of linear RGB.
struct Octahedral {
  int size = 0;
  std::vector<Vec3> texels;  // rows of v, columns of u
  const Vec3& texel(int x, int y) const { return texels[std::size_t(y) * std::size_t(size) + std::size_t(x)]; }
  Vec3 bilinear(const Vec2& uv) const {
    const Real x = std::clamp(uv.x * Real(size) - Real(0.5), Real(-1), Real(size)),
               y = std::clamp(uv.y * Real(size) - Real(0.5), Real(-1), Real(size));
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const Real fx = x - Real(x0), fy = y - Real(y0);
    const auto at = [&](int i, int j) { return texel(std::clamp(i, 0, size - 1), std::clamp(j, 0, size - 1)); };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
  }
};

// OctahedralUv on one direction.
Vec2 octahedralUv(const Vec3& d) {
  const Real s = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  Real px = d.x / s, pz = d.z / s;
  if (d.y < 0) {
    const Real fx = (1 - std::abs(pz)) * (px < 0 ? -1 : 1), fz = (1 - std::abs(px)) * (pz < 0 ? -1 : 1);
    px = fx, pz = fz;
  }
  return {px * Real(0.5) + Real(0.5), pz * Real(0.5) + Real(0.5)};
}

// The unit direction at (u, v) of the octahedral square: OctahedralUv's inverse.
Vec3 octahedralDirection(Real u, Real v) {
  const Real px = 2 * u - 1, pz = 2 * v - 1;
  Vec3 d(px, 1 - std::abs(px) - std::abs(pz), pz);
  if (d.y < 0) d.x = (1 - std::abs(pz)) * (px < 0 ? -1 : 1), d.z = (1 - std::abs(px)) * (pz < 0 ? -1 : 1);
  return glm::normalize(d);
}

Octahedral halved(const Octahedral& src) {
  Octahedral dst{std::max(1, src.size / 2), {}};
  dst.texels.resize(std::size_t(dst.size) * std::size_t(dst.size));
  for (int y = 0; y < dst.size; ++y)
    for (int x = 0; x < dst.size; ++x)
      dst.texels[std::size_t(y) * std::size_t(dst.size) + std::size_t(x)] =
          Real(0.25) * (src.texel(2 * x, 2 * y) + src.texel(2 * x + 1, 2 * y) + src.texel(2 * x, 2 * y + 1) +
                        src.texel(2 * x + 1, 2 * y + 1));
  return dst;
}

// A mip pyramid of the map on the octahedron, for filtered importance sampling (Křivánek and
// Colbert 2008): a sample that stands for a larger solid angle than a texel reads a coarser level.
struct Pyramid {
  std::vector<Octahedral> levels;
  Vec3 at(const Vec3& d, Real lod) const {
    const Real l = std::clamp(lod, Real(0), Real(levels.size() - 1));
    const int l0 = int(l);
    const int l1 = std::min(l0 + 1, int(levels.size()) - 1);
    const Real f = l - Real(l0);
    const Vec2 uv = octahedralUv(d);
    const Vec3 a = levels[std::size_t(l0)].bilinear(uv);
    return f > 0 ? (1 - f) * a + f * levels[std::size_t(l1)].bilinear(uv) : a;
  }
};

// The map seen through the GGX lobe of `roughness` about each texel's direction (N = V = R),
// the samples weighted by N·L as Karis's prefilter weighs them.
Octahedral prefilter(const Pyramid& source, Real roughness, int size) {
  // A narrow lobe reads fine levels of the pyramid, where fewer samples cover it without gaps.
  const int kSamples = roughness < Real(0.5) ? 16 : 32;
  const Real alpha = alphaOf(roughness);
  const Octahedral& base = source.levels.front();
  const Real texelSolidAngle = 4 * kPi / (Real(base.size) * Real(base.size));
  // The lobe's samples about +Z, the same for every texel (V = N): the half vector, and the level
  // of detail the pyramid is read at for the solid angle each stands for.
  struct LobeSample {
    Vec3 h;
    Real lod;
  };
  std::vector<LobeSample> lobe;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 h = sampleGgxHalfVector(i, kSamples, alpha);
    if (2 * h.z * h.z - 1 <= 0) continue;                // N·L = 2 (N·H)² − 1: below the surface
    const Real pdf = ggxDistribution(h.z, alpha) / 4;  // D·(N·H)/(4 V·H), N·H = V·H
    lobe.push_back({h, Real(0.5) * std::log2(1 / (Real(kSamples) * pdf) / texelSolidAngle) + 1});
  }
  Octahedral out{size, std::vector<Vec3>(std::size_t(size) * std::size_t(size))};
  tbb::parallel_for(0, size, [&](int y) {
    for (int x = 0; x < size; ++x) {
      const Vec3 n = octahedralDirection((Real(x) + Real(0.5)) / Real(size), (Real(y) + Real(0.5)) / Real(size));
      Vec3 t, b;
      frameAbout(n, t, b);
      Vec3 sum(0);
      Real weight = 0;
      for (const LobeSample& s : lobe) {
        const Vec3 H = s.h.x * t + s.h.y * b + s.h.z * n;
        const Vec3 L = 2 * s.h.z * H - n;  // V = N, so V·H = N·H
        const Real NoL = 2 * s.h.z * s.h.z - 1;
        sum += NoL * source.at(L, s.lod);
        weight += NoL;
      }
      out.texels[std::size_t(y) * std::size_t(size) + std::size_t(x)] = weight > 0 ? sum / weight : source.at(n, 0);
    }
  });
  return out;
}

// The split sum's table, A and B as two planes of kSplitSumTableSize² entries.
struct DfgTable {
  static constexpr int kSize = kSplitSumTableSize;
  std::array<std::array<Real, kSize * kSize>, 2> planes;
  DfgTable() {
    constexpr int kSamples = 64;
    for (int j = 0; j < kSize; ++j) {
      const Real alpha = alphaOf(Real(j) / Real(kSize - 1));
      std::array<Vec3, kSamples> halfVectors;
      for (int s = 0; s < kSamples; ++s) halfVectors[std::size_t(s)] = sampleGgxHalfVector(s, kSamples, alpha);
      for (int i = 0; i < kSize; ++i) {
        const Real NoV = std::max(Real(i) / Real(kSize - 1), Real(1e-3));
        const Vec3 V(std::sqrt(1 - NoV * NoV), 0, NoV);
        Real a = 0, b = 0;
        for (int s = 0; s < kSamples; ++s) {
          const Vec3& H = halfVectors[std::size_t(s)];
          const Real VoH = glm::dot(V, H);
          const Vec3 L = 2 * VoH * H - V;
          const Real NoL = L.z, NoH = H.z;
          if (NoL <= 0 || VoH <= 0) continue;
          // f·cos / pdf, with pdf = D·N·H / (4 V·H): the distribution cancels.
          const Real g = smithVisibility(NoV, NoL, alpha) * 4 * NoL * VoH / NoH;
          const Real m = 1 - VoH, fc = m * m * m * m * m;
          a += (1 - fc) * g;
          b += fc * g;
        }
        planes[0][std::size_t(j * kSize + i)] = a / kSamples;
        planes[1][std::size_t(j * kSize + i)] = b / kSamples;
      }
    }
  }
};

const DfgTable& dfgTable() {
  static const DfgTable table;
  return table;
}

std::uint64_t contentHash(const EnvironmentMap& map) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull ^ (std::uint64_t(map.width()) << 32 | std::uint32_t(map.height()));
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const Vec3 t = map.texel(x, y);
      std::uint32_t words[3];
      std::memcpy(words, &t, sizeof words);
      for (std::uint32_t w : words) {
        h ^= w;
        h *= 0x100000001B3ull;
        h ^= h >> 29;
      }
    }
  return h;
}

}  // namespace

Vec3 LatLongImage::texel(int x, int y) const {
  const float* p = rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  return {Real(p[0]), Real(p[1]), Real(p[2])};
}

Vec2 latLongPosition(const Vec3& d) {
  return {Real(0.5) + std::atan2(d.x, -d.z) / (2 * kPi), std::acos(std::clamp(d.y, Real(-1), Real(1))) / kPi};
}

Vec3 LatLongImage::bilinear(const Vec3& d) const { return at(latLongPosition(d)); }

Vec3 LatLongImage::at(const Vec2& uv) const {
  const Real x = uv.x * Real(width) - Real(0.5), y = uv.y * Real(height) - Real(0.5);
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const Real fx = x - Real(x0), fy = y - Real(y0);
  const auto at = [&](int i, int j) { return texel(((i % width) + width) % width, std::clamp(j, 0, height - 1)); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

Vec3 latLongDirection(Real x, Real y, int width, int height) {
  const Real phi = (x / Real(width) - Real(0.5)) * 2 * kPi, theta = y / Real(height) * kPi;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

ImageLight::ImageLight(const EnvironmentMap& map) {
  std::vector<LatLongImage> latLong{copyOf(map)};
  while (latLong.front().width > 256) latLong.front() = halved(latLong.front());
  while (latLong.back().width > 64) latLong.push_back(halved(latLong.back()));

  // Irradiance: the radiance projected on the nine harmonics from a level of about 64 × 32, then
  // convolved with the clamped cosine and divided by π.
  const LatLongImage* small = &latLong.front();
  for (const LatLongImage& level : latLong)
    if (level.width >= 64) small = &level;
  std::array<glm::dvec3, 9> projected{};
  for (int y = 0; y < small->height; ++y)
    for (int x = 0; x < small->width; ++x) {
      const std::array<double, 9> basis = shOverTexel(x, y, small->width, small->height);
      const glm::dvec3 radiance(small->texel(x, y));
      for (std::size_t k = 0; k < 9; ++k) projected[k] += basis[k] * radiance;
    }
  constexpr double kBandOverPi[3] = {1, 2.0 / 3, 0.25};
  for (std::size_t k = 0; k < 9; ++k) sh_[k] = Vec3(projected[k] * kBandOverPi[k == 0 ? 0 : k < 4 ? 1 : 2]);

  // Specular: the map on the octahedron (128², about the latitude-longitude base's density), its
  // pyramid, then a lobe per roughness, all levels in one atlas.
  Pyramid octahedral;
  Octahedral sharp{128, std::vector<Vec3>(128 * 128)};
  const LatLongImage& base = latLong.front();
  for (int y = 0; y < sharp.size; ++y)
    for (int x = 0; x < sharp.size; ++x)
      sharp.texels[std::size_t(y) * 128 + std::size_t(x)] =
          base.bilinear(octahedralDirection((Real(x) + Real(0.5)) / 128, (Real(y) + Real(0.5)) / 128));
  octahedral.levels.push_back(sharp);
  while (octahedral.levels.back().size > 4) octahedral.levels.push_back(halved(octahedral.levels.back()));
  constexpr int kSizes[kLevels] = {128, 64, 32, 32, 16, 16};
  RealIndex offset = 0;
  for (int k = 0; k < kLevels; ++k) {
    const Octahedral level = k == 0 ? sharp : prefilter(octahedral, Real(k) / Real(kLevels - 1), kSizes[k]);
    levelSize_[std::size_t(k)] = level.size;
    levelOffset_[std::size_t(k)] = offset;
    offset += RealIndex(level.size) * RealIndex(level.size);
    for (const Vec3& t : level.texels)
      for (int c = 0; c < 3; ++c) atlas_[std::size_t(c)].push_back(t[c]);
  }
}

std::shared_ptr<const ImageLight> ImageLight::of(const EnvironmentMap& map) {
  static std::mutex mutex;
  static std::map<std::uint64_t, std::shared_ptr<const ImageLight>> cache;
  const std::uint64_t key = contentHash(map);
  std::lock_guard lock(mutex);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  if (cache.size() >= 8) cache.erase(cache.begin());  // a long batch of many maps keeps the last few
  auto light = std::make_shared<const ImageLight>(map);
  cache.emplace(key, light);
  return light;
}

namespace one {
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<Real, 1>;
constexpr D d;
}  // namespace one

Vec3 ImageLight::irradianceOverPi(const Vec3& n) const {
  return HWY_NAMESPACE::Lane0(HWY_NAMESPACE::IrradianceOverPi(one::d, *this, HWY_NAMESPACE::Broadcast(one::d, n)));
}

Vec3 ImageLight::prefiltered(const Vec3& r, Real roughness) const {
  return HWY_NAMESPACE::Lane0(
      HWY_NAMESPACE::Prefiltered(one::d, *this, HWY_NAMESPACE::Broadcast(one::d, r), hwy::HWY_NAMESPACE::Set(one::d, roughness)));
}

const Real* splitSumTable(int which) { return dfgTable().planes[std::size_t(which)].data(); }

Vec2 splitSumDfg(Real NoV, Real roughness) {
  namespace hn = hwy::HWY_NAMESPACE;
  hn::VFromD<one::D> a, b;
  HWY_NAMESPACE::SplitSum(one::d, hn::Set(one::d, NoV), hn::Set(one::d, roughness), a, b);
  return {hn::GetLane(a), hn::GetLane(b)};
}

}  // namespace illum
