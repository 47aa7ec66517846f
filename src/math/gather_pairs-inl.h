// Two neighbouring 32-bit values a lane, base[index] and base[index + 1] (a row's two texels of a
// bilinear read), read together. AVX-512 gathers cost by the element, and one eight-byte element
// holds both neighbours: half the elements of two four-byte gathers, each pair then taken apart by
// two permutes; from a row short enough for two registers, permutes alone. Other targets (and
// 64-bit values) gather twice. The values are the same bits either way.
// Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_MATH_GATHER_PAIRS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_MATH_GATHER_PAIRS_INL_H_
#undef ILLUM_MATH_GATHER_PAIRS_INL_H_
#else
#define ILLUM_MATH_GATHER_PAIRS_INL_H_
#endif

#include <hwy/highway.h>

#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// first = base[index], second = base[index + 1] in each lane.
template <class D, class T = hn::TFromD<D>, class VI = hn::VFromD<hn::RebindToSigned<D>>>
HWY_INLINE void GatherPairs(D d, const T* HWY_RESTRICT base, VI index, hn::VFromD<D>& first, hn::VFromD<D>& second) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  if constexpr (sizeof(T) == 4 && hn::MaxLanes(D()) == 16) {
    const __m512i low = _mm512_i32gather_epi64(_mm512_castsi512_si256(index.raw), base, 4);
    const __m512i high = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(index.raw, 1), base, 4);
    const __m512i even = _mm512_set_epi32(30, 28, 26, 24, 22, 20, 18, 16, 14, 12, 10, 8, 6, 4, 2, 0);
    const __m512i odd = _mm512_set_epi32(31, 29, 27, 25, 23, 21, 19, 17, 15, 13, 11, 9, 7, 5, 3, 1);
    const hn::RebindToSigned<D> di;
    first = hn::BitCast(d, hn::VFromD<decltype(di)>{_mm512_permutex2var_epi32(low, even, high)});
    second = hn::BitCast(d, hn::VFromD<decltype(di)>{_mm512_permutex2var_epi32(low, odd, high)});
    return;
  }
#endif
  first = hn::GatherIndex(d, base, index);
  second = hn::GatherIndex(d, base, index + hn::Set(hn::RebindToSigned<D>(), 1));
}

// The same pairs from one short row of kShortRow values (index + 1 inside it): on AVX-512 the row
// is two registers, read by permutes instead of gathers.
constexpr int kShortRow = 32;
template <class D, class T = hn::TFromD<D>, class VI = hn::VFromD<hn::RebindToSigned<D>>>
HWY_INLINE void ShortRowPairs(D d, const T* HWY_RESTRICT row, VI index, hn::VFromD<D>& first, hn::VFromD<D>& second) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  if constexpr (std::is_same_v<T, float> && hn::MaxLanes(D()) == 16) {
    const __m512 low = _mm512_loadu_ps(row), high = _mm512_loadu_ps(row + 16);
    first = hn::VFromD<D>{_mm512_permutex2var_ps(low, index.raw, high)};
    second = hn::VFromD<D>{_mm512_permutex2var_ps(low, (index + hn::Set(hn::RebindToSigned<D>(), 1)).raw, high)};
    return;
  }
#endif
  GatherPairs(d, row, index, first, second);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_MATH_GATHER_PAIRS_INL_H_
