// An environment map: radiance arriving from every direction, stored as an equirectangular
// (latitude-longitude) image of linear RGB, the form of Radiance .hdr light probes. The path
// tracer reads it where a path escapes the scene.
#pragma once

#include <illum/limits.h>
#include <illum/real.h>

#include <filesystem>
#include <vector>

namespace illum {

class EnvironmentMap {
 public:
  EnvironmentMap(int width, int height, std::vector<Vec3> texels);
  // Reads a Radiance .hdr (RGBE) file with stb_image. Throws InputError naming the file; images
  // of more than limits.maxPixels are refused from their header, before decoding.
  static EnvironmentMap load(const std::filesystem::path& path, const Limits& limits);

  // The radiance towards world direction `d` (unit; +Y up): longitude from −Z towards +X across the
  // image's width, latitude from +Y (top row) to −Y (bottom row); bilinear between texels.
  Vec3 radiance(const Vec3& d) const;
  // The stored texel at column x, row y (row 0 at the top).
  const Vec3& texel(int x, int y) const { return texels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)]; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::vector<Vec3> texels_;  // rows top to bottom
};

}  // namespace illum
