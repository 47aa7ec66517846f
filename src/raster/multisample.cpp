#include "raster/multisample.h"

#include "raster/setup.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace illum {
namespace {

// Direct3D's standard sample positions in 1/16 pixel (y down there: flipped for GL's y up),
// times 16 for illum's 1/256 sub-pixel grid.
template <std::size_t N>
constexpr std::array<SubpixelOffset, N> scaled(const int (&xy)[N][2]) {
  std::array<SubpixelOffset, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = {xy[i][0] * 16, -xy[i][1] * 16};
  return out;
}

constexpr int kFour[4][2] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
constexpr int kEight[8][2] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
constexpr int kSixteen[16][2] = {{1, 1},  {-1, -3}, {-3, 2},  {4, -1}, {-5, -2}, {2, 5},  {5, 3},   {3, -5},
                                 {-2, 6}, {0, -7},  {-4, -6}, {-6, 4}, {-8, 0},  {7, -4}, {6, 7},   {-7, -8}};
constexpr auto kFourPattern = scaled(kFour);
constexpr auto kEightPattern = scaled(kEight);
constexpr auto kSixteenPattern = scaled(kSixteen);
constexpr std::array<SubpixelOffset, 1> kCentre = {SubpixelOffset{0, 0}};
constexpr std::size_t kMaxSampleCount = kSixteenPattern.size();

}  // namespace

std::span<const SubpixelOffset> multisamplePattern(int count) {
  switch (count) {
    case 4: return kFourPattern;
    case 8: return kEightPattern;
    case 16: return kSixteenPattern;
    default: return kCentre;
  }
}

std::size_t resolveTile(std::span<const Framebuffer> samples, int tile, Image& image, std::uint32_t background8) {
  const Framebuffer& first = samples.front();
  const int x0 = tile % first.tilesX() * kTileSize, y0 = tile / first.tilesX() * kTileSize;
  const int count = std::min(kTileSize, first.width() - x0), rows = std::min(kTileSize, first.height() - y0);
  const std::uint32_t n = std::uint32_t(samples.size());
  const std::uint32_t* planes[kMaxSampleCount];
  std::uint32_t clear[kMaxSampleCount];
  for (std::size_t s = 0; s < samples.size(); ++s) {
    planes[s] = samples[s].tileColors(tile);
    clear[s] = samples[s].clearWord();
  }
  std::size_t unlike = 0;
  for (int r = 0; r < rows; ++r) {
    std::uint8_t* out = image.pixel(x0, first.height() - 1 - (y0 + r));  // the image's rows run from the top
    for (int x = 0; x < count; ++x, out += 4) {
      const int at = r * kTileSize + x;
      std::uint32_t premultiplied[3] = {}, straight[3] = {}, alpha = 0;
      for (std::size_t s = 0; s < samples.size(); ++s) {
        const std::uint32_t word = planes[s] ? planes[s][at] : clear[s];
        const std::uint32_t a = word >> 24;
        for (int c = 0; c < 3; ++c) {
          const std::uint32_t v = word >> (8 * c) & 0xFF;
          premultiplied[c] += v * a;
          straight[c] += v;
        }
        alpha += a;
      }
      for (int c = 0; c < 3; ++c)
        out[c] = std::uint8_t(alpha > 0 ? (premultiplied[c] + alpha / 2) / alpha : (straight[c] + n / 2) / n);
      out[3] = std::uint8_t((alpha + n / 2) / n);
      std::uint32_t word;
      std::memcpy(&word, out, 4);
      unlike += word != background8;
    }
  }
  return unlike;
}

}  // namespace illum
