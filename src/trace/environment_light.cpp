#include "trace/environment_light.h"

#include "trace/sampling.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

// Index i with cdf[i] <= x < cdf[i + 1] over the n intervals, skipping empty ones.
int findInterval(const Real* cdf, int n, Real x) {
  const Real* it = std::upper_bound(cdf + 1, cdf + n + 1, x);
  int i = std::clamp(int(it - cdf) - 1, 0, n - 1);
  while (i > 0 && !(cdf[i + 1] > cdf[i])) --i;  // x at the top end of an empty run
  return i;
}


}  // namespace

EnvironmentLight::EnvironmentLight(const EnvironmentMap& map) : width_(map.width()), height_(map.height()) {
  const std::size_t w = std::size_t(width_), h = std::size_t(height_);
  weight_.resize(w * h);
  columnCdf_.resize((w + 1) * h);
  rowCdf_.resize(h + 1);
  for (int y = 0; y < height_; ++y) {
    const Real sinTheta = std::sin(kPiReal * (Real(y) + Real(0.5)) / Real(height_));
    Real* cdf = &columnCdf_[std::size_t(y) * (w + 1)];
    cdf[0] = 0;
    for (int x = 0; x < width_; ++x) {
      // The mean over the texel of the bilinear radiance that lookups return: 9/16 of its own,
      // 3/32 of each side neighbour's and 1/64 of each corner's (longitude wraps, latitude
      // clamps). Wherever a lookup finds radiance, the density is then not 0.
      Real mean = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const Real share = Real(dj == 0 ? 3 : 1) * Real(di == 0 ? 3 : 1) / 16;
          mean += share * luminance(map.texel((x + di + width_) % width_, std::clamp(y + dj, 0, height_ - 1)));
        }
      const Real v = mean * sinTheta;
      weight_[std::size_t(y) * w + std::size_t(x)] = std::isfinite(v) ? v : 0;
      cdf[x + 1] = cdf[x] + weight_[std::size_t(y) * w + std::size_t(x)];
    }
    rowCdf_[std::size_t(y) + 1] = rowCdf_[std::size_t(y)] + cdf[width_];
  }
  total_ = rowCdf_[h];
}

EnvironmentSample EnvironmentLight::sample(Real u0, Real u1) const {
  EnvironmentSample out;
  if (empty()) return out;
  const std::size_t w = std::size_t(width_);
  const int y = findInterval(rowCdf_.data(), height_, u0 * total_);
  const Real* cdf = &columnCdf_[std::size_t(y) * (w + 1)];
  const int x = findInterval(cdf, width_, u1 * cdf[width_]);
  // Where in the texel: the remainders of the two choices, uniform within it.
  const Real rowWeight = rowCdf_[std::size_t(y) + 1] - rowCdf_[std::size_t(y)], texel = cdf[x + 1] - cdf[x];
  const Real fy = std::clamp((u0 * total_ - rowCdf_[std::size_t(y)]) / rowWeight, Real(0), Real(1));
  const Real fx = std::clamp((u1 * cdf[width_] - cdf[x]) / texel, Real(0), Real(1));
  const Real u = (Real(x) + fx) / Real(width_), v = (Real(y) + fy) / Real(height_);
  // EnvironmentMap::radiance's mapping reversed: longitude from −Z towards +X, latitude from +Y.
  const Real theta = v * kPiReal, phi = (u - Real(0.5)) * 2 * kPiReal;
  const Real sinTheta = std::sin(theta);
  out.direction = {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
  out.pdf = pdf(out.direction);
  return out;
}

Real EnvironmentLight::pdf(const Vec3& d) const {
  if (empty()) return 0;
  const Real u = Real(0.5) + std::atan2(d.x, -d.z) / (2 * kPiReal);
  const Real theta = std::acos(std::clamp(d.y, Real(-1), Real(1)));
  const int x = std::clamp(int(u * Real(width_)), 0, width_ - 1);
  const int y = std::clamp(int(theta / kPiReal * Real(height_)), 0, height_ - 1);
  const Real sinTheta = std::sin(theta);
  if (!(sinTheta > 0)) return 0;
  // Density over the unit square (texel weight / total × texel count), then per solid angle:
  // dω = 2π·π·sin θ du dv.
  const Real pdfUv = weight_[std::size_t(y) * std::size_t(width_) + std::size_t(x)] / total_ * Real(width_) * Real(height_);
  return pdfUv / (2 * kPiReal * kPiReal * sinTheta);
}

}  // namespace illum
