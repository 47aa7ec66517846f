// toUnorm8 (framebuffer.h) over lanes: round(clamp(c)·255) of four float channels packed into
// RGBA8 pixels (R in the lowest byte, as the framebuffer stores them). The product and the half
// are exact in double, so truncation rounds halves up exactly as the scalar conversion does, on
// every SIMD target. Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_MATH_UNORM8_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_MATH_UNORM8_INL_H_
#undef ILLUM_MATH_UNORM8_INL_H_
#else
#define ILLUM_MATH_UNORM8_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One channel: round(clamp(c)·255) as 32-bit lanes. Lanes(DF) floats, DF = Rebind<float,
// ScalableTag<double>> (as many as a double vector holds).
template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> Unorm8(DF df, V c) {
  const hn::Rebind<double, DF> dd;
  const hn::Rebind<std::int32_t, DF> di;
  c = hn::Min(hn::Max(c, hn::Zero(df)), hn::Set(df, 1.0f));
  const auto x = hn::PromoteTo(dd, c) * hn::Set(dd, 255.0) + hn::Set(dd, 0.5);
  return hn::BitCast(hn::Rebind<std::uint32_t, DF>(), hn::DemoteTo(di, x));  // truncates toward zero
}

// Colour channels with a given alpha byte (255 for opaque pixels).
template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> PackUnorm8(DF df, V r, V g, V b, std::uint32_t alpha8) {
  const hn::Rebind<std::uint32_t, DF> du;
  return hn::Or(hn::Or(Unorm8(df, r), hn::ShiftLeft<8>(Unorm8(df, g))),
                hn::Or(hn::ShiftLeft<16>(Unorm8(df, b)), hn::Set(du, alpha8 << 24)));
}

template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> PackUnorm8(DF df, V r, V g, V b, V a) {
  return hn::Or(PackUnorm8(df, r, g, b, 0u), hn::ShiftLeft<24>(Unorm8(df, a)));
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_MATH_UNORM8_INL_H_
