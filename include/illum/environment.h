// An environment map: radiance arriving from every direction, stored as an equirectangular
// (latitude-longitude) image of linear RGB, the form of Radiance .hdr light probes. The path
// tracer reads it where a path escapes the scene.
#pragma once

#include <illum/limits.h>
#include <illum/real.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace illum {

class EnvironmentMap {
 public:
  EnvironmentMap(int width, int height, const std::vector<Vec3>& texels);
  // Decodes a Radiance .hdr (RGBE) file's bytes with stb_image, after checkRadianceHdr, or an
  // OpenEXR file's R, G and B (known by its magic number) with OpenEXR, its size checked against
  // the limits before any pixel is read. Throws InputError naming `name`.
  static EnvironmentMap decode(const std::string& bytes, const std::string& name, const Limits& limits);
  // Reads `path` through the input gate (regular files only, sized before reading), then decode().
  static EnvironmentMap load(const std::filesystem::path& path, const Limits& limits);

  // The radiance towards world direction `d` (unit; +Y up): longitude from −Z towards +X across the
  // image's width, latitude from +Y (top row) to −Y (bottom row); bilinear between texels.
  Vec3 radiance(const Vec3& d) const;
  // The stored texel at column x, row y (row 0 at the top).
  Vec3 texel(int x, int y) const {
    const float* p = rgb_.get() + 3 * (std::size_t(y) * std::size_t(width_) + std::size_t(x));
    return {Real(p[0]), Real(p[1]), Real(p[2])};
  }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  EnvironmentMap(int width, int height, std::shared_ptr<const float> rgb) : width_(width), height_(height), rgb_(std::move(rgb)) {}
  int width_, height_;
  std::shared_ptr<const float> rgb_;  // 3 floats a texel, rows top to bottom: stb's own buffer, not a copy
};

// The size a Radiance .hdr file's header gives, after checking that its pixel data can be decoded
// in bounded time: every scanline complete, no run or dump of length 0 (stb_image loops for ever
// on one: it never advances), nothing cut short. Throws InputError naming `name`: a 0×0 map, a
// map of more than limits.maxPixels, a truncated one.
struct HdrSize {
  int width = 0, height = 0;
};
HdrSize checkRadianceHdr(const std::string& bytes, const std::string& name, const Limits& limits);

// A scene's environment map file. Opening it reads and checks the file (the input gate, the
// header, checkRadianceHdr), so that a scene with a bad map is refused when it is read, whichever
// renderer draws it; only a renderer that samples the map decodes it (the rasterizer never does),
// once per process for the same bytes: the panels of a sheet share one decoded map.
class EnvironmentMapFile {
 public:
  static std::shared_ptr<const EnvironmentMapFile> open(const std::filesystem::path& path, const Limits& limits);
  // A map already in memory (tests, generated maps).
  static std::shared_ptr<const EnvironmentMapFile> of(std::shared_ptr<const EnvironmentMap> map);

  // The decoded map; throws InputError if decoding fails.
  const EnvironmentMap& map() const;
  const std::filesystem::path& path() const { return path_; }
  int width() const { return size_.width; }
  int height() const { return size_.height; }

 private:
  std::filesystem::path path_;
  std::string bytes_;
  Limits limits_;
  HdrSize size_;
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const EnvironmentMap> map_;
};

}  // namespace illum
