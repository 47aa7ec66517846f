// 8-bit RGBA images, row 0 at the top, and their PNG form.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace illum {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width·height·4 bytes, rows top to bottom

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
  }
};

// Linear values per pixel before their 8-bit conversion, RGBA floats, rows top to bottom: the
// radiance the ray and path tracers computed, unclamped (the rasterizer's bytes / 255).
// Further values of a FloatImage's pixels, under a name: `channels` (3: R, G, B; 4: and A) per
// pixel, in the same order. OpenEXR output writes them as the layer's channels NAME.R, NAME.G, ...
struct FloatLayer {
  std::string name;
  int channels = 3;
  std::vector<float> values;
};

struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;
  // The path tracer's, when it denoised `rgba`: "beauty" (its picture before), "albedo" and
  // "normal" (the denoiser's guides).
  std::vector<FloatLayer> layers;
  float* pixel(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

// Encodes linear values as OpenEXR (32-bit float R, G, B, A and the layers' channels, ZIP
// compression) in memory.
std::vector<std::uint8_t> encodeExr(const FloatImage& image);
// Reads an OpenEXR file's R, G, B, A channels (missing ones read as 0). Throws InputError.
FloatImage readExr(const std::filesystem::path& path);

// Encodes the image as JPEG (libjpeg-turbo, RGB: alpha is dropped) at `quality` 1..100.
std::vector<std::uint8_t> encodeJpeg(const Image& image, int quality = 90);
// Encodes the image as WebP: lossless without a quality, lossy at `quality` 1..100.
std::vector<std::uint8_t> encodeWebp(const Image& image, std::optional<int> quality = std::nullopt);

// Encodes the image as PNG in memory.
std::vector<std::uint8_t> encodePng(const Image& image);
// Encodes 16-bit RGBA PNG samples (big-endian, as PNG stores them), `rgba` holding four per pixel.
std::vector<std::uint8_t> encodePng16(int width, int height, const std::vector<std::uint16_t>& rgba);
// Writes a PNG with writeOutputFile (output_file.h): never a partial or clobbered file.
void writePng(const std::filesystem::path& path, const Image& image);
// Reads a PNG (any 8-bit format, expanded to RGBA). Throws InputError on failure.
Image readPng(const std::filesystem::path& path);

// How far two images are apart, per channel, in 8-bit steps.
struct ImageDifference {
  int maxError = 0;               // largest |a−b| over every channel of every pixel
  double fractionWithin = 1;      // fraction of pixels whose every channel is within the tolerance
  double psnr = 0;                // dB over RGB; +inf for identical images
};
ImageDifference compareImages(const Image& a, const Image& b, int tolerance);
// |a−b| per channel, amplified so small errors show, alpha opaque.
Image differenceImage(const Image& a, const Image& b, int gain = 16);

}  // namespace illum
