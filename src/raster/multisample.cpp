#include "raster/multisample.h"

#include "raster/setup.h"

#include <array>

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

MultisampleResolve::MultisampleResolve(int width, int height)
    : width_(width), height_(height),
      premultiplied_(std::size_t(width) * std::size_t(height) * 4, 0),
      straight_(std::size_t(width) * std::size_t(height) * 3, 0) {}

void MultisampleResolve::add(const Image& pass) {
  ++passes_;
  const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t* p = &pass.rgba[4 * i];
    const std::uint32_t a = p[3];
    for (std::size_t c = 0; c < 3; ++c) {
      premultiplied_[4 * i + c] += p[c] * a;
      straight_[3 * i + c] += p[c];
    }
    premultiplied_[4 * i + 3] += a;
  }
}

void MultisampleResolve::finish(Image& out) const {
  out = Image(width_, height_);
  const std::uint32_t n = std::uint32_t(passes_);
  const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint32_t alpha = premultiplied_[4 * i + 3];
    std::uint8_t* o = &out.rgba[4 * i];
    for (std::size_t c = 0; c < 3; ++c)
      o[c] = std::uint8_t(alpha > 0 ? (premultiplied_[4 * i + c] + alpha / 2) / alpha : (straight_[3 * i + c] + n / 2) / n);
    o[3] = std::uint8_t((alpha + n / 2) / n);
  }
}

}  // namespace illum
