#include <illum/texture.h>

#include <illum/display.h>

#include <hwy/highway.h>

#include "image/texel_lookup.h"
#include "image/texture_lanes-inl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace illum {
namespace {

// A byte's value, as each encoding decodes it: 256 entries, each exactly as srgbDecoded gives it.
struct DecodeTables {
  std::array<Real, 256> linear, srgb;
  // srgbThreshold[k]: the linear value halfway, in the encoded scale, between bytes k and k + 1
  // (srgbDecoded((k + ½)/255)): a linear value encodes to the number of thresholds at or below it,
  // which is round(srgbEncoded(v)·255) without a pow per texel.
  std::array<Real, 255> srgbThreshold;
  // Each table's entries as floats in byte planes (Texture::colorTableBytes).
  alignas(64) std::array<std::uint8_t, 1024> linearBytes, srgbBytes;
  DecodeTables() {
    for (int i = 0; i < 256; ++i) {
      linear[std::size_t(i)] = Real(i) / Real(255);
      srgb[std::size_t(i)] = srgbDecoded(Real(i) / 255);
    }
    const auto planes = [](const std::array<Real, 256>& table, std::array<std::uint8_t, 1024>& bytes) {
      for (std::size_t i = 0; i < 256; ++i) {
        std::uint32_t bits;
        const float value = float(table[i]);
        std::memcpy(&bits, &value, 4);
        for (std::size_t k = 0; k < 4; ++k) bytes[256 * k + i] = std::uint8_t(bits >> (8 * k));
      }
    };
    planes(linear, linearBytes);
    planes(srgb, srgbBytes);
    for (int k = 0; k < 255; ++k) srgbThreshold[std::size_t(k)] = srgbDecoded((Real(k) + Real(0.5)) / 255);
  }
};

const DecodeTables& tables() {
  static const DecodeTables t;
  return t;
}

// The next mip level: each texel the 2×2 box average of the level above, in linear values (sRGB
// colour decoded first), rounded back to a byte (a single row or column halves in one direction).
Image halved(const Image& prev, TexelEncoding encoding) {
  Image next(std::max(prev.width / 2, 1), std::max(prev.height / 2, 1));
  const DecodeTables& t = tables();
  // Rows pair up from GL's first row, the image's bottom one (it matters for odd heights).
  const auto imageRow = [](const Image& level, int glRow) { return level.height - 1 - glRow; };
  for (int gy = 0; gy < next.height; ++gy) {
    const int y = imageRow(next, gy);
    const int y0 = imageRow(prev, std::min(2 * gy, prev.height - 1)),
              y1 = imageRow(prev, std::min(2 * gy + 1, prev.height - 1));
    for (int x = 0; x < next.width; ++x) {
      const int x0 = std::min(2 * x, prev.width - 1), x1 = std::min(2 * x + 1, prev.width - 1);
      const std::uint8_t* q[4] = {prev.pixel(x0, y0), prev.pixel(x1, y0), prev.pixel(x0, y1), prev.pixel(x1, y1)};
      std::uint8_t* p = next.pixel(x, y);
      for (int c = 0; c < 4; ++c) {
        const unsigned sum = unsigned(q[0][c]) + q[1][c] + q[2][c] + q[3][c];
        if (c == 3 || encoding == TexelEncoding::Linear) {
          p[c] = std::uint8_t((sum + 2) / 4);  // round(mean), halves up, exactly in integers
          continue;
        }
        const Real mean = (t.srgb[q[0][c]] + t.srgb[q[1][c]] + t.srgb[q[2][c]] + t.srgb[q[3][c]]) / Real(4);
        p[c] = std::uint8_t(std::upper_bound(t.srgbThreshold.begin(), t.srgbThreshold.end(), mean) -
                            t.srgbThreshold.begin());
      }
    }
  }
  return next;
}

}  // namespace

Texture::Texture(Image image, TexelEncoding encoding, TextureWraps wraps)
    : decode_(encoding == TexelEncoding::Srgb ? tables().srgb.data() : tables().linear.data()),
      decodeBytes_(encoding == TexelEncoding::Srgb ? tables().srgbBytes.data() : tables().linearBytes.data()),
      encoding_(encoding),
      wraps_(wraps) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() < std::size_t(image.width) * std::size_t(image.height) * 4) {
    image = Image(std::max(image.width, 1), std::max(image.height, 1));
    std::fill(image.rgba.begin(), image.rgba.end(), std::uint8_t(255));  // white: modulates nothing
  }
  for (std::size_t i = 3; i < image.rgba.size() && !hasTransparency_; i += 4) hasTransparency_ = image.rgba[i] < 255;
  levels_.push_back(std::move(image));
  while (levels_.back().width > 1 || levels_.back().height > 1) levels_.push_back(halved(levels_.back(), encoding));
}

std::size_t Texture::byteSize() const {
  std::size_t n = 0;
  for (const Level& l : levels_) n += l.rgba.size();
  return n;
}

const Real* Texture::alphaTable() { return tables().linear.data(); }

bool cpuHasVbmi() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx512vbmi");
#else
  return false;
#endif
}

Vec4 Texture::texel(const Level& level, int x, int glRow) const {
  const std::uint8_t* p = level.pixel(x, level.height - 1 - glRow);
  return Vec4(decode_[p[0]], decode_[p[1]], decode_[p[2]], tables().linear[p[3]]);
}

namespace {

// GL_LINEAR along one axis of n texels: the two texels around c·n − ½ and the second one's weight,
// the indices wrapped as `wrap` says. The coordinate is first brought into one period (repeat:
// [0, 1), mirrored: [0, 2), clamped: [0, 1]), which changes no texel and keeps the indices small.
struct TexelPair {
  int i0, i1;
  Real weight;
};

TexelPair texelPair(Real c, int n, TextureWrap wrap) {
  const Real reduced = wrap == TextureWrap::ClampToEdge ? std::clamp(c, Real(0), Real(1))
                       : wrap == TextureWrap::Repeat    ? c - std::floor(c)
                                                        : c - 2 * std::floor(c / 2);
  const Real x = reduced * Real(n) - Real(0.5);
  const Real fx = std::floor(x);
  const int i = int(fx);
  // The reduced coordinate puts i in [−1, n − 1] ([−1, 2n − 1] mirrored): its neighbour is at
  // most one texel out.
  const auto wrapped = [&](int k) {
    switch (wrap) {
      case TextureWrap::Repeat: return k < 0 ? k + n : k >= n ? k - n : k;
      case TextureWrap::ClampToEdge: return std::clamp(k, 0, n - 1);
      case TextureWrap::MirroredRepeat: {
        const int m = k < 0 ? k + 2 * n : k >= 2 * n ? k - 2 * n : k;
        return m < n ? m : 2 * n - 1 - m;
      }
    }
    return 0;
  };
  return {wrapped(i), wrapped(i + 1), x - fx};
}

// A footprint's mip level: the lanes' MipLevelLanes on one lane of the static target (every target
// computes the same bits).
Real mipLevel(Real texelsPerPixel) {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::CappedTag<Real, 1> d;
  return hn::GetLane(HWY_NAMESPACE::MipLevelLanes(d, hn::Set(d, texelsPerPixel)));
}

}  // namespace

Vec4 Texture::sampleLevel(const Vec2& uv, int level) const {
  const Level& l = levels_[std::size_t(std::clamp(level, 0, levelCount() - 1))];
  // The wrap modes, then GL_LINEAR: the four texels around (u·w − 0.5, v·h − 0.5).
  const TexelPair x = texelPair(uv.x, l.width, wraps_.s), y = texelPair(uv.y, l.height, wraps_.t);
  const Real ax = x.weight, ay = y.weight;
  return (1 - ay) * ((1 - ax) * texel(l, x.i0, y.i0) + ax * texel(l, x.i1, y.i0)) +
         ay * ((1 - ax) * texel(l, x.i0, y.i1) + ax * texel(l, x.i1, y.i1));
}

Vec4 Texture::sample(const Vec2& uv, Real texelsPerPixel) const {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return Vec4(1);
  const Real lod = mipLevel(texelsPerPixel);
  const Real clamped = std::min(lod, Real(levelCount() - 1));
  const int l0 = int(std::floor(clamped));
  const Real t = clamped - Real(l0);
  if (t == 0) return sampleLevel(uv, l0);
  return (1 - t) * sampleLevel(uv, l0) + t * sampleLevel(uv, l0 + 1);
}

}  // namespace illum
