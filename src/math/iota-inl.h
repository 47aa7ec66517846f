// first, first + 1, … in the lanes, for a `first` known only at run time. Highway 1.0.3 (Debian
// 12) builds Iota(d, first) by storing each lane to memory and loading the vector back: the load
// waits for the stores (a failed store-to-load forwarding): perf put 8 % of RasterizeSamples'
// samples on that wait in its per-triangle tables, though out-of-order execution hid most of it
// (ClearCoatTest's frame at 8 samples changed within the noise). A constant Iota plus `first` is
// the same lanes (integers wrap as Iota's do; float lanes add exactly while first + lane is exact).
// Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_MATH_IOTA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_MATH_IOTA_INL_H_
#undef ILLUM_MATH_IOTA_INL_H_
#else
#define ILLUM_MATH_IOTA_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D, typename T2>
HWY_INLINE hn::VFromD<D> IotaFrom(D d, T2 first) {
  return hn::Add(hn::Iota(d, 0), hn::Set(d, static_cast<hn::TFromD<D>>(first)));
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
