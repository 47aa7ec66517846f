#include <illum/texture.h>

#include <illum/display.h>

#include <array>

#include <algorithm>
#include <cmath>

namespace illum {

Texture::Texture(const Image& image, TexelEncoding encoding) : encoding_(encoding) {
  // Decoding by table: 256 values, each exactly as srgbDecoded gives it.
  std::array<Real, 256> decode;
  for (int i = 0; i < 256; ++i)
    decode[std::size_t(i)] = encoding == TexelEncoding::Srgb ? srgbDecoded(Real(i) / 255) : Real(i) / Real(255);
  Level base{std::max(image.width, 1), std::max(image.height, 1), {}};
  base.texels.resize(std::size_t(base.width) * std::size_t(base.height), Vec4(1));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, image.height - 1 - y);
      hasTransparency_ = hasTransparency_ || p[3] < 255;
      base.texels[std::size_t(y) * std::size_t(base.width) + std::size_t(x)] =
          Vec4(decode[p[0]], decode[p[1]], decode[p[2]], Real(p[3]) / Real(255));
    }
  levels_.push_back(std::move(base));
  // The mipmap chain by 2×2 box filtering (a single row or column halves in one direction).
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& prev = levels_.back();
    Level next{std::max(prev.width / 2, 1), std::max(prev.height / 2, 1), {}};
    next.texels.resize(std::size_t(next.width) * std::size_t(next.height));
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) {
        Vec4 sum(0);
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int sx = std::min(2 * x + dx, prev.width - 1), sy = std::min(2 * y + dy, prev.height - 1);
            sum += prev.texels[std::size_t(sy) * std::size_t(prev.width) + std::size_t(sx)];
          }
        next.texels[std::size_t(y) * std::size_t(next.width) + std::size_t(x)] = sum / Real(4);
      }
    levels_.push_back(std::move(next));
  }
}

Image Texture::baseImage() const {
  const Level& base = levels_.front();
  Image image(base.width, base.height);
  for (int y = 0; y < base.height; ++y)
    for (int x = 0; x < base.width; ++x) {
      const Vec4 t = base.texels[std::size_t(y) * std::size_t(base.width) + std::size_t(x)];
      std::uint8_t* p = image.pixel(x, base.height - 1 - y);
      for (int c = 0; c < 4; ++c) {
        const Real v = c < 3 && encoding_ == TexelEncoding::Srgb ? srgbEncoded(t[c]) : t[c];
        p[c] = std::uint8_t(std::lround(v * Real(255)));
      }
    }
  return image;
}

Vec4 Texture::sampleLevel(const Vec2& uv, int level) const {
  const Level& l = levels_[std::size_t(std::clamp(level, 0, levelCount() - 1))];
  // GL_REPEAT, then GL_LINEAR: the four texels around (u·w − 0.5, v·h − 0.5).
  const Real u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
  const Real x = u * Real(l.width) - Real(0.5), y = v * Real(l.height) - Real(0.5);
  const Real fx = std::floor(x), fy = std::floor(y);
  const Real ax = x - fx, ay = y - fy;
  const auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int x0 = wrap(int(fx), l.width), x1 = wrap(int(fx) + 1, l.width);
  const int y0 = wrap(int(fy), l.height), y1 = wrap(int(fy) + 1, l.height);
  const auto at = [&](int xx, int yy) { return l.texels[std::size_t(yy) * std::size_t(l.width) + std::size_t(xx)]; };
  return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x1, y0)) + ay * ((1 - ax) * at(x0, y1) + ax * at(x1, y1));
}

Vec4 Texture::sample(const Vec2& uv, Real texelsPerPixel) const {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return Vec4(1);
  const Real lod = texelsPerPixel > 1 ? std::log2(texelsPerPixel) : Real(0);
  const Real clamped = std::min(lod, Real(levelCount() - 1));
  const int l0 = int(std::floor(clamped));
  const Real t = clamped - Real(l0);
  if (t == 0) return sampleLevel(uv, l0);
  return (1 - t) * sampleLevel(uv, l0) + t * sampleLevel(uv, l0 + 1);
}

}  // namespace illum
