// 8-bit conversion of one channel, round(clamp(c)·255), as GL's framebuffer stores a colour: the
// scalar instance that the rasterizer, the ray tracers and the reports share (unorm8-inl.h is the
// same rounding over SIMD lanes, tested against this one).
#pragma once

#include <illum/real.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace illum {

// round(clamp(c)·255), halves away from zero, as std::lround would. With float channels the
// product is exact in double (24 + 8 bits), so adding 0.5 is exact too and truncation rounds the
// same way, without a call into libm per channel; double channels keep std::lround.
inline std::uint8_t toUnorm8(Real c) {
  const double x = double(std::clamp(c, Real(0), Real(1))) * 255.0;
  if constexpr (sizeof(Real) == sizeof(float)) return std::uint8_t(int(x + 0.5));
  else return std::uint8_t(std::lround(x));
}

// A colour as the framebuffer stores it: RGBA8, R in the lowest byte.
inline std::uint32_t packUnorm8(const Color4& c) {
  return std::uint32_t(toUnorm8(c.r)) | std::uint32_t(toUnorm8(c.g)) << 8 | std::uint32_t(toUnorm8(c.b)) << 16 |
         std::uint32_t(toUnorm8(c.a)) << 24;
}

}  // namespace illum
