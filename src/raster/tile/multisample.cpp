#include "raster/tile/multisample.h"


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

}  // namespace

std::span<const SubpixelOffset> multisamplePattern(int count) {
  switch (count) {
    case 4: return kFourPattern;
    case 8: return kEightPattern;
    case 16: return kSixteenPattern;
    default: return kCentre;
  }
}

std::uint32_t resolvePixel(const std::uint32_t* samples, int n) {
  // Most pixels lie inside one surface: samples that agree are their colour (the sums give it too).
  int same = 1;
  while (same < n && samples[same] == samples[0]) ++same;
  if (same == n) return samples[0];
  std::uint32_t premultiplied[3] = {}, straight[3] = {}, alpha = 0;
  for (int s = 0; s < n; ++s) {
    const std::uint32_t word = samples[s], a = word >> 24;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = word >> (8 * c) & 0xFF;
      premultiplied[c] += v * a;
      straight[c] += v;
    }
    alpha += a;
  }
  const std::uint32_t count = std::uint32_t(n);
  if (alpha == 255 * count && (count & (count - 1)) == 0) {
    // Opaque samples (most edges between two surfaces): each premultiplied sum is 255 times the
    // straight one, and alpha/2 is 255·count/2, so (255·s + 255·count/2) / (255·count) is
    // (s + count/2) / count, a shift for counts of a power of two. The same bytes, no division.
    const int shift = __builtin_ctz(count);
    std::uint32_t out = 0xFFu << 24;
    for (int c = 0; c < 3; ++c) out |= (straight[c] + count / 2) >> shift << (8 * c);
    return out;
  }
  std::uint32_t out = (alpha + count / 2) / count << 24;
  for (int c = 0; c < 3; ++c)
    out |= (alpha > 0 ? (premultiplied[c] + alpha / 2) / alpha : (straight[c] + count / 2) / count) << (8 * c);
  return out;
}

}  // namespace illum
