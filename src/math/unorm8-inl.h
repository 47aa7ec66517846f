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

// Lanes(DF) float channels, DF = Rebind<float, ScalableTag<double>> (as many as a double vector).
template <class DF, class V = hn::VFromD<DF>>
HWY_INLINE hn::VFromD<hn::Rebind<std::uint32_t, DF>> PackUnorm8(DF df, V r, V g, V b, V a) {
  const hn::Rebind<double, DF> dd;
  const hn::Rebind<std::int32_t, DF> di;
  const hn::Rebind<std::uint32_t, DF> du;
  const auto channel = [&](V c) {
    c = hn::Min(hn::Max(c, hn::Zero(df)), hn::Set(df, 1.0f));
    const auto x = hn::PromoteTo(dd, c) * hn::Set(dd, 255.0) + hn::Set(dd, 0.5);
    return hn::BitCast(du, hn::DemoteTo(di, x));  // truncates toward zero
  };
  return hn::Or(hn::Or(channel(r), hn::ShiftLeft<8>(channel(g))),
                hn::Or(hn::ShiftLeft<16>(channel(b)), hn::ShiftLeft<24>(channel(a))));
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_MATH_UNORM8_INL_H_
