// toUnorm8 (framebuffer.h) over lanes: round(clamp(c)·255) of four float channels packed into
// RGBA8 pixels (R in the lowest byte, as the framebuffer stores them), halves up exactly as the
// scalar conversion rounds them, on every SIMD target. Included once per target (Highway's -inl.h
// convention).

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

// One channel: ⌊c·255 + ½⌋ of c clamped to [0, 1], as 32-bit lanes.
#if HWY_NATIVE_FMA
// The exact product c·255 is never a tie k + ½ except at c = ½ (c = m/2^e with m odd gives
// 255·m·2^(1−e) = 2k + 1 only for e = 1, m = 1), where ties to even also gives 128: so rounding it
// to nearest, ties to even, is ⌊c·255 + ½⌋. One fused multiply-add rounds the exact c·255 + 2^23 to
// the float grid of spacing 1 there, 2^23 + k, whose low mantissa bits are k.
template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> Unorm8(DF df, V c) {
  const hn::Rebind<std::uint32_t, DF> du;
  c = hn::Min(hn::Max(c, hn::Zero(df)), hn::Set(df, 1.0f));
  const V shifted = hn::MulAdd(c, hn::Set(df, 255.0f), hn::Set(df, 8388608.0f));  // 2^23 + k
  return hn::And(hn::BitCast(du, shifted), hn::Set(du, 0xFFu));
}
#else
// Without a fused multiply-add (SSE4 and older, the scalar targets): c·255 and the half are exact
// in double, where truncation rounds as the scalar conversion does; a float vector wider than a
// double one goes half by half.
template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> Unorm8(DF df, V c) {
  c = hn::Min(hn::Max(c, hn::Zero(df)), hn::Set(df, 1.0f));
  if constexpr (hn::MaxLanes(DF()) <= hn::MaxLanes(hn::ScalableTag<double>())) {
    const hn::Rebind<double, DF> dd;
    const auto x = hn::PromoteTo(dd, c) * hn::Set(dd, 255.0) + hn::Set(dd, 0.5);
    return hn::BitCast(hn::Rebind<std::uint32_t, DF>(), hn::DemoteTo(hn::Rebind<std::int32_t, DF>(), x));
  } else {
#if HWY_TARGET != HWY_SCALAR
    const hn::Half<DF> dh;
    return hn::Combine(hn::Rebind<std::uint32_t, DF>(), Unorm8(dh, hn::UpperHalf(dh, c)),
                       Unorm8(dh, hn::LowerHalf(dh, c)));
#endif
  }
}
#endif

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
