#include <illum/environment.h>
#include <illum/error.h>

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace illum {

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<Vec3> texels)
    : width_(width), height_(height), texels_(std::move(texels)) {}

EnvironmentMap EnvironmentMap::load(const std::filesystem::path& path, const Limits& limits) {
  int w = 0, h = 0, channels = 0;
  if (!stbi_info(path.c_str(), &w, &h, &channels))
    throw InputError(path.string() + ": cannot read the environment map (expected a Radiance .hdr image): " +
                     stbi_failure_reason());
  if (!stbi_is_hdr(path.c_str()))
    throw InputError(path.string() + ": the environment map is not a high dynamic range image (expected a Radiance .hdr)");
  if (std::uint64_t(w) * std::uint64_t(h) > limits.maxPixels)
    throw InputError(path.string() + ": the environment map has " + withThousands(std::uint64_t(w) * std::uint64_t(h)) +
                     " pixels, more than the limit of " + withThousands(limits.maxPixels) + " (raise it with --max-pixels)");
  const std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!data) throw InputError(path.string() + ": cannot decode the environment map: " + stbi_failure_reason());
  std::vector<Vec3> texels(std::size_t(w) * std::size_t(h));
  for (std::size_t i = 0; i < texels.size(); ++i) {
    const float* p = data.get() + 3 * i;
    // Radiance stays finite and non-negative whatever the file says.
    for (int c = 0; c < 3; ++c) texels[i][c] = std::isfinite(p[c]) ? std::max(0.0f, p[c]) : 0.0f;
  }
  return EnvironmentMap(w, h, std::move(texels));
}

Vec3 EnvironmentMap::radiance(const Vec3& d) const {
  constexpr Real kPi = Real(3.14159265358979323846);
  const Real u = Real(0.5) + std::atan2(d.x, -d.z) / (2 * kPi);
  const Real v = std::acos(std::clamp(d.y, Real(-1), Real(1))) / kPi;
  // Texel centres at (i + 0.5, j + 0.5); longitude wraps, latitude clamps.
  const Real x = u * Real(width_) - Real(0.5), y = v * Real(height_) - Real(0.5);
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const Real fx = x - Real(x0), fy = y - Real(y0);
  const auto at = [&](int i, int j) {
    i = ((i % width_) + width_) % width_;
    j = std::clamp(j, 0, height_ - 1);
    return texels_[std::size_t(j) * std::size_t(width_) + std::size_t(i)];
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

}  // namespace illum
